#!/usr/bin/env bash
# Convergence study of a resolved flagship scene with scripts/convergence_study.py: adaptive
# levels (maximum level at the contact = initial refinement cycles) and a step-size sequence,
# Richardson estimates and a work-precision PNG.
#  gear_rolling (prm/gear_rolling.prm, the resolved trailing scene): residual d_n along the flank (max-norm on the
#    common radius grid), peak die force, die force at t = 0.6, peak contact pressure, plastic-zone
#    depth (eps_p > 0.2 %).
#  gear_rolling_bulk (prm/gear_rolling.prm, the whole mesh refined: Global refinements = Minimum level
#    = level, Maximum level = level + 3, so that the bulk below the contact band, where the lower
#    part of the rolled layer lies, is refined too; level 2 is the shipped scene): the ISO 1328
#    profile quantities F_alpha, f_f_alpha, f_H_alpha, d_n, and the residual stress profiles of
#    the depth probes at the pitch point and in the root of the rolled flank.
#  gear_ausrolling_finished (prm/gear_ausrolling_finished.prm, the chain to the finished gear; levels
#    of Adaptivity/Case level, 3 shipped): the ISO 1328 quantities of the finished flank, the
#    residual hoop stress 0.2 mm below the pitch point and the root, the martensite 0.05 mm below the pitch point, the peak die force;
#    gear_ausrolling_finished_bulk: the same on the whole-mesh sequence of gear_rolling_bulk.
#  disk_rolling (prm/disk_rolling_quick.prm): the 15 degree ring refined to 15 / 2^level degrees
#    in the 12 mm band, radially likewise; steps = rolling steps per revolution (Coulomb mu = 0.3); mean
#    die force over 60-300 degrees of revolution, residual lobe (max) and trough (min) of the rim,
#    and the residual rim in the max-norm on the common angle grid.
#  disk_rolling_3d_round, disk_rolling_3d_flat (prm/disk_rolling_3d_round_adaptive.prm, for the flat die with
#    the cylinder of prm/disk_rolling_3d_flat.prm): levels of the contact band that follows the die,
#    feed and 15 degrees of rolling; force per mm while rolling, depth, lateral spread and spread over
#    depth (doc/scenes/disk_rolling_3d.md). Runs under ulimit -v 12000000.
# Usage: benchmarks/convergence/convergence.sh SCENE [AUSROLL] [WORK] [LEVELS] [STEPS] [STEP_LEVEL] [more convergence_study.py options]
#   SCENE: gear_rolling (defaults: levels "2 3 4 5", steps "60 120 240 480", step level 4) or
#          disk_rolling (defaults: levels "1 2 3", steps "144 288 576", step level 2)
#          disk_rolling_3d_round / disk_rolling_3d_flat (defaults: levels "0 1 2 3", no step sequence)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
SCENE="${1:-}"
LEVEL_SETS=(--level-set "Adaptivity/Maximum level = {level}"
  --level-set "Adaptivity/Initial refinement cycles = {level}")
