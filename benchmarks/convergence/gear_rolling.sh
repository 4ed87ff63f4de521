#!/usr/bin/env bash
# Convergence study of the resolved gear scene (prm/gear_rolling_adaptive.prm) with
# scripts/convergence_study.py: adaptive levels (maximum level at the contact = initial cycles)
# and a step-size sequence; residual d_n along the flank (max-norm on the common radius grid),
# peak die force, die force at t = 0.6, peak contact pressure, plastic-zone depth (eps_p > 0.2 %).
# Usage: benchmarks/convergence/gear_rolling.sh [AUSROLL] [WORK] [LEVELS] [STEPS] [STEP_LEVEL] [more convergence_study.py options]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
AUSROLL="${1:-$ROOT/build/ausroll}"
WORK="${2:-/tmp/convergence_gear}"
LEVELS="${3:-3 4 5}"
STEPS="${4:-60 120 240 480}"
STEP_LEVEL="${5:-4}"
# shellcheck disable=SC2086
shift $(( $# < 5 ? $# : 5 ))
exec /usr/bin/python3 "$ROOT/scripts/convergence_study.py" "$ROOT/prm/gear_rolling_adaptive.prm" \
  --ausroll "$AUSROLL" --work "$WORK" \
  --levels $LEVELS --level-set "Adaptivity/Maximum level = {level}" \
  --level-set "Adaptivity/Initial refinement cycles = {level}" \
  --steps $STEPS --step-level "$STEP_LEVEL" \
  --set "Output/Write VTU = true" --set "Output/Interval = 1" \
  --history "F_peak=max:hypot(die_die_force_x, die_die_force_y)" \
  --history "F_0.6=at(0.6):hypot(die_die_force_x, die_die_force_y)" \
  --after "/usr/bin/python3 $ROOT/benchmarks/gear_rolling/gear_quantities.py {out}" \
  --value "d_n_min=d_n_min" --value "p_n_max=p_n_max" --value "plastic_depth=plastic_depth" \
  --profile "d_n=residual_dn.csv:R:d_n" \
  --plot "$WORK/gear_work_precision.png" "$@"
