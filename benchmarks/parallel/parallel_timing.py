#!/usr/bin/env python3
"""np = 1 vs np = 2: wall and CPU time, and equality of the results, for two cases of more than
100k DoFs:

- `uniform`: the thick cylinder (prm/thick_cylinder.prm) on a 12 x 6 ring refined 4 times, Q2
  (148 617 DoFs), 5 load steps to p = 180 MPa (partly plastic);
- `adaptive`: tests/checks/scenes/thick_cylinder_adapt.prm.in scaled up (Q2, 3 global
  refinements, then refinement and coarsening with material-point transfer after every step up
  to level 6): pressure to 150 MPa by t = 1, then held while the mesh changes.

For each case the history of np = 2 is compared column by column with np = 1: the largest
difference relative to the column's largest magnitude is printed (wall time excluded). Prints a
markdown table. Timings on a shared machine: the CPU time (summed over the ranks) is the reliable
measure of work; the wall time shows the speed-up only when two cores are free.

Usage (from the repository root, after building):
    /usr/bin/python3 benchmarks/parallel/parallel_timing.py [--ausroll build/ausroll]
        [--work /tmp/ausroll_parallel] [--cases uniform,adaptive] [--reuse]
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import ausroll_run  # noqa: E402

ROOT = ausroll_run.ROOT


def cases(work):
    adapt_in = os.path.join(ROOT, "tests", "checks", "scenes", "thick_cylinder_adapt.prm.in")
    adapt = os.path.join(work, "thick_cylinder_adapt.prm")
    with open(adapt, "w") as f:
        f.write(open(adapt_in).read().replace("@CMAKE_SOURCE_DIR@", ROOT))
    return {
        "uniform": (os.path.join(ROOT, "prm", "thick_cylinder.prm"),
                    ["Geometry/Global refinements = 4",
                     "Geometry/Quarter ring/Radial cells = 12",
                     "Geometry/Quarter ring/Angular cells = 6",
                     "Loading/End time = 1", "Loading/Number of steps = 5",
                     "Output/Interval = 0"]),
        "adaptive": (adapt, ["Geometry/Global refinements = 3",
                             "Adaptivity/Maximum level = 6",
                             "Adaptivity/Refine fraction = 0.3",
                             "Adaptivity/Coarsen fraction = 0.05"]),
    }


def kind(column):
    """Columns compared on a common scale: all displacements, all reactions, yield excess."""
    if column.startswith("reaction_"):
        return "reaction"
    if column.endswith(("_ux", "_uy")):
        return "displacement"
    return column


def max_relative_difference(a, b):
    """Largest |a - b| / scale over the result columns of two histories, where scale is the
    largest magnitude of that kind of column (all displacements, all reactions; a zero-by-symmetry
    column such as outer_uy is thus compared with the radial displacement, not with its own
    round-off). yield_excess is already relative to sigma_y and compared absolutely. Mesh columns
    (dofs, cells), step counters and the wall time are not results and are skipped."""
    if len(a) != len(b):
        return float("inf"), f"{len(a)} vs {len(b)} rows"
    skip = ("wall_seconds", "step", "dofs", "cells", "time", "load_factor")
    columns = [c for c in a[0] if c not in skip]
    scales = {}
    for col in columns:
        scales[kind(col)] = max([scales.get(kind(col), 0.0)] + [abs(float(r[col])) for r in a])
    worst, where = 0.0, ""
    for col in columns:
        scale = 1.0 if col == "yield_excess" else scales[kind(col)]
        if scale == 0.0:
            continue
        d = max(abs(float(x[col]) - float(y[col])) for x, y in zip(a, b)) / scale
        if d > worst:
            worst, where = d, col
    return worst, where


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--ausroll", default=os.path.join(ROOT, "build", "ausroll"))
    ap.add_argument("--work", default="/tmp/ausroll_parallel")
    ap.add_argument("--cases", default="uniform,adaptive")
    ap.add_argument("--reuse", action="store_true", help="reuse runs in the work directory")
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    all_cases = cases(args.work)
    table = []
    for case in args.cases.split(","):
        base, overrides = all_cases[case]
        runs = {}
        for np in (1, 2):
            run = ausroll_run.run_variant(args.ausroll, base, args.work, f"{case}_np{np}",
                                          overrides, np=np, reuse=args.reuse)
            runs[np] = run
            print(f"  {case} np={np}: exit {run.returncode}, "
                  f"{run.rows[-1]['dofs'] if run.rows else '?'} DoFs, {run.wall:.1f} s wall, "
                  f"{run.cpu:.1f} s CPU", flush=True)
        if not (runs[1].ok and runs[2].ok):
            table.append([case, "failed", "", "", "", "", "", ""])
            continue
        diff, col = max_relative_difference(runs[1].rows, runs[2].rows)
        dofs = [int(runs[n].rows[-1]["dofs"]) for n in (1, 2)]
        table.append([case, f"{dofs[0]}" if dofs[0] == dofs[1] else f"{dofs[0]} / {dofs[1]}",
                      len(runs[1].rows) - 1, f"{runs[1].wall:.1f}", f"{runs[2].wall:.1f}",
                      f"{runs[1].wall / runs[2].wall:.2f}", f"{runs[1].cpu:.1f}",
                      f"{runs[2].cpu:.1f}", f"{diff:.1e} ({col})"])
    print(ausroll_run.markdown_table(
        ["case", "final DoFs (np=1 / np=2)", "steps", "wall np=1 (s)", "wall np=2 (s)", "speed-up (wall)",
         "CPU np=1 (s)", "CPU np=2 (s, both ranks)", "max rel. diff. of history"], table))
    return 0


if __name__ == "__main__":
    sys.exit(main())
