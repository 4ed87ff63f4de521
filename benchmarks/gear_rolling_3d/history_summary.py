#!/usr/bin/env python3
"""Summary of a gear rolling history (2D or 3D) for the tables of doc/scenes/gear_rolling_3d.md.

Usage: history_summary.py HISTORY.csv [--width W] [--at T ...]

Prints the steps (rows after step 0), the Newton iterations and cutbacks summed over the steps,
the peak die force magnitude and the force magnitude at the times --at (linear interpolation in
t; default 0.6), all divided by --width (mm): 1 for a 2D run (force per mm already) or a 1 mm 3D
slice, the meshed half face width (12.7 mm) for prm/gear_rolling_3d.prm (mean force per mm of
face). A partial history (a run stopped early) gives the same lines up to its last step.
"""

import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from convergence_study import interpolate  # noqa: E402 (the linear interpolation of the convergence tool)


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("history")
    p.add_argument("--width", type=float, default=1.0)
    p.add_argument("--at", type=float, nargs="*", default=[0.6])
    args = p.parse_args()
    with open(args.history) as f:
        rows = [r for r in csv.DictReader(f) if int(r["step"]) > 0]
    t = [float(r["time"]) for r in rows]
    F = [float(r["die_die_force_magnitude"]) / args.width for r in rows]
    i = max(range(len(F)), key=F.__getitem__)
    print(f"steps={len(rows)} t_end={t[-1]:.6g} "
          f"newton={sum(int(r['newton_iterations']) for r in rows)} "
          f"cutbacks={sum(int(r['cutbacks']) for r in rows)} "
          f"peak_F_per_mm={F[i]:.6g} at t={t[i]:.6g}")
    for T in args.at:
        value = interpolate(t, F, T) if t[0] <= T <= t[-1] else float("nan")
        print(f"F_per_mm(t={T:g})={value:.6g}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
