#!/usr/bin/env python3
"""Compare the contact pressure of a Hertz scene with the plane-strain Hertz solution.

For each contact_NNNN.csv in DIRECTORY (time read from its '# time = t' header; the load is
P = LOAD_PER_TIME * t, N per mm of cylinder length, or, with --force-column, P = FORCE_FACTOR times
that history.csv column in the row of the same time, e.g. the measured punch force of a
displacement-driven scene), the nodal pressures of the closed nodes are fitted to the elliptic
distribution p(x)^2 = p0^2 (1 - x^2 / a^2) (linear least squares in x^2; x is the column named by
--coordinate: the die coordinate s of a flat die with s = 0 on the symmetry axis, or the current
position x for a die centred on x = 0), and a, p0 are compared with
    a = sqrt(4 P R (1 - nu^2) / (pi E)),   p0 = 2 P / (pi a).
The fit uses all closed nodes, so it does not depend on where the last closed node happens to lie.
Exit status 0 if every load meets --tol (relative, for a and p0), 1 otherwise, 2 on data errors.
"""

import argparse
import csv
import glob
import math
import os
import sys


def closed_nodes(lines):
    """Rows (dicts) of the closed nodes of a contact CSV given as its lines."""
    return [r for r in csv.DictReader(l for l in lines if not l.startswith("#")) if r["status"] != "0"]


def fit_ellipse(rows, coordinate="s"):
    """Least-squares fit of p_n^2 = p0^2 (1 - x^2 / a^2) over rows; (p0, a), or None if the
    pressures do not decrease with |x| like an ellipse."""
    xs = [float(r[coordinate]) ** 2 for r in rows]
    ys = [float(r["p_n"]) ** 2 for r in rows]
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    if n < 2 or sxx <= 0:
        return None
    B = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx
    A = my - B * mx
    if A <= 0 or B >= 0:
        return None
    return math.sqrt(A), math.sqrt(-A / B)


def hertz(P, radius, youngs_modulus, poissons_ratio):
    """Plane-strain Hertz half-width a and peak pressure p0 for the load P (per unit length)."""
    a_ref = math.sqrt(4 * P * radius * (1 - poissons_ratio ** 2) / (math.pi * youngs_modulus))
    return a_ref, 2 * P / (math.pi * a_ref)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("directory")
    p.add_argument("--load-per-time", type=float)
    p.add_argument("--force-column", help="history.csv column giving the load instead")
    p.add_argument("--force-factor", type=float, default=1.0,
                   help="P = factor * force column (e.g. -2 for the y force on a half model)")
    p.add_argument("--coordinate", default="s", help="contact CSV column of the position (s or x)")
    p.add_argument("--radius", type=float, required=True)
    p.add_argument("--youngs-modulus", type=float, required=True)
    p.add_argument("--poissons-ratio", type=float, required=True)
    p.add_argument("--tol", type=float, default=0.01)
    p.add_argument("--min-nodes", type=int, default=5)
    p.add_argument("--min-load", type=float, default=0.0,
                   help="skip loads below this (coarse contact zones at small loads)")
    a = p.parse_args()
    files = sorted(glob.glob(os.path.join(a.directory, "contact_*.csv")))
    if not files:
        print(f"check_hertz.py: no contact_*.csv in {a.directory}", file=sys.stderr)
        return 2
    if (a.load_per_time is None) == (a.force_column is None):
        print("check_hertz.py: give --load-per-time or --force-column", file=sys.stderr)
        return 2
    history = {}
    if a.force_column:
        with open(os.path.join(a.directory, "history.csv")) as h:
            history = {float(r["time"]): float(r[a.force_column]) for r in csv.DictReader(h)}
    failed = checked = 0
    print(f"{'P':>10} {'nodes':>5} {'a':>9} {'a_ref':>9} {'err_a':>9} {'p0':>9} {'p0_ref':>9} {'err_p0':>9}")
    for f in files:
        lines = open(f).read().splitlines()
        t = float(lines[0].split("=")[1].split(";")[0])
        if a.force_column:
            t_near = min(history, key=lambda th: abs(th - t))
            if abs(t_near - t) > 1e-5 * max(1.0, abs(t)):
                print(f"check_hertz.py: no history row at time {t}", file=sys.stderr)
                return 2
            P = a.force_factor * history[t_near]
        else:
            P = a.load_per_time * t
        rows = closed_nodes(lines)
        if P <= 0 or P < a.min_load * (1 - 1e-9) or len(rows) < a.min_nodes:
            continue
        n = len(rows)
        fit = fit_ellipse(rows, a.coordinate)
        if fit is None:
            print(f"{P:10.2f}: pressure is not elliptic")
            failed += 1
            continue
        p0, half_width = fit
        a_ref, p0_ref = hertz(P, a.radius, a.youngs_modulus, a.poissons_ratio)
        ea, ep = half_width / a_ref - 1, p0 / p0_ref - 1
        ok = abs(ea) <= a.tol and abs(ep) <= a.tol
        failed += not ok
        checked += 1
        print(f"{P:10.2f} {n:5d} {half_width:9.4f} {a_ref:9.4f} {ea:+9.2%} {p0:9.2f} {p0_ref:9.2f} {ep:+9.2%}"
              f"{'' if ok else '  <- FAIL'}")
    if checked == 0:
        print("check_hertz.py: no load with enough closed nodes", file=sys.stderr)
        return 2
    print(f"{checked} loads checked, tolerance {a.tol:.1%}: " + ("passed" if not failed else "FAILED"))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