# the finished-flank quantities of both gear_ausrolling_finished sequences
FINISHED_QUANTITIES=(
  --history "F_peak=max:hypot(die_die_force_x, die_die_force_y)"
  --history "martensite_mean=last:martensite_mean"
  --after "/usr/bin/python3 $ROOT/benchmarks/gear_rolling/gear_quantities.py {out} --scale 0.9973324"
  --value "d_n_min=d_n_min" --value "F_alpha=F_alpha" --value "f_f_alpha=f_f_alpha"
  --value "f_H_alpha=f_H_alpha"
  --profile "d_n=residual_dn.csv:R:d_n"
  --profile "s_tt_pitch_0.2=depth_pitch_right_*.csv:s:stress_tt:at(0.2)"
  --profile "s_tt_pitch_min=depth_pitch_right_*.csv:s:stress_tt:min"
  --profile "s_tt_root_0.2=depth_root_right_*.csv:s:stress_tt:at(0.2)"
  --profile "f_M_pitch_0.05=depth_pitch_right_*.csv:s:martensite:at(0.05)"
)
case "$SCENE" in
  gear_rolling)
    PRM=prm/gear_rolling.prm
    DEFAULTS=("2 3 4 5" "60 120 240 480" 4)
    SCENE_OPTIONS=(
      --set "Output/Write VTU = true" --set "Output/Interval = 1"
      --history "F_peak=max:hypot(die_die_force_x, die_die_force_y)"
      --history "F_0.6=at(0.6):hypot(die_die_force_x, die_die_force_y)"
      --after "/usr/bin/python3 $ROOT/benchmarks/gear_rolling/gear_quantities.py {out}"
      --value "d_n_min=d_n_min" --value "p_n_max=p_n_max" --value "plastic_depth=plastic_depth"
      --profile "d_n=residual_dn.csv:R:d_n")
    PLOT=gear_work_precision.png ;;
  gear_rolling_bulk)
    PRM=prm/gear_rolling.prm
    DEFAULTS=("1 2 3" "120 240 480" 2)
    LEVEL_SETS=(--level-set "Geometry/Global refinements = {level}"
      --level-set "Adaptivity/Minimum level = {level}"
      --level-set "Adaptivity/Maximum level = {level + 3}")
    SCENE_OPTIONS=(
      --set "Output/Write VTU = true"
      --history "F_peak=max:hypot(die_die_force_x, die_die_force_y)"
      --after "/usr/bin/python3 $ROOT/benchmarks/gear_rolling/gear_quantities.py {out}"
      --value "d_n_min=d_n_min" --value "F_alpha=F_alpha" --value "f_f_alpha=f_f_alpha"
      --value "f_H_alpha=f_H_alpha" --value "plastic_depth=plastic_depth"
      --profile "d_n=residual_dn.csv:R:d_n"
      --profile "s_tt_pitch=depth_pitch_right_*.csv:s:stress_tt"
      --profile "s_tt_pitch_0.2=depth_pitch_right_*.csv:s:stress_tt:at(0.2)"
      --profile "s_tt_pitch_min=depth_pitch_right_*.csv:s:stress_tt:min"
      --profile "s_zz_pitch_0.2=depth_pitch_right_*.csv:s:stress_zz:at(0.2)"
      --profile "s_tt_root=depth_root_right_*.csv:s:stress_tt")
    PLOT=gear_bulk_work_precision.png ;;
  gear_ausrolling)
    # the hot scene: t in seconds (14 deg of rolling in 0.1 s), so F_0.06 is at the angle of the
    # flagship's F_0.6; the coolest and hottest temperatures of the run besides the mechanics
    PRM=prm/gear_ausrolling.prm
    DEFAULTS=("3 4 5" "120 240 480" 5)
    SCENE_OPTIONS=(
      --set "Output/Write VTU = true" --set "Output/Interval = 1"
      --history "F_peak=max:hypot(die_die_force_x, die_die_force_y)"
      --history "F_0.06=at(0.06):hypot(die_die_force_x, die_die_force_y)"
      --history "T_min=min:T_min" --history "T_max=max:T_max"
      --after "/usr/bin/python3 $ROOT/benchmarks/gear_rolling/gear_quantities.py {out}"
      --value "d_n_min=d_n_min" --value "p_n_max=p_n_max" --value "plastic_depth=plastic_depth"
      --profile "d_n=residual_dn.csv:R:d_n")
    PLOT=gear_ausrolling_work_precision.png ;;
  gear_ausrolling_finished)
    # the whole chain (rolling in the bath, cooling with the transformation): the finished flank
    # of the last output against the involute scaled by the body's free strain at 20 C (0.99733,
    # prm/gear_ausrolling_finished.prm); levels: Adaptivity/Case level (the carburized case along
    # the whole outline; 2 = no refinement beyond the tooth's, 3 = shipped); n = rolling steps, the
    # cooling steps scale with them
    PRM=prm/gear_ausrolling_finished.prm
    DEFAULTS=("2 3 4" "120 240 480" 3)
    LEVEL_SETS=(--level-set "Adaptivity/Case level = {level}")
    SCENE_OPTIONS=(
      --set "Output/Write VTU = true"
      --step-set "Stages/Stage 0/Step size = {0.12 / n}"
      --step-set "Stages/Stage 1/Step size = {960 / n}"
      --step-set "Loading/Number of steps = {1001 * n}"
      "${FINISHED_QUANTITIES[@]}")
    PLOT=gear_ausrolling_finished_work_precision.png ;;
  gear_ausrolling_finished_bulk)
    # the same quantities on the whole-mesh sequence of gear_rolling_bulk (the case below the
    # whole outline transforms, not only the band the die touches; level 2 is the shipped scene)
    PRM=prm/gear_ausrolling_finished.prm
    DEFAULTS=("1 2 3" "" 2)
    LEVEL_SETS=(--level-set "Geometry/Global refinements = {level}"
      --level-set "Adaptivity/Minimum level = {level}"
      --level-set "Adaptivity/Maximum level = {level + 3}")
    SCENE_OPTIONS=(
      --set "Output/Write VTU = true"
      "${FINISHED_QUANTITIES[@]}")
    PLOT=gear_ausrolling_finished_bulk_work_precision.png ;;
  disk_rolling)
    PRM=prm/disk_rolling_quick.prm
    DEFAULTS=("1 2 3" "144 288 576" 2)
    SCENE_OPTIONS=(
      --step-set "Loading/End time = {n + 8}" --step-set "Loading/Number of steps = {n + 8}"
      --step-set "Contact/Die 0/Motion/Rolling/Revolution angle = t <= 4 ? 0 : (t <= {n + 4} ? {360 / n} * (t - 4) : 360)"
      --step-set "Contact/Die 0/Motion/Rolling/Feed = t <= 4 ? 0.762 * t / 4 : (t <= {n + 4} ? 0.762 : 0.762 - 1.062 * (t - {n + 4}) / 4)"
      --time-column die_roll_revolution
      --history "F_mean=mean(60,300):die_roll_force_magnitude"
      --profile "lobe=profile_*.csv:angle:radial_displacement:max"
      --profile "trough=profile_*.csv:angle:radial_displacement:min"
      --profile "rim=profile_*.csv:angle:radial_displacement")
    PLOT=disk_work_precision.png ;;
  disk_rolling_3d_round|disk_rolling_3d_flat)
    # 3D disk (doc/scenes/disk_rolling_3d.md): the coarse 24 x 2 x 2 Q2 section refined to
    # Maximum level = level in the 2 mm contact band that follows the die (level 0: no refinement);
    # feed 0.762 mm in 4 steps, then 15 degrees of rolling in 1.25 degree steps (90 and 95 degrees,
    # where the depth and spread are read, lie 10-15 degrees behind the die at the end); no
    # unloading. Force per mm of thickness 2 |F_half| / 25.4 mm averaged over 7.5-15 degrees (7.5
    # degrees: a whole number of Q2 node spacings on the rim at every level, 7.5 / 2^level, over
    # which the force oscillates as the contact passes the nodes); depth -u_r at mid-thickness and spread u_z of the side-face edge
    # (z = 12.7 mm), means of the monitor points at 90 and 95 degrees, under load (last step).
    ulimit -v 12000000 # 3D: a run that runs away must not exhaust the shared machine's memory
    DIE="${SCENE#disk_rolling_3d_}"
    PRM=prm/disk_rolling_3d_round_adaptive.prm
    DEFAULTS=("0 1 2 3" "" 0)
    SCENE_OPTIONS=(
      --set "Loading/End time = 16" --set "Loading/Number of steps = 16"
      --set "Contact/Die 0/Motion/Rolling/Revolution angle = t <= 4 ? 0 : 1.25 * (t - 4)"
      --set "Contact/Die 0/Motion/Rolling/Feed = t <= 4 ? 0.762 * t / 4 : 0.762"
      --set "Adaptivity/Plastic coarsening level = -1"
      --set "Output/Write VTU = true" --set "Output/Interval = 0"
      --time-column die_roll_revolution
      --history "F_per_mm=mean(7.5,15):2 * die_roll_force_magnitude / 25.4"
      --history "depth=last:-(mid90_uy + mid95_ux * cos(radians(95)) + mid95_uy * sin(radians(95))) / 2"
      --history "spread=last:(side90_uz + side95_uz) / 2"
      --history "spread_over_depth=last:(side90_uz + side95_uz) / max(1e-12, -(mid90_uy + mid95_ux * cos(radians(95)) + mid95_uy * sin(radians(95))))")
    if [ "$DIE" = flat ]; then
      # the flat-faced die of prm/disk_rolling_3d_flat.prm on the same adaptive section
      SCENE_OPTIONS+=(
        --set "Contact/Die 0/Shape = cylinder"
        --set "Contact/Die 0/Cylinder/Center = 0, 0, 0" --set "Contact/Die 0/Cylinder/Axis = 0, 0, 1"
        --set "Contact/Die 0/Cylinder/Radius = 116.55" --set "Contact/Die 0/Cylinder/Width = 31.4"
        --set "Contact/Die 0/Cylinder/Edge radius = 1.5"
        --set "Contact/Die 0/Motion/Rolling/Die rolling radius = 116.55")
    fi
    PLOT=${SCENE}_work_precision.png ;;
  *)
    echo "usage: $0 gear_rolling|gear_rolling_bulk|gear_ausrolling|gear_ausrolling_finished[_bulk]|disk_rolling|disk_rolling_3d_round|disk_rolling_3d_flat [AUSROLL] [WORK] [LEVELS] [STEPS] [STEP_LEVEL] [options]" >&2
    exit 1 ;;
esac
shift
AUSROLL="${1:-$ROOT/build/ausroll}"
WORK="${2:-/tmp/convergence_${SCENE%_rolling}}"
LEVELS="${3:-${DEFAULTS[0]}}"
STEPS="${4:-${DEFAULTS[1]}}"
STEP_LEVEL="${5:-${DEFAULTS[2]}}"
shift $(( $# < 5 ? $# : 5 ))
# shellcheck disable=SC2086
exec /usr/bin/python3 "$ROOT/scripts/convergence_study.py" "$ROOT/$PRM" \
  --ausroll "$AUSROLL" --work "$WORK" \
  --levels $LEVELS "${LEVEL_SETS[@]}" \
  --steps $STEPS --step-level "$STEP_LEVEL" \
  "${SCENE_OPTIONS[@]}" \
  --plot "$WORK/$PLOT" "$@"
