#!/usr/bin/env python3
"""Depth probes (Postprocess/Depth probes) against Lame's thick cylinder.

Usage: check_depth_probe.py AUSROLL SOURCE_DIR

prm/thick_cylinder.prm (quarter ring a = 100, b = 200 mm, plane strain, Q2, exact circles through
the polar manifold) loaded elastically to p = 90 MPa in one step (the first yield is at
p = 104 MPa). Two depth probes:
  - 'outer' from a point 1 mm outside the outer circle at 30 deg: it must start on the outer
    circle (the foot of the nearest outline point, r = 200 to 1e-9 mm) and run radially inwards
    for 100 mm to the bore;
  - 'inner' from the bore at 60 deg (a point on the surface), 50 mm deep, radially outwards.
Along both, the stress in the frame of the surface is compared with Lame's closed form:
stress_nn = sigma_rr = A - B / r^2, stress_tt = sigma_tt = A + B / r^2 (A = p a^2 / (b^2 - a^2),
B = A b^2), stress_nt = 0. Tolerance 0.5 % of p: the stress of a probe point is the Lagrange
interpolation of the 3 x 3 material points of its cell (Q2 on 16 x 8 cells of 12.5 mm), which
departs from the exact stress by up to 0.42 % of p at the bore (measured); the radial line probe
of the scene, the same interpolation along the x axis in sigma_xx and sigma_yy, departs by 0.41 %
there, so the difference is the FE error, not the frame (a wrong frame would mix sigma_rr and
sigma_tt, 180 % of p apart at the bore). The foot and the end of each probe are checked to 1e-5 mm:
the distance to the outline is exact to about 1e-12 of its size, but along the surface the foot is
located to 1.5e-8 of the 78 mm coarse face (Brent's bracket in the face parameter), 1.2e-6 mm. The depth column s is the distance below the surface.
"""

import csv
import math
import os
import subprocess
import sys

A_IN, B_OUT, P = 100.0, 200.0, 90.0


def lame(r):
    a_coef = P * A_IN ** 2 / (B_OUT ** 2 - A_IN ** 2)
    b_coef = a_coef * B_OUT ** 2
    return a_coef - b_coef / r ** 2, a_coef + b_coef / r ** 2


def main():
    ausroll, source = sys.argv[1], sys.argv[2]
    c30, s30 = math.cos(math.pi / 6), math.sin(math.pi / 6)
    c60, s60 = math.cos(math.pi / 3), math.sin(math.pi / 3)
    probes = (f"outer: {201 * c30:.12g}, {201 * s30:.12g}, 100, 41; "
              f"inner: {100 * c60:.12g}, {100 * s60:.12g}, 50, 21")
    args = ["--set", "Loading/End time=0.5", "--set", "Loading/Number of steps=1",
            "--set", "Output/Directory=out", "--set", "Output/Interval=1",
            "--set", f"Postprocess/Depth probes={probes}",
            "--set", "Postprocess/Depth probe boundaries=0, 1"]
    r = subprocess.run([ausroll, os.path.join(source, "prm", "thick_cylinder.prm"), "--overwrite"]
                       + args, capture_output=True, text=True)
    if r.returncode != 0:
        print(r.stdout[-2000:], r.stderr[-2000:])
        return 1
    failures = 0

    def check(name, ok, detail):
        nonlocal failures
        print(("ok   " if ok else "FAIL ") + f"{name}: {detail}")
        failures += 0 if ok else 1

    for name, r0, sign, depth, angle in (("outer", 200.0, -1, 100.0, 30), ("inner", 100.0, 1, 50.0, 60)):
        with open(os.path.join("out", f"depth_{name}_0001.csv")) as f:
            rows = list(csv.DictReader(f))
        first, last = rows[0], rows[-1]
        # positions to 1e-5 mm: Brent finds the face parameter to 1.5e-8 of the 78 mm coarse face
        # (1.2e-6 mm along the surface) and the CSV holds 10 significant digits (1e-7 mm)
        ca, sa = math.cos(math.radians(angle)), math.sin(math.radians(angle))
        x0, y0 = float(first["x"]), float(first["y"])
        off = math.hypot(x0 - r0 * ca, y0 - r0 * sa)
        check(f"{name}: starts at the foot on the circle at {angle} deg (1e-5 mm)", off < 1e-5,
              f"{off:.2e} mm from ({r0 * ca:.9f}, {r0 * sa:.9f})")
        x1, y1 = float(last["x"]), float(last["y"])
        r1 = r0 + sign * depth
        off = math.hypot(x1 - r1 * ca, y1 - r1 * sa)
        check(f"{name}: ends {depth} mm along the normal (1e-5 mm), s = depth",
              off < 1e-5 and abs(float(last["s"]) - depth) < 1e-6, f"{off:.2e} mm, s = {last['s']}")
        worst = 0.0
        for row in rows:
            rr = math.hypot(float(row["x"]), float(row["y"]))
            srr, stt = lame(rr)
            worst = max(worst, abs(float(row["stress_nn"]) - srr), abs(float(row["stress_tt"]) - stt),
                        abs(float(row["stress_nt"])))
        check(f"{name}: stress_nn, stress_tt, stress_nt = Lame's sigma_rr, sigma_tt, 0 within "
              f"0.5 % of p", worst <= 0.005 * P, f"largest difference {worst:.4f} MPa "
              f"({worst / P:.2%} of p)")
    print(f"{failures} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
