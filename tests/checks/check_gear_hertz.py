#!/usr/bin/env python3
"""Elastic contact at the pitch point of the gear scene against plane-strain Hertz theory.

Usage: check_gear_hertz.py OUT_DIR [--tol 0.03] [--min-nodes 10]

For every contact_NNNN.csv of OUT_DIR with at least --min-nodes closed nodes, the nodal pressures
of the closed nodes are fitted to the Hertz ellipse p^2 = p0^2 (1 - (xi - xi0)^2 / a^2) (linear
least squares in xi, xi the current position projected on the chord of the contact zone; over
the 0.2 mm wide zone the flank curvature (rho = 17.35 mm) makes chord and arc differ by < 1e-5
relative), and compared with Hertz for two cylinders of the local involute radii of curvature,
rho = sqrt(r^2 - r_b^2) at the contact point: gear rho_1 at the radius of the centre of the closed
nodes, die rho_2 = r_pD sin(alpha) at its pitch point (57 teeth, DP 8.5, alpha = 22 deg), and
rigid die E* = E / (1 - nu^2):
    1/R = 1/rho_1 + 1/rho_2,  a = sqrt(4 P R / (pi E*)),  p0 = 2 P / (pi a),
P = |F| of the die per mm (history.csv; frictionless, so |F| is the normal force).
Tolerance 3 % (issue 12) on a and p0. Measured: a -1.2 ... -1.4 %, p0 +0.9 ... +1.0 % (20-30
nodes); one more refinement level (40-54 nodes) gives the same -1.0 ... -1.4 % and +0.8 ... +1.2 %,
so the rest is not discretisation (the same fit on the Hertz scene reaches 0.4 %) but the model
difference between a tooth and Hertz's two half-spaces: the tooth bends (the contact slides
0.015 mm down the flank and the flank rotates), it is a finite body (4.7 mm thick, 27 half-widths),
the radii of curvature vary by +-0.5 % across the contact, and the run is finite strain. The
contact must also be resolved: >= 10 nodes.
"""

import argparse
import csv
import glob
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklist import Checklist  # noqa: E402


def fit(points):
    """(xi0, a, p0) of the ellipse fitted to (xi, p) by least squares of p^2 in 1, xi, xi^2."""
    n = len(points)
    s = [[0.0] * 3 for _ in range(3)]
    b = [0.0] * 3
    for xi, p in points:
        row = [1.0, xi, xi * xi]
        for i in range(3):
            b[i] += row[i] * p * p
            for j in range(3):
                s[i][j] += row[i] * row[j]
    # Gaussian elimination of the 3x3 normal equations
    for i in range(3):
        for k in range(i + 1, 3):
            f = s[k][i] / s[i][i]
            for j in range(3):
                s[k][j] -= f * s[i][j]
            b[k] -= f * b[i]
    c = [0.0] * 3
    for i in reversed(range(3)):
        c[i] = (b[i] - sum(s[i][j] * c[j] for j in range(i + 1, 3))) / s[i][i]
    A, B, C = c
    if C >= 0 or n < 3:
        return None
    xi0 = -B / (2 * C)
    p0_sq = A - B * B / (4 * C)
    if p0_sq <= 0:
        return None
    return xi0, math.sqrt(-p0_sq / C), math.sqrt(p0_sq)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("out")
    p.add_argument("--tol", type=float, default=0.03)
    p.add_argument("--min-nodes", type=int, default=10)
    p.add_argument("--youngs-modulus", type=float, default=68950.0)
    p.add_argument("--poissons-ratio", type=float, default=0.33)
    p.add_argument("--gear-teeth", type=int, default=31)
    p.add_argument("--die-teeth", type=int, default=57)
    p.add_argument("--diametral-pitch", type=float, default=8.5)
    p.add_argument("--pressure-angle", type=float, default=22.0)
    a = p.parse_args()
    alpha = math.radians(a.pressure_angle)
    module = 25.4 / a.diametral_pitch
    rb = 0.5 * module * a.gear_teeth * math.cos(alpha)
    rho_die = 0.5 * module * a.die_teeth * math.sin(alpha)
    e_star = a.youngs_modulus / (1 - a.poissons_ratio ** 2)
    history = list(csv.DictReader(open(os.path.join(a.out, "history.csv"))))
    checks = Checklist()
    checked = 0
    for name in sorted(glob.glob(os.path.join(a.out, "contact_*.csv"))):
        lines = open(name).readlines()
        t = float(lines[0].split("=")[1].split(";")[0])
        rows = [r for r in csv.DictReader(l for l in lines if not l.startswith("#"))
                if r["status"] != "0"]
        if len(rows) < a.min_nodes:
            continue
        rows.sort(key=lambda r: math.hypot(float(r["X"]), float(r["Y"])))
        x0, y0, x1, y1 = (float(rows[0]["x"]), float(rows[0]["y"]), float(rows[-1]["x"]),
                          float(rows[-1]["y"]))
        length = math.hypot(x1 - x0, y1 - y0)
        tx, ty = (x1 - x0) / length, (y1 - y0) / length
        pts = [((float(r["x"]) - x0) * tx + (float(r["y"]) - y0) * ty, float(r["p_n"]))
               for r in rows]
        result = fit(pts)
        h = min(history, key=lambda r: abs(float(r["time"]) - t))
        P = math.hypot(float(h["die_die_force_x"]), float(h["die_die_force_y"]))
        R_c = math.hypot(sum(float(r["X"]) for r in rows) / len(rows),
                         sum(float(r["Y"]) for r in rows) / len(rows))
        rho_gear = math.sqrt(R_c ** 2 - rb ** 2)
        R = 1 / (1 / rho_gear + 1 / rho_die)
        a_h = math.sqrt(4 * P * R / (math.pi * e_star))
        p_h = 2 * P / (math.pi * a_h)
        if result is None:
            checks(f"t = {t:g}: pressures do not form an ellipse", False)
            continue
        _, a_fit, p_fit = result
        print(f"t = {t:g}: {len(rows)} nodes, contact at r = {R_c:.4f} mm (rho_1 = "
              f"{rho_gear:.3f}, rho_2 = {rho_die:.3f} mm), P = {P:.2f} N/mm: a = {a_fit:.5f} "
              f"(Hertz {a_h:.5f}, {a_fit / a_h - 1:+.2%}), p0 = {p_fit:.1f} (Hertz {p_h:.1f}, "
              f"{p_fit / p_h - 1:+.2%}) MPa")
        checks(f"t = {t:g}: half-width within {a.tol:.0%}", abs(a_fit / a_h - 1) <= a.tol)
        checks(f"t = {t:g}: peak pressure within {a.tol:.0%}", abs(p_fit / p_h - 1) <= a.tol)
        checked += 1
    checks(f"{checked} output steps with >= {a.min_nodes} nodes in contact (>= 2)", checked >= 2)
    return checks.exit_status()


if __name__ == "__main__":
    sys.exit(main())
