#!/bin/sh
# 3D Hertz point contact (tests/checks/scenes/hertz3d.prm, doc/scenes/hertz_3d.md): the CI scene
# (Q2, node spacing a / 8 under the contact) with Q1 on its mesh (a / 4), Q1 on the mesh refined
# once more near the contact (a / 8) and Q2 on that mesh (a / 16); for each the table of tests/checks/check_hertz_3d.py (errors of a, p0 and F against
# Hertz) and the CPU time (user + sys) of the run. No pass/fail (doc/studies/benchmarks_journal.md).
# Usage: study.sh AUSROLL SOURCE_DIR WORK_DIR
set -e
ausroll=$1
src=$2
work=$3
mkdir -p "$work"
cd "$work"
scene=$src/tests/checks/scenes/hertz3d.prm
write() { # name, extra lines
  printf 'include %s\n%s\nsubsection Output\n  set Directory = %s\nend\n' "$scene" "$2" "$1" > "$1.prm"
}
write q1 'subsection Model
  set Polynomial degree = 1
end'
fine='subsection Geometry
  set Local refinements = 9
  set Refinement radius factor = 0.603
end'
write q1_fine "$fine
subsection Model
  set Polynomial degree = 1
end"
write q2 ''
write q2_fine "$fine"
for name in q1 q1_fine q2 q2_fine; do
  echo "== $name"
  DEAL_II_NUM_THREADS=1 /usr/bin/time -f "CPU %U s user + %S s sys, wall %e s" \
    "$ausroll" "$name.prm" --overwrite > "$name.log" 2>&1 || { cat "$name.log"; exit 1; }
  tail -n 1 "$name.log"
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "dofs") c = i } NR == 2 { print "DoFs", $c }' "$name/history.csv"
  /usr/bin/python3 "$src/tests/checks/check_hertz_3d.py" "$name" --radius 50 --center 0,178,0 \
    --youngs-modulus 210000 --poissons-ratio 0.3 --tol 0.02 --min-nodes 10 || true
done
