#!/usr/bin/env bash
# Usage: benchmarks/amg_3d_parallel.sh BUILD_DIR LOG
# The np = 1 vs np = 2 runs of doc/studies/benchmarks_journal.md, section "3D linear solver": benchmarks/amg_3d on
# Q1 unit cubes of N^3 cells (N = 10, 20, 40: three meshes, the last 206 763 DoFs), elastic and
# small-strain J2, AMG, two solves each, on one process and on two MPI ranks, one after the other;
# then two ranks on the meshes of the one-process table (N = 8, 16, 32, 64; one solve each).
# Each run under `ulimit -v 16000000`, with the load average before it, and /usr/bin/time's user,
# sys, wall (s) and maximum resident set (kB) of the largest process.
set -u
BUILD="$1"
LOG="$2"
export DEAL_II_NUM_THREADS=1 OMP_NUM_THREADS=1
export OMPI_MCA_mpi_yield_when_idle=1 OMPI_MCA_rmaps_base_oversubscribe=1
ulimit -v 16000000
EXE="$BUILD/benchmarks/amg_3d"
run() {
  echo "### $* (load average before: $(cut -d' ' -f1-3 /proc/loadavg))" >> "$LOG"
  nice timeout 900 /usr/bin/time -f "time: %U %S %e %M" "$@" >> "$LOG" 2>&1
}
for n in 10 20 40; do
  for mode in elastic plastic; do
    run "$EXE" $mode $n 1 amg 2
    run mpirun -np 2 "$EXE" $mode $n 1 amg 2
  done
done
for n in 8 16 32 64; do
  for mode in elastic plastic; do
    run mpirun -np 2 "$EXE" $mode $n 1 amg 1
  done
done
