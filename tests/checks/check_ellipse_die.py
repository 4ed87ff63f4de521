#!/usr/bin/env python3
"""The elliptic die in a whole scene: tests/checks/scenes/disk_rolling_short.prm (a Coulomb
mu = 0.3 roll of radius 116.60 mm fed into a ring and rolled 20 degrees, nested active set) run
with its circle die and again with `Shape = ellipse`, semi-axes a = b = 116.60: the ellipse's
projection, normal, curvature and arc length s (stick points, slip along the die) equal the
circle's to rounding (unit test EllipseSurface.CircleLimitEqualsCircleShape, 1e-12), so the
histories must agree to 1e-10 relative (measured 3.8e-13). Then an oval roll (a = 116.60,
b = 0.98 a, the a axis along the line of centres at t = 0) must run to the end and press the
ring (die force towards the ring centre) at every loaded step until t = 20 (the end time).

Usage: check_ellipse_die.py AUSROLL SOURCE_DIR
"""

import csv
import os
import subprocess
import sys

from checklist import ausroll_command  # tests/checks/checklist.py (next to this script)

ausroll, source = sys.argv[1], sys.argv[2]
prm = os.path.join(source, "tests", "checks", "scenes", "disk_rolling_short.prm")
compare = os.path.join(source, "tests", "checks", "compare_histories.py")


def run(directory, *overrides):
    args = ausroll_command(ausroll, prm, (f"Output/Directory={directory}",) + overrides)
    status = subprocess.run(args, stdout=subprocess.DEVNULL).returncode
    if status != 0:
        sys.exit(f"FAIL: {directory} exited with {status}")
    return os.path.join(directory, "history.csv")


ellipse = ["Contact/Die 0/Shape=ellipse", "Contact/Die 0/Ellipse/Center=0, 0",
           "Contact/Die 0/Ellipse/Semi-axis a=116.60"]
circle = run("circle")
round_ellipse = run("ellipse_round", *ellipse, "Contact/Die 0/Ellipse/Semi-axis b=116.60")
status = subprocess.run([sys.executable, compare, circle, round_ellipse, "--rel-tol",
                         "1e-10"]).returncode
if status != 0:
    sys.exit("FAIL: the ellipse with a = b does not reproduce the circle die to 1e-10")

oval = run("ellipse_oval", *ellipse, "Contact/Die 0/Ellipse/Semi-axis b=114.268",
           "Contact/Die 0/Ellipse/Rotation angle=90")
with open(oval) as f:
    rows = list(csv.DictReader(f))
radial = [float(r["die_roll_force_radial"]) for r in rows if float(r["time"]) > 0.5]
if not rows or abs(float(rows[-1]["time"]) - 20.) > 1e-9 or not radial or max(radial) >= 0.:
    sys.exit(f"FAIL: the oval roll does not press the ring: force_radial {radial}")
print(f"ellipse a = b reproduces the circle die; oval roll: {len(rows)} rows, "
      f"force_radial {min(radial):.1f} ... {max(radial):.1f} N/mm")
print("passed")
