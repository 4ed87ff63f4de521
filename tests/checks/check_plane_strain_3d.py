#!/usr/bin/env python3
"""3D-against-2D check: scenes/cylinder_block_3d.prm (a block extruded 1 mm along z with u_z = 0
on both z faces, pressed by a frictionless cylinder) reproduces the plane-strain 2D scene
scenes/cylinder_block_2d.prm (same x-y mesh, circle die, motion).

Asserts: every history column of the 2D run that the 3D run also has agrees within 1e-8
relative to the column's largest value (compare_histories.py; the two discrete problems are the
same, so only the Newton tolerance and round-off separate them; measured 0 to 10 digits) except
dofs, wall_seconds and the columns counted differently in 3D (slip nodes: 3 nodes through the
thickness per 2D node; contact length: a surface coordinate of the cylinder); the 3D die force
has no z component.

Usage: check_plane_strain_3d.py AUSROLL SOURCE_DIR
"""

import csv
import os
import subprocess
import sys

from checklist import Checklist  # tests/checks/checklist.py (next to this script)


def main():
    ausroll, source = sys.argv[1], sys.argv[2]
    here = os.path.dirname(os.path.abspath(__file__))
    checks = Checklist()
    histories = {}
    for d in ("2d", "3d"):
        os.makedirs(d, exist_ok=True)
        prm = os.path.join(here, "scenes", f"cylinder_block_{d}.prm")
        run = subprocess.run([ausroll, prm, "--overwrite"], cwd=d)
        if run.returncode != 0:
            print(f"FAIL {d} run exited with {run.returncode}")
            return 1
        histories[d] = os.path.join(d, "out", "history.csv")
    compare = subprocess.run([sys.executable, os.path.join(here, "compare_histories.py"),
                              histories["2d"], histories["3d"], "--rel-tol", "1e-8",
                              "--ignore", "wall_seconds", "dofs", "die_roll_slip_nodes",
                              "die_roll_contact_length"])
    checks("3D history equals the 2D plane-strain history (1e-8)", compare.returncode == 0)
    rows = list(csv.DictReader(open(histories["3d"])))
    force_y = max(abs(float(r["die_roll_force_y"])) for r in rows)
    force_z = max(abs(float(r["die_roll_force_z"])) for r in rows)
    checks(f"3D die force: max |F_y| = {force_y:.6g} N, max |F_z| = {force_z:.3g} N",
           force_y > 100 and force_z <= 1e-9 * force_y)
    return checks.exit_status()


if __name__ == "__main__":
    sys.exit(main())
