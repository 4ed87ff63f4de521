#!/usr/bin/env bash
# Usage: benchmarks/amg_3d_study.sh BUILD_DIR LOG
# The runs of doc/studies/benchmarks_journal.md, section "3D linear solver": benchmarks/amg_3d on Q1 blocks of
# N^3 cells (N = 8, 16, 32, 64: three refinements) for the elastic, small-strain plastic and
# finite-strain plastic tangents with AMG, the direct solver (MUMPS) as far as it fits, Q2 blocks,
# and np = 2 for the largest (np = 1 vs np = 2 side by side: benchmarks/amg_3d_parallel.sh). Each
# run under `ulimit -v 16000000`, CPU time and peak memory from /usr/bin/time (user, sys, wall in
# s, max resident kB).
set -u
BUILD="$1"
LOG="$2"
export DEAL_II_NUM_THREADS=1
ulimit -v 16000000
run() {
  echo "### $*" >> "$LOG"
  nice timeout 900 /usr/bin/time -f "time: %U %S %e %M" "$@" >> "$LOG" 2>&1
}
EXE="$BUILD/benchmarks/amg_3d"
# AMG, Q1, three refinements of N = 8
for mode in elastic plastic finite; do
  for n in 8 16 32; do run "$EXE" $mode $n 1 amg; done
  run "$EXE" $mode 64 1 amg 1
done
# direct (MUMPS; KLU for comparison) as far as a run stays within a few minutes of CPU
for n in 8 16 24; do run "$EXE" elastic $n 1 mumps; done
for n in 8 16; do run "$EXE" plastic $n 1 mumps; done
for n in 8 16; do run "$EXE" elastic $n 1 klu; done
# Q2
for n in 4 8 16; do run "$EXE" elastic $n 2 amg; done
for n in 4 8; do run "$EXE" elastic $n 2 mumps; done
# two ranks on the largest
for mode in elastic plastic; do run mpirun -np 2 "$EXE" $mode 64 1 amg; done
run mpirun -np 2 "$EXE" elastic 16 1 mumps
