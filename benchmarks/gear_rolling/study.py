#!/usr/bin/env python3
"""Uniform mesh sequence of the gear rolling pass (prm/gear_rolling_uniform.prm): wall and user
CPU time, steps, Newton iterations, cutbacks, die force and flank deviation for Global
refinements = 1, 2, 3, ...; errors relative to the finest mesh of the sequence. Not a test
(ctest label benchmark).

Usage (from the repository root, after building):
    /usr/bin/python3 benchmarks/gear_rolling/study.py [--ausroll build/ausroll] [--work DIR]
        [--refinements 1 2 3] [--end-time 1.2 --steps 60] [--prm prm/gear_rolling_uniform.prm]
        [--plot doc/figures/gear_rolling_mesh_study.png]
The pass is cut at --end-time (the step size is kept: --steps must match End time / 0.02).
Prints a Markdown table (pasted into doc/studies/benchmarks_journal.md and doc/scenes/gear_rolling.md).
"""

import argparse
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "benchmarks"))
from ausroll_run import run_variant  # noqa: E402


def run_level(args, level):
    """Run the pass with `level` global refinements in <work>/ref<level> (benchmarks/ausroll_run.py:
    one rank, one thread; wall and user + system CPU time of the process)."""
    os.makedirs(args.work, exist_ok=True)
    run = run_variant(args.ausroll, args.prm, args.work, f"ref{level}",
                      [f"Geometry/Global refinements = {level}", "Output/Write VTU = true",
                       f"Loading/End time = {args.end_time}",
                       f"Loading/Number of steps = {args.steps}",
                       f"Output/Interval = {args.steps}"] + args.set, reuse=args.reuse)
    rows, wall, user = run.rows, run.wall, run.cpu
    failed = run.returncode != 0 or float(rows[-1]["time"]) < args.end_time - 1e-9
    if failed:
        print(f"level {level}: exit {run.returncode}: {run.log.strip()[-300:]}", file=sys.stderr)
    work = os.path.join(args.work, f"ref{level}")
    summary = {"d_n_min": "nan", "d_n_max": "nan"}
    if not failed:
        flank = subprocess.run([sys.executable,
                                os.path.join(ROOT, "scripts", "gear_flank_analysis.py"),
                                work], capture_output=True, text=True,
                               check=True)
        summary = dict(kv.split("=") for kv in flank.stdout.split())
    last = rows[-1]
    at = min(rows, key=lambda r: abs(float(r["time"]) - args.compare_time))
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
        "end": float(last["time"]),
        "f_at": (float(at["die_die_force_x"]) ** 2 + float(at["die_die_force_y"]) ** 2) ** 0.5,
        "fx": float(peak["die_die_force_x"]),
        "fy": float(peak["die_die_force_y"]),
        "dmin": float(summary["d_n_min"]),
        "dmax": float(summary["d_n_max"]),
    }


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--ausroll", default=os.path.join(ROOT, "build", "ausroll"))
    p.add_argument("--work", default="/tmp/gear_rolling_study")
    p.add_argument("--prm", default=os.path.join(ROOT, "prm", "gear_rolling_uniform.prm"))
    p.add_argument("--refinements", type=int, nargs="+", default=[1, 2, 3])
    p.add_argument("--end-time", type=float, default=1.2)
    p.add_argument("--steps", type=int, default=60)
    p.add_argument("--compare-time", type=float, default=0.6,
                   help="die force compared at this time (contact near the pitch point)")
    p.add_argument("--reuse", action="store_true",
                   help="use the histories and times of an earlier run")
    p.add_argument("--set", action="append", default=[],
                   help="further prm override, e.g. 'Contact/Strategy = nested active set'")
    p.add_argument("--plot")
    args = p.parse_args()
    results = [run_level(args, level) for level in args.refinements]
    ref = results[-1]
    fref = (ref["fx"] ** 2 + ref["fy"] ** 2) ** 0.5
    print(f"| refinements | cells | DoFs | reached t | steps | Newton it. | cutbacks | wall (s) | "
          f"CPU (s) | peak die force (N/mm) | error | die force at t = {args.compare_time} "
          f"(N/mm) | error | residual d_n min / max (um) | error of d_n min |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in results:
        f = (r["fx"] ** 2 + r["fy"] ** 2) ** 0.5
        ef = abs(f - fref) / fref
        ea = abs(r["f_at"] - ref["f_at"]) / ref["f_at"]
        ed = abs(r["dmin"] - ref["dmin"]) / abs(ref["dmin"])
        print(f"| {r['level']} | {r['cells']} | {r['dofs']} | {r['end']:.3f} | {r['steps']} | "
              f"{r['newton']} | {r['cutbacks']} | {r['wall']:.1f} | {r['user']:.1f} | {f:.1f} | "
              f"{ef:.4f} | {r['f_at']:.1f} | {ea:.4f} | {1000 * r['dmin']:.2f} / "
              f"{1000 * r['dmax']:.2f} | {ed:.3f} |")
    if args.plot:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(6, 4))
        coarse = results[:-1]
        cost = [r["wall"] for r in coarse]
        ax.loglog(cost, [abs(((r["fx"] ** 2 + r["fy"] ** 2) ** 0.5) - fref) / fref
                         for r in coarse], "o-", label="peak die force")
        ax.loglog(cost, [abs(r["f_at"] - ref["f_at"]) / ref["f_at"] for r in coarse], "s-",
                  label=f"die force at t = {args.compare_time}")
        ax.loglog(cost, [abs(r["dmin"] - ref["dmin"]) / abs(ref["dmin"]) for r in coarse], "^-",
                  label="residual flank deviation d_n min")
        for r, c in zip(coarse, cost):
            ax.annotate(f"ref {r['level']}", (c, abs(r["f_at"] - ref["f_at"]) / ref["f_at"]))
        ax.set_xlabel("wall time (s, shared machine)")
        ax.set_ylabel(f"error vs refinement {ref['level']}")
        ax.grid(alpha=0.3, which="both")
        ax.legend()
        fig.tight_layout()
        fig.savefig(args.plot, dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main())
