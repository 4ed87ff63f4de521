#!/usr/bin/env bash
# Usage: scripts/run.sh [FILE.prm [OPTIONS]]
# Installs what is missing (Debian 12), builds ausroll (Release, build/) and runs FILE.prm
# (default: the flagship scene) with the ausroll OPTIONS (--overwrite to rerun into the same
# output directory, --resume, --set "Section/Entry=value"). Set NP=4 to run with mpirun on 4 ranks.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"

prm="${1:-$AUSROLL_ROOT/prm/gear_rolling.prm}"
options=("${@:2}")
if [ ! -f "$prm" ]; then
  echo "scripts/run.sh: no such parameter file: $prm" >&2
  exit 2
fi

ausroll_install_missing
ausroll_build

# Run, keep what ausroll prints, and take the output directory from its closing line
# ("finished: ... history: DIR/history.csv"), which knows the includes and --set overrides.
log="$(mktemp)"
trap 'rm -f "$log"' EXIT
set +e
if [ "${NP:-1}" -gt 1 ]; then
  mpirun -np "$NP" "$BUILD_DIR/ausroll" "$prm" "${options[@]}" | tee "$log"
else
  "$BUILD_DIR/ausroll" "$prm" "${options[@]}" | tee "$log"
fi
status=${PIPESTATUS[0]}
set -e

dir=$(sed -n 's/^finished: .*; history: \(.*\)\/history\.csv.*/\1/p' "$log" | tail -n 1)
if [ -n "$dir" ]; then
  case "$dir" in /*) ;; *) dir="$(pwd)/$dir" ;; esac
  echo
  echo "Output of $(basename "$prm") is in $dir/ (history.csv; open solution.pvd in ParaView)."
fi
exit "$status"
