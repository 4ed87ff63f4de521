#!/usr/bin/env bash
# Usage: benchmarks/parallel/weak_scaling_3d.sh AUSROLL WORK [LEVEL:STEPS[:LAYERS] ...]
# Per-rank costs of the 3D gear scene for the weak-scaling estimate of doc/studies/scaling_3d.md:
# prm/gear_rolling_3d.prm at Geometry/Global refinements = LEVEL (1: 6 993, 2: 49 167, 3: 367 707
# DoFs; LAYERS the coarse layers through the half face, 4 as shipped), the first STEPS steps of the
# feed (step size 0.02 as shipped; the die touches in step 1), on one process and on two MPI ranks,
# one after the other, always with the iterative solver (GMRES + AMG, also below the automatic
# threshold of 10^4 unknowns), Output/Verbosity = verbose (one line per linear solve with its
# iterations and the CPU seconds of rank 0), no VTU. Default: 1:2 2:2 3:1. Each run under `ulimit -v 12000000`, `nice -n 5`, DEAL_II_NUM_THREADS=1, with the
# load average before and after it in WORK/runs.txt; the logs are WORK/L<level>_np<n>.log.
# Tables: /usr/bin/python3 benchmarks/parallel/weak_scaling_3d.py WORK.
set -u
AUSROLL="$(realpath "$1")"
WORK="$2"
shift 2
LEVELS=("$@")
[ ${#LEVELS[@]} -eq 0 ] && LEVELS=(1:2 2:2 3:1)
HERE="$(cd "$(dirname "$0")/../.." && pwd)"
mkdir -p "$WORK"
export DEAL_II_NUM_THREADS=1 OMP_NUM_THREADS=1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export OMPI_MCA_mpi_yield_when_idle=1
ulimit -v 12000000
for spec in "${LEVELS[@]}"; do
  level="${spec%%:*}"
  rest="${spec#*:}"
  steps="${rest%%:*}"
  layers=4
  [ "$rest" != "$steps" ] && layers="${rest#*:}"
  end=$(python3 -c "print(0.02 * $steps)")
  for np in 1 2; do
    name="L${level}"
    [ "$layers" != 4 ] && name="${name}x${layers}"
    name="${name}_np${np}"
    launch=()
    [ "$np" -gt 1 ] && launch=(mpirun -np "$np")
    echo "### $name steps $steps load before: $(cut -d' ' -f1-3 /proc/loadavg) $(date -u +%FT%TZ)" >> "$WORK/runs.txt"
    nice -n 5 /usr/bin/time -f "$name time: user %U sys %S wall %e maxrss_kB %M" -a -o "$WORK/runs.txt" \
      "${launch[@]}" "$AUSROLL" "$HERE/prm/gear_rolling_3d.prm" --overwrite \
      --set "Geometry/Global refinements=$level" --set "Geometry/Extruded gear tooth/Layers=$layers" \
      --set "Solver/Linear solver/Type=iterative" --set "Loading/End time=$end" \
      --set "Loading/Number of steps=$steps" --set "Output/Directory=$WORK/$name" \
      --set "Output/Verbosity=verbose" --set "Output/Write VTU=false" > "$WORK/$name.log" 2>&1
    echo "$name exit $? load after: $(cut -d' ' -f1-3 /proc/loadavg)" >> "$WORK/runs.txt"
  done
done
