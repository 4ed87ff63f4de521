#!/usr/bin/env python3
"""Resolved contact of the adaptive gear scene (short pass across the pitch point).

Usage: check_gear_adaptive.py OUT_DIR --theta0 DEG [--rate 14] [--t-roll 0.1] [--mu 0.1]
                              [--min-nodes 8] [--window 0.6] [--mu-margin 0.05]

1. Resolution: at every step whose revolution angle lies within --window degrees of the pitch
   point angle theta_p = -s_p / (2 r_p) (trailing side; rigid flanks touch at r_p there), at least
   --min-nodes nodes are in contact (stick + slip; issue 12: >= 8 nodes across the contact width).
2. Coulomb bound at every loaded step (|F| > 10 N/mm): |F_t| <= (1 + margin) mu F_n, with F_n the
   component of the die force along the line of action (the common normal of conjugate involutes:
   direction alpha + theta_G in the non-rotating gear frame) and F_t the component across it. The
   margin 5 % allows for the deformed flank tilting the contact normal against the rigid line of
   action by a few 1e-3 rad (measured 0.008 rad over whole passes, check_gear_rolling.py), which
   moves up to 0.008 F_n from the normal into the tangential component.
3. The mesh was adapted: the cell count changes during the pass.
"""

import argparse
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklist import Checklist  # noqa: E402


def main():
    p = argparse.ArgumentParser()
    p.add_argument("out")
    p.add_argument("--theta0", type=float, required=True)
    p.add_argument("--rate", type=float, default=14.0)
    p.add_argument("--t-roll", type=float, default=0.1)
    p.add_argument("--mu", type=float, default=0.1)
    p.add_argument("--mu-margin", type=float, default=0.05)
    p.add_argument("--min-nodes", type=int, default=8)
    p.add_argument("--window", type=float, default=0.6)
    p.add_argument("--pressure-angle", type=float, default=22.0)
    p.add_argument("--pitch-thickness", type=float, default=4.69392)
    p.add_argument("--pitch-radius", type=float, default=46.3176471)
    a = p.parse_args()
    rows = list(csv.DictReader(open(os.path.join(a.out, "history.csv"))))
    theta_p = -math.degrees(a.pitch_thickness / (2 * a.pitch_radius))
    checks = Checklist()
    near, worst = 0, 0.0
    for r in rows[1:]:
        t = float(r["time"])
        theta = a.theta0 + a.rate * max(t - a.t_roll, 0.0)
        fx, fy = float(r["die_die_force_x"]), float(r["die_die_force_y"])
        if math.hypot(fx, fy) <= 10.0:
            continue
        psi = math.radians(a.pressure_angle + theta)
        f_n = -(fx * math.cos(psi) + fy * math.sin(psi))  # the die pushes along -(cos, sin)
        f_t = -fx * math.sin(psi) + fy * math.cos(psi)
        worst = max(worst, abs(f_t) / f_n)
        nodes = int(float(r["die_die_stick_nodes"]) + float(r["die_die_slip_nodes"]))
        if abs(theta - theta_p) <= a.window and t > a.t_roll:
            near += 1
            checks(f"t = {t:.4f}, theta_G = {theta:.3f} deg: {nodes} nodes in contact "
                   f"(>= {a.min_nodes})", nodes >= a.min_nodes)
    checks(f"{near} steps within {a.window} deg of the pitch point (theta_p = {theta_p:.3f} deg)",
           near >= 2)
    checks(f"Coulomb bound: max |F_t| / F_n = {worst:.4f} <= {(1 + a.mu_margin) * a.mu:.4f}",
           worst <= (1 + a.mu_margin) * a.mu)
    cells = {int(float(r["cells"])) for r in rows}
    checks(f"mesh adapted during the pass ({min(cells)} ... {max(cells)} cells)", len(cells) > 1)
    return checks.exit_status()


if __name__ == "__main__":
    sys.exit(main())
