#!/usr/bin/env bash
# Convergence study of the adaptive disk rolling scene (prm/disk_rolling_adaptive.prm) with
# scripts/convergence_study.py: levels of refinement at the die (maximum level = initial cycles;
# the 15 degree ring refined to 15 / 2^level degrees in the band, radially likewise) and a
# step-size sequence (rolling steps per revolution, Coulomb mu = 0.3); mean die force over
# 60-300 degrees of revolution, residual lobe (max) and trough (min) of the rim, and the residual
# rim in the max-norm on the common angle grid.
# Usage: benchmarks/convergence/disk_rolling.sh [AUSROLL] [WORK] [LEVELS] [STEPS] [STEP_LEVEL] [more convergence_study.py options]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
AUSROLL="${1:-$ROOT/build/ausroll}"
WORK="${2:-/tmp/convergence_disk}"
LEVELS="${3:-1 2 3}"
STEPS="${4:-144 288 576}"
STEP_LEVEL="${5:-2}"
# shellcheck disable=SC2086
shift $(( $# < 5 ? $# : 5 ))
exec /usr/bin/python3 "$ROOT/scripts/convergence_study.py" "$ROOT/prm/disk_rolling_adaptive.prm" \
  --ausroll "$AUSROLL" --work "$WORK" \
  --levels $LEVELS --level-set "Adaptivity/Maximum level = {level}" \
  --level-set "Adaptivity/Initial refinement cycles = {level}" \
  --steps $STEPS --step-level "$STEP_LEVEL" \
  --step-set "Loading/End time = {n + 8}" --step-set "Loading/Number of steps = {n + 8}" \
  --step-set "Contact/Die 0/Motion/Revolution angle = t <= 4 ? 0 : (t <= {n + 4} ? {360 / n} * (t - 4) : 360)" \
  --step-set "Contact/Die 0/Motion/Feed = t <= 4 ? 0.762 * t / 4 : (t <= {n + 4} ? 0.762 : 0.762 - 1.062 * (t - {n + 4}) / 4)" \
  --time-column die_roll_revolution \
  --history "F_mean=mean(60,300):die_roll_force_magnitude" \
  --profile "lobe=profile_*.csv:angle:radial_displacement:max" \
  --profile "trough=profile_*.csv:angle:radial_displacement:min" \
  --profile "rim=profile_*.csv:angle:radial_displacement" \
  --plot "$WORK/disk_work_precision.png" "$@"
