#!/usr/bin/env python3
"""Mesh sequence of the gear rolling pass (prm/gear_rolling.prm): wall and user CPU time, steps,
Newton iterations, cutbacks, die force and flank deviation for Global refinements = 1, 2, 3, ...;
errors relative to the finest mesh of the sequence. Not a test (ctest label benchmark).

Usage (from the repository root, after building):
    /usr/bin/python3 benchmarks/gear_rolling/study.py [--ausroll build/ausroll] [--work DIR]
        [--refinements 1 2 3] [--end-time 1.2 --steps 60] [--prm prm/gear_rolling.prm]
        [--plot doc/figures/gear_rolling_mesh_study.png]
The pass is cut at --end-time (the step size is kept: --steps must match End time / 0.02).
Prints a Markdown table (pasted into doc/benchmarks.md and doc/scenes/gear_rolling.md).
"""

import argparse
import csv
import os
import resource
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def run_level(args, level):
    work = os.path.join(args.work, f"ref{level}")
    os.makedirs(work, exist_ok=True)
    prm = os.path.join(work, "scene.prm")
    subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "prm_variant.py"), args.prm, prm,
                    f"Geometry/Global refinements = {level}", f"Output/Directory = {work}/out",
                    "Output/Verbosity = quiet", f"Loading/End time = {args.end_time}",
                    f"Loading/Number of steps = {args.steps}",
                    f"Output/Interval = {args.steps}"], check=True)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.time()
    result = subprocess.run([args.ausroll, prm], capture_output=True, text=True, cwd=ROOT)
    wall = time.time() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    user = after.ru_utime - before.ru_utime
    if result.returncode != 0:
        print(result.stderr, file=sys.stderr)
        raise SystemExit(f"level {level} failed")
    rows = list(csv.DictReader(open(os.path.join(work, "out", "history.csv"))))
    flank = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "gear_flank_analysis.py"),
                            os.path.join(work, "out")], capture_output=True, text=True, check=True)
    summary = dict(kv.split("=") for kv in flank.stdout.split())
    last = rows[-1]
    peak = max(rows, key=lambda r: (float(r["die_die_force_x"]) ** 2
                                    + float(r["die_die_force_y"]) ** 2))
    return {
        "level": level,
        "cells": int(last["cells"]),
        "dofs": int(last["dofs"]),
        "steps": len(rows) - 1,
        "newton": sum(int(r["newton_iterations"]) for r in rows),
        "cutbacks": sum(int(r["cutbacks"]) for r in rows),
        "wall": wall,
        "user": user,
        "fx": float(peak["die_die_force_x"]),
        "fy": float(peak["die_die_force_y"]),
        "dmin": float(summary["d_n_min"]),
        "dmax": float(summary["d_n_max"]),
    }


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--ausroll", default=os.path.join(ROOT, "build", "ausroll"))
    p.add_argument("--work", default="/tmp/gear_rolling_study")
    p.add_argument("--prm", default=os.path.join(ROOT, "prm", "gear_rolling.prm"))
    p.add_argument("--refinements", type=int, nargs="+", default=[1, 2, 3])
    p.add_argument("--end-time", type=float, default=1.2)
    p.add_argument("--steps", type=int, default=60)
    p.add_argument("--plot")
    args = p.parse_args()
    results = [run_level(args, level) for level in args.refinements]
    ref = results[-1]
    fref = (ref["fx"] ** 2 + ref["fy"] ** 2) ** 0.5
    print("| refinements | cells | DoFs | steps | Newton it. | cutbacks | wall (s) | user CPU (s) "
          "| peak die force (N/mm) | error | min d_n (um) | max d_n (um) | error max d_n |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in results:
        f = (r["fx"] ** 2 + r["fy"] ** 2) ** 0.5
        ef = abs(f - fref) / fref
        ed = abs(r["dmax"] - ref["dmax"]) / abs(ref["dmax"]) if ref["dmax"] else float("nan")
        print(f"| {r['level']} | {r['cells']} | {r['dofs']} | {r['steps']} | {r['newton']} | "
              f"{r['cutbacks']} | {r['wall']:.1f} | {r['user']:.1f} | {f:.1f} | {ef:.3f} | "
              f"{1000 * r['dmin']:.1f} | {1000 * r['dmax']:.1f} | {ed:.3f} |")
    if args.plot:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(6, 4))
        coarse = results[:-1]
        ax.loglog([r["user"] for r in coarse],
                  [abs(((r["fx"] ** 2 + r["fy"] ** 2) ** 0.5) - fref) / fref for r in coarse],
                  "o-", label="peak die force")
        ax.loglog([r["user"] for r in coarse],
                  [abs(r["dmax"] - ref["dmax"]) / abs(ref["dmax"]) for r in coarse],
                  "s-", label="max normal deviation")
        for r in coarse:
            ax.annotate(f"ref {r['level']}", (r["user"], abs(r["dmax"] - ref["dmax"]) / abs(ref["dmax"])))
        ax.set_xlabel("user CPU time (s)")
        ax.set_ylabel(f"error vs refinement {ref['level']}")
        ax.grid(alpha=0.3, which="both")
        ax.legend()
        fig.tight_layout()
        fig.savefig(args.plot, dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main())
