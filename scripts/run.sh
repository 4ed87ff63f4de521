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

if [ "${NP:-1}" -gt 1 ]; then
  mpirun -np "$NP" "$BUILD_DIR/ausroll" "$prm" "${options[@]}"
else
  "$BUILD_DIR/ausroll" "$prm" "${options[@]}"
fi

dir=$(sed -n 's/^[[:space:]]*set[[:space:]]\+Directory[[:space:]]*=[[:space:]]*\([^#]*\).*/\1/p' "$prm" | tail -n 1 | xargs)
echo
echo "Output of $(basename "$prm") is in $(pwd)/${dir:-output}/ (history.csv; open solution.pvd in ParaView)."
