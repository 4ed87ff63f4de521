#!/usr/bin/env python3
"""Elastic-plastic indentation by a rigid cylinder (prm/indentation.prm): force-depth checks.

Reads history.csv of the half model (die named --die): depth d = -die_<die>_y, force per mm of
thickness on the half model F = -die_<die>_force_y, contact half-width a = die_<die>_contact_width.
Asserts
  1. the punch force increases strictly with the depth (loading of a hardening material), and
  2. once the contact is well developed (depth >= --from-depth), the mean contact pressure
     p_m = F / a lies within --tol of the plane-strain limit pressure (2 + pi) k, k = sigma_y/sqrt 3,
     of a flat punch on a rigid-plastic half-space (Prandtl/Hill slip-line solution). A shallow
     cylinder (a/R < 0.5) is nearly flat under the contact, so p_m tends to that value; the
     tolerance covers hardening (H' eps_p ~ 1 % of sigma_y here), friction and the curvature of
     the punch (slip-line fields for cylinders give p_m within a few % of (2 + pi) k, Johnson 1985,
     ch. 6), and the discretisation of a by the contact nodes.
Exit status 0 if all hold, 1 otherwise, 2 on data errors.
"""

import argparse
import csv
import math
import sys


def main():
    p = argparse.ArgumentParser()
    p.add_argument("history")
    p.add_argument("--die", default="punch")
    p.add_argument("--yield-stress", type=float, required=True)
    p.add_argument("--from-depth", type=float, required=True)
    p.add_argument("--tol", type=float, required=True)
    a = p.parse_args()
    try:
        rows = list(csv.DictReader(open(a.history)))
    except OSError as e:
        print(f"check_indentation.py: cannot read {a.history}: {e.strerror}", file=sys.stderr)
        return 2
    prefix = f"die_{a.die}_"
    try:
        data = [(-float(r[prefix + "y"]), -float(r[prefix + "force_y"]),
                 float(r[prefix + "contact_width"])) for r in rows]
    except KeyError as e:
        print(f"check_indentation.py: no column {e}", file=sys.stderr)
        return 2
    failed = 0
    p_lim = (2 + math.pi) * a.yield_stress / math.sqrt(3)
    print(f"{'depth':>8} {'force':>10} {'a':>8} {'p_m':>9} {'p_m/p_lim':>9}")
    checked = 0
    for k, (d, f, w) in enumerate(data):
        pm = f / w if w > 0 else float("nan")
        line = f"{d:8.4f} {f:10.2f} {w:8.4f} {pm:9.2f} {pm / p_lim:9.4f}"
        if k > 0 and d > data[k - 1][0] and not f > data[k - 1][1]:
            line += "  <- force does not increase"
            failed += 1
        if d >= a.from_depth * (1 - 1e-9):
            checked += 1
            if not abs(pm / p_lim - 1) <= a.tol:
                line += f"  <- p_m off (2 + pi) k by more than {a.tol:.0%}"
                failed += 1
        print(line)
    if checked == 0:
        print(f"check_indentation.py: no row with depth >= {a.from_depth}", file=sys.stderr)
        return 2
    print(f"(2 + pi) k = {p_lim:.2f} MPa; {checked} rows checked: " + ("passed" if not failed else "FAILED"))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
