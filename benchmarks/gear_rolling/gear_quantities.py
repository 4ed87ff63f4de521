#!/usr/bin/env python3
"""Flagship answers of a gear rolling run, for scripts/convergence_study.py (--after):

Usage: /usr/bin/python3 benchmarks/gear_rolling/gear_quantities.py OUTPUT_DIR [--threshold 0.002]
           [--flank negative|positive]

Reads OUTPUT_DIR/solution.pvd (VTU with `Output/Deformed mesh = true`; the last dataset is the
residual state after unloading) and prints key=value words:
  d_n_min, d_n_max        residual normal flank deviation (mm), scripts/gear_flank_analysis.py
  p_n_max                 largest nodal contact pressure over all written steps (MPa; the
                          contact_NNNN.csv files: write every step for the peak, Output/Interval)
  plastic_depth           depth of the plastic zone (mm): the largest distance below the original
                          involute (in the reference configuration) at which the equivalent
                          plastic strain reaches --threshold (0.2 %), interpolated linearly along
                          the cell edges where it crosses the threshold, over the involute part
  plastic_max             largest nodal equivalent plastic strain
  F_alpha, f_f_alpha,     ISO 1328-1 total, form and slope profile deviation (mm) of the last step
  f_H_alpha               over the evaluation range L_alpha of scripts/gear_flank_analysis.py
                          (its --sap-radius, --tip-chamfer-radius, --evaluation-fraction)
and writes OUTPUT_DIR/residual_dn.csv (R, d_n of the last step, sorted by R) for a profile
comparison (--profile "d_n=residual_dn.csv:R:d_n").
"""

import argparse
import csv
import glob
import math
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import gear_flank_analysis as gfa  # noqa: E402
import vtu_io  # noqa: E402


def plastic_zone(directory, args):
    from vtk.util.numpy_support import vtk_to_numpy

    grid = vtu_io.read_grid(vtu_io.datasets(directory)[-1][1])
    x = vtk_to_numpy(grid.GetPoints().GetData())
    u = vtu_io.point_array(grid, "displacement")
    ep = vtu_io.point_array(grid, "equivalent_plastic_strain")
    rp, rb, ra, theta_h = gfa.gear_data(args)
    axis = math.radians(args.axis_angle)
    sign = 1.0 if args.flank == "positive" else -1.0

    def depth(k):
        X, Y = float(x[k][0] - u[k][0]), float(x[k][1] - u[k][1])
        R = math.hypot(X, Y)
        if R <= rb or R >= ra:
            return None
        phi = math.remainder(math.atan2(Y, X) - axis, 2.0 * math.pi)
        if sign * phi < 0:  # the other half of the tooth
            return None
        return rb * (theta_h(R) - sign * phi)  # > 0 inside the tooth

    deepest = 0.0
    for c in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(c).GetPointIds()
        n = ids.GetNumberOfIds()
        for i in range(n):
            a, b = ids.GetId(i), ids.GetId((i + 1) % n)
            da, db = depth(a), depth(b)
            if da is None or db is None:
                continue
            ea, eb = float(ep[a]), float(ep[b])
            if ea >= args.threshold:
                deepest = max(deepest, da)
            if eb >= args.threshold:
                deepest = max(deepest, db)
            if (ea - args.threshold) * (eb - args.threshold) < 0:
                w = (args.threshold - ea) / (eb - ea)
                deepest = max(deepest, (1 - w) * da + w * db)
    return deepest, float(max(ep))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("directory")
    p.add_argument("--threshold", type=float, default=0.002)
    gfa.add_gear_options(p)
    args = p.parse_args()
    results, rp = gfa.analyse(args)
    s = gfa.summary(results, rp)
    rb, ra = gfa.gear_data(args)[1:3]
    r0, r1 = gfa.evaluation_range([r for r in results if r[0] == s["step"]], rb, ra, args)
    iso = gfa.iso_summary(gfa.iso1328([r for r in results if r[0] == s["step"]], rb, r0, r1)[s["step"]],
                          rb, r0, r1)
    last = max(r[0] for r in results)
    final = sorted((r[2], r[4]) for r in results if r[0] == last)
    with open(os.path.join(args.directory, "residual_dn.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["R", "d_n"])
        w.writerows(final)
    depth, ep_max = plastic_zone(args.directory, args)
    p_n_max = 0.0
    for name in glob.glob(os.path.join(args.directory, "contact_*.csv")):
        rows = csv.DictReader(line for line in open(name) if not line.startswith("#"))
        p_n_max = max([p_n_max] + [float(r["p_n"]) for r in rows])
    print(f"d_n_min={s['d_n_min']:.8g} d_n_max={s['d_n_max']:.8g} "
          f"p_n_max={p_n_max:.8g} plastic_depth={depth:.8g} "
          f"plastic_max={ep_max:.8g} F_alpha={iso['F_alpha']:.8g} "
          f"f_f_alpha={iso['f_f_alpha']:.8g} f_H_alpha={iso['f_H_alpha']:.8g}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
