#!/usr/bin/env bash
# Usage: benchmarks/gear_rolling_3d/run.sh AUSROLL WORK_DIR [NP]
# The 3D gear roll prm/gear_rolling_3d.prm (one rank, or NP ranks with mpirun) and the 2D scene on
# the same section mesh and steps (prm/gear_rolling_uniform.prm with Geometry/Global refinements = 1),
# each timed (user, system, wall s, peak kB), then scripts/gear_flank_3d.py: residual flank
# deviation d_n at mid-face against the 2D run, d_n along the face width at four radii, and the
# figure WORK_DIR/gear_rolling_3d_flank.png. Tables: doc/scenes/gear_rolling_3d.md.
set -euo pipefail
AUSROLL="$1"; WORK="$2"; NP="${3:-1}"
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
mkdir -p "$WORK" && cd "$WORK"
RUN=("$AUSROLL")
[ "$NP" -gt 1 ] && RUN=(mpirun -np "$NP" "$AUSROLL")
/usr/bin/time -f "3D: %U user %S sys %e wall s, %M kB" "${RUN[@]}" "$ROOT/prm/gear_rolling_3d.prm" \
  --overwrite --set "Output/Directory = $WORK/3d" > 3d.log
/usr/bin/time -f "2D: %U user %S sys %e wall s, %M kB" "$AUSROLL" "$ROOT/prm/gear_rolling_uniform.prm" \
  --overwrite --set "Output/Directory = $WORK/2d" --set "Geometry/Global refinements = 1" > 2d.log
tail -n 2 3d.log 2d.log
/usr/bin/python3 "$ROOT/scripts/gear_flank_analysis.py" "$WORK/2d"
/usr/bin/python3 "$ROOT/scripts/gear_flank_3d.py" "$WORK/3d" \
  --compare-2d "$WORK/2d/flank_deviation.csv" --plot "$WORK/gear_rolling_3d_flank.png"
