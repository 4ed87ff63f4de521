#!/usr/bin/env bash
# Shared set-up of scripts/run.sh and scripts/test.sh: install what is missing (Debian 12),
# configure a Release build in build/ and build it. Source this file; do not run it directly.
set -euo pipefail

AUSROLL_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${AUSROLL_BUILD_DIR:-$AUSROLL_ROOT/build}"
JOBS="${AUSROLL_JOBS:-$(nproc 2>/dev/null || echo 2)}"

# OpenMPI refuses to run as root unless told otherwise; oversubscription lets tests with 2 ranks
# share 2 cores with a parallel ctest.
export OMPI_ALLOW_RUN_AS_ROOT=1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
# Oversubscribed ranks should yield the core instead of spinning while they wait.
export OMPI_MCA_mpi_yield_when_idle=1
# One thread per MPI rank (deal.II/TBB would otherwise use every core in every rank).
export DEAL_II_NUM_THREADS="${DEAL_II_NUM_THREADS:-1}"

ausroll_packages=(
  cmake g++ make perl python3 python3-matplotlib clang-format
  libdeal.ii-dev libgtest-dev numdiff openmpi-bin
)

ausroll_install_missing() {
  local missing=()
  for p in "${ausroll_packages[@]}" "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -eq 0 ]; then
    return 0
  fi
  echo "ausroll: installing missing packages: ${missing[*]}"
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    sudo="sudo"
  fi
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

ausroll_build() {
  if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then
    cmake -S "$AUSROLL_ROOT" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
  fi
  cmake --build "$BUILD_DIR" -j "$JOBS"
}
