#!/usr/bin/env python3
"""Oblique slide under a plane die (scenes/block3d_oblique_slide.prm): checks on its history.csv.

Asserts:
  * partial slip at t = 2 (after the small slide of 0.0006 mm): sticking nodes present and
    0.05 < |F_t| / (mu F_n) < 0.9;
  * full slip for 5 <= t <= 6 (after the elastic transient of the start of sliding, which decays
    by a factor ~0.2 per step): no sticking node and the tangential die force on the block is the
    vector mu F_n e_s (e_s the die's sliding direction, i.e. -mu F_n along the block's slip
    direction relative to the die): |F_t - mu F_n e_s| / (mu F_n) <= 1e-9 (the exact Coulomb
    cone; the history's 10 digits allow ~1e-10), and the top reaction balances the die force
    (1e-8: the out-of-balance force of the free equations is below the Newton tolerance, 1e-9 of
    the force level, in the l2 norm; its sum over the nodes can be up to sqrt(n) times that:
    measured 1.1e-9 since the slip direction is linearised consistently and Newton stops at its
    tolerance, 0 to the history's digits when extra direction passes drove it to round-off);
  * after the release (t = 7): no force, no sticking or slipping node.

Usage: check_oblique_slide_3d.py HISTORY [--mu 0.3] [--angle 30]
"""

import argparse
import csv
import math
import sys

from checklist import Checklist  # tests/checks/checklist.py (next to this script)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("history")
    p.add_argument("--mu", type=float, default=0.3)
    p.add_argument("--angle", type=float, default=30.0, help="sliding direction from x (degrees)")
    p.add_argument("--die", default="plate")
    a = p.parse_args()
    rows = list(csv.DictReader(open(a.history)))
    phi = math.radians(a.angle)
    e_s = (math.cos(phi), math.sin(phi))
    checks = Checklist()

    def force(r, prefix):
        return [float(r[f"{prefix}_{c}"]) for c in "xyz"]

    def at(t):
        best = min(rows, key=lambda r: abs(float(r["time"]) - t))
        if abs(float(best["time"]) - t) > 1e-9 * max(1.0, t):
            print(f"check_oblique_slide_3d.py: no row at t = {t}", file=sys.stderr)
            sys.exit(2)
        return best

    die = f"die_{a.die}"
    r = at(2.0)
    fx, fy, fz = force(r, f"{die}_force")
    ratio = math.hypot(fx, fy) / (a.mu * fz)
    n_stick = int(float(r[f"{die}_stick_nodes"]))
    checks(f"t = 2: {n_stick} sticking nodes, |F_t| / mu F_n = {ratio:.4f} (partial slip)",
           n_stick > 0 and 0.05 < ratio < 0.9)

    worst_slip, worst_balance, worst_stick, n_rows = 0.0, 0.0, 0, 0
    for r in rows:
        t = float(r["time"])
        if t < 5.0 - 1e-9 or t > 6.0 + 1e-9:
            continue
        n_rows += 1
        fx, fy, fz = force(r, f"{die}_force")
        mu_fn = a.mu * fz
        worst_slip = max(worst_slip, math.hypot(fx - mu_fn * e_s[0], fy - mu_fn * e_s[1]) / mu_fn)
        rx, ry, rz = force(r, "reaction_5")
        worst_balance = max(worst_balance, math.sqrt((fx + rx) ** 2 + (fy + ry) ** 2 + (fz + rz) ** 2)
                            / math.sqrt(fx * fx + fy * fy + fz * fz))
        worst_stick = max(worst_stick, int(float(r[f"{die}_stick_nodes"])))
    checks(f"full slip, {n_rows} steps in 5 <= t <= 6: max |F_t - mu F_n e_s| / mu F_n = "
           f"{worst_slip:.2e} (<= 1e-9), no sticking node ({worst_stick})",
           n_rows >= 4 and worst_slip <= 1e-9 and worst_stick == 0)
    checks(f"full slip: max |F_die + R_top| / |F_die| = {worst_balance:.2e} (<= 1e-8)",
           n_rows >= 4 and worst_balance <= 1e-8)

    r = at(7.0)
    f = force(r, f"{die}_force")
    closed = int(float(r[f"{die}_stick_nodes"])) + int(float(r[f"{die}_slip_nodes"]))
    checks(f"released (t = 7): |F| = {math.sqrt(sum(x * x for x in f)):.1e}, {closed} closed nodes",
           all(x == 0.0 for x in f) and closed == 0)
    return checks.exit_status()


if __name__ == "__main__":
    sys.exit(main())
