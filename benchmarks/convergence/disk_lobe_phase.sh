#!/usr/bin/env bash
# Residual lobe of prm/disk_rolling.prm against where the die stops relative to the mesh
# (issue 12; doc/studies/disk_rolling.md, "The lobe depends on where the die stops").
# Each level runs the graded family at 2304 rolling steps per revolution (step-converged to 0.06 %
# of the lobe at level 4) with the die start (and so its stop) rotated by k eighths of a rim face
# (a face spans 15 / 2^level degrees), then benchmarks/convergence/disk_lobe_phase.py reads the lobe
# at the nodes and as the maximum of the quadratic face traces, per run and per level.
# Usage: benchmarks/convergence/disk_lobe_phase.sh [AUSROLL] [WORK] [LEVELS] [EIGHTHS]
#   defaults: build/ausroll, /tmp/disk_lobe_phase, levels "2 3", eighths "0 1 2 3 4 5 6 7" (a whole face).
#   CPU per run (one core): about 45 s (level 2), 150 s (3), 700 s (4), 3500 s (5).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
AUSROLL="${1:-$ROOT/build/ausroll}"
WORK="${2:-/tmp/disk_lobe_phase}"
LEVELS="${3:-2 3}"
EIGHTHS="${4:-0 1 2 3 4 5 6 7}"
n=2304
mkdir -p "$WORK"
dirs=()
for L in $LEVELS; do
  for k in $EIGHTHS; do
    shift_deg=$(/usr/bin/python3 -c "print($k * 15 / 2**$L / 8)")
    out="$WORK/L${L}_s${shift_deg}"
    dirs+=("$out")
    # a finished run (last history row at t = n + 8) is kept
    [ -f "$out/history.csv" ] && [ "$(tail -n 1 "$out/history.csv" | cut -d, -f2)" = "$((n + 8))" ] && continue
    echo "level $L, die start 90 + $shift_deg deg -> $out"
    /usr/bin/time -f "%U %S %e %M" -o "$out.time" "$AUSROLL" "$ROOT/prm/disk_rolling.prm" --overwrite \
      --set "Output/Directory=$out" --set "Output/Write VTU=false" \
      --set "Adaptivity/Maximum level=$L" --set "Adaptivity/Initial refinement cycles=$L" \
      --set "Adaptivity/Interval=$((8 * n / 576))" --set "Output/Interval=$((48 * n / 576))" \
      --set "Loading/End time = $((n + 8))" --set "Loading/Number of steps = $((n + 8))" \
      --set "Contact/Die 0/Motion/Rolling/Initial line angle = $(/usr/bin/python3 -c "print(90 + $shift_deg)")" \
      --set "Contact/Die 0/Motion/Rolling/Revolution angle = t <= 4 ? 0 : (t <= $((n + 4)) ? $(/usr/bin/python3 -c "print(360 / $n)") * (t - 4) : 360)" \
      --set "Contact/Die 0/Motion/Rolling/Feed = t <= 4 ? 0.762 * t / 4 : (t <= $((n + 4)) ? 0.762 : 0.762 - 1.062 * (t - $((n + 4))) / 4)" \
      > "$out.log" 2>&1
  done
done
exec /usr/bin/python3 "$ROOT/benchmarks/convergence/disk_lobe_phase.py" --csv "$WORK/lobe_phase.csv" "${dirs[@]}"
