#!/usr/bin/env python3
"""Compare a 3D Hertz point-contact scene (rigid sphere on an elastic block) with Hertz theory.

The scene is a quarter model (symmetry planes x = 0, z = 0), the sphere of radius R moves along
-y by delta(t) from first touch at t = 0 (history column die_<NAME>_y) and presses the block;
its force on the quarter is die_<NAME>_force_y. For each contact_NNNN.csv in DIRECTORY with at
least --min-nodes closed nodes:
  1. projection: the gap of every row equals the distance of the current node position to the
     sphere, |x - c(t)| - R, c(t) = centre + (0, -delta, 0), to 1e-8 of the size of the
     coordinates (the CSV's 10 significant digits; the projection on the revolved arc is exact);
  2. the nodal pressures p_n (= R_n / tributary area) of the closed nodes are fitted to
     p^2 = p0^2 (1 - r^2 / a^2), r = sqrt(X^2 + Z^2) (check_hertz.fit_ellipse);
  3. with F = 4 |F_y| (whole sphere) and E* = E / (1 - nu^2), Hertz at the measured force,
     a(F) = (3 F R / (4 E*))^(1/3), p0(F) = 3 F / (2 pi a(F)^2), and at the given indentation,
     a(delta) = sqrt(R delta), p0(delta) = 2 E* a(delta) / (pi R), F(delta) = 4/3 E* R^(1/2)
     delta^(3/2): a, p0 (fit) and F must be within --tol (relative) of these references.
Exit status 0 if every load passes, 1 otherwise, 2 on data errors.
"""

import argparse
import csv
import glob
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_hertz import closed_nodes, fit_ellipse  # noqa: E402


def hertz_at_force(F, radius, e_star):
    """Contact radius and peak pressure of a sphere (radius R) under the total force F."""
    a = (3 * F * radius / (4 * e_star)) ** (1 / 3)
    return a, 3 * F / (2 * math.pi * a * a)


def hertz_at_indentation(delta, radius, e_star):
    """Contact radius, peak pressure and force at the indentation (approach) delta."""
    a = math.sqrt(radius * delta)
    return a, 2 * e_star * a / (math.pi * radius), 4 / 3 * e_star * math.sqrt(radius) * delta ** 1.5


def main():
    p = argparse.ArgumentParser()
    p.add_argument("directory")
    p.add_argument("--die", default="sphere", help="die name (history columns die_<name>_...)")
    p.add_argument("--radius", type=float, required=True)
    p.add_argument("--center", required=True, help="sphere centre at t = 0: 'x,y,z'")
    p.add_argument("--youngs-modulus", type=float, required=True)
    p.add_argument("--poissons-ratio", type=float, required=True)
    p.add_argument("--symmetry-factor", type=float, default=4.0,
                   help="whole force / modelled force (4: quarter model)")
    p.add_argument("--tol", type=float, default=0.02)
    p.add_argument("--min-nodes", type=int, default=30)
    a = p.parse_args()
    center = [float(v) for v in a.center.split(",")]
    e_star = a.youngs_modulus / (1 - a.poissons_ratio ** 2)
    files = sorted(glob.glob(os.path.join(a.directory, "contact_*.csv")))
    try:
        with open(os.path.join(a.directory, "history.csv")) as h:
            history = {float(r["time"]): r for r in csv.DictReader(h)}
    except OSError as e:
        print(f"check_hertz_3d.py: {e}", file=sys.stderr)
        return 2
    if not files:
        print(f"check_hertz_3d.py: no contact_*.csv in {a.directory}", file=sys.stderr)
        return 2
    failed = checked = 0
    print(f"{'t':>5} {'nodes':>5} {'F':>9} {'a':>7} {'err a(F)':>9} {'err a(d)':>9} {'p0':>8}"
          f" {'err p0(F)':>9} {'err p0(d)':>9} {'err F(d)':>9} {'gap err mm':>10}")
    for f in files:
        lines = open(f).read().splitlines()
        t = float(lines[0].split("=")[1].split(";")[0])
        t_near = min(history, key=lambda th: abs(th - t))
        if abs(t_near - t) > 1e-8 * max(1.0, abs(t)):
            print(f"check_hertz_3d.py: no history row at time {t}", file=sys.stderr)
            return 2
        row = history[t_near]
        delta = -float(row[f"die_{a.die}_y"])
        F = -a.symmetry_factor * float(row[f"die_{a.die}_force_y"])
        # 1. the gap is the exact distance to the sphere
        c = (center[0], center[1] - delta, center[2])
        all_rows = [r for r in csv.DictReader(l for l in lines if not l.startswith("#"))]
        gap_error = max(abs(math.dist([float(r[k]) for k in "xyz"], c) - a.radius - float(r["gap"]))
                        for r in all_rows)
        gap_tol = 1e-8 * max([abs(v) for v in c] + [abs(float(r[k])) for r in all_rows for k in "xyz"])
        rows = closed_nodes(lines)
        if len(rows) < a.min_nodes:
            continue
        for r in rows:
            r["r"] = math.hypot(float(r["X"]), float(r["Z"]))
        fit = fit_ellipse(rows, "r")
        if fit is None:
            print(f"{t:5.2f}: pressure is not elliptic  <- FAIL")
            failed += 1
            continue
        p0, radius = fit
        a_F, p0_F = hertz_at_force(F, a.radius, e_star)
        a_d, p0_d, F_d = hertz_at_indentation(delta, a.radius, e_star)
        errors = [radius / a_F - 1, radius / a_d - 1, p0 / p0_F - 1, p0 / p0_d - 1, F / F_d - 1]
        ok = all(abs(e) <= a.tol for e in errors) and gap_error <= gap_tol
        failed += not ok
        checked += 1
        print(f"{t:5.2f} {len(rows):5d} {F:9.1f} {radius:7.4f} {errors[0]:+9.2%} {errors[1]:+9.2%}"
              f" {p0:8.1f} {errors[2]:+9.2%} {errors[3]:+9.2%} {errors[4]:+9.2%} {gap_error:10.1e}"
              + ("" if ok else "  <- FAIL"))
    if checked == 0:
        print("check_hertz_3d.py: no load with enough closed nodes", file=sys.stderr)
        return 2
    print(f"{checked} loads checked, tolerance {a.tol:.1%} (gaps: 1e-8 of the coordinates): "
          + ("passed" if not failed else "FAILED"))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
