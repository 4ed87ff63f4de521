#!/usr/bin/env python3
"""3D upsetting against the axisymmetric run of the same scene (issue 14, 6b).

Runs scenes/upsetting_3d_short.prm (configured into the build directory: the quarter cylinder of
prm/upsetting_3d.prm, one global refinement: 4 Q2 cells along the radius, 4 layers; to 10 %
height reduction in 1 % steps) and prm/upsetting.prm (axisymmetric) on the matching Q2 4 x 4
rectangle with the same steps, and compares the platen force (3D: 4 x die_platen_force_z of the
quarter; 2D: die_platen_force_y, full 2 pi).

Asserts: |F_3D - F_2D| / F_2D <= 1 % at every step from 1 % on (measured <= 0.17 %). Reason for
the tolerance: the two meshes are different discretisations of the same body; at matched
resolution the difference stays far below the mesh error of either (axisymmetric Q2 4x4 -> 8x8:
1.4 % at 10 %; quarter cylinder 1 -> 2 refinements: 1.3 %), and 1 % is the issue's figure. The
full 30 % comparison is the benchmark benchmark_upsetting_3d (doc/scenes/verification_3d.md).

Usage: check_upsetting_3d.py AUSROLL SOURCE_DIR SHORT_3D_PRM
"""

import csv
import os
import subprocess
import sys

from checklist import Checklist  # tests/checks/checklist.py (next to this script)


def history(path):
    with open(path) as f:
        return {round(float(r["time"]), 9): r for r in csv.DictReader(f)}


def main():
    ausroll, source, prm3d = sys.argv[1], sys.argv[2], sys.argv[3]
    checks = Checklist()
    subprocess.run([sys.executable, os.path.join(source, "scripts", "prm_variant.py"),
                    os.path.join(source, "prm", "upsetting.prm"), "axisymmetric.prm",
                    "Geometry/Rectangle/Cells = 4, 4", "Loading/End time = 10",
                    "Loading/Number of steps = 10", "Output/Directory = out2d",
                    "Output/Write VTU = false", "Output/Verbosity = quiet"], check=True)
    for prm, name in (("axisymmetric.prm", "2D"), (prm3d, "3D")):
        run = subprocess.run([ausroll, prm, "--overwrite"])
        if run.returncode != 0:
            print(f"FAIL {name} run exited with {run.returncode}")
            return 1
    h2, h3 = history(os.path.join("out2d", "history.csv")), history(os.path.join("out", "history.csv"))
    worst, worst_t, n = 0.0, 0.0, 0
    for t, r in sorted(h3.items()):
        if t < 1.0 - 1e-9 or t not in h2:  # (a cut-back step may add a time to one run)
            continue
        f3 = -4.0 * float(r["die_platen_force_z"])
        f2 = -float(h2[t]["die_platen_force_y"])
        dev = abs(f3 - f2) / abs(f2)
        n += 1
        if dev > worst:
            worst, worst_t = dev, t
        if t in (5.0, 10.0):
            print(f"     {t:g} %: F_3D = {f3 / 1000:.2f} kN, F_2D = {f2 / 1000:.2f} kN "
                  f"({100 * (f3 - f2) / f2:+.3f} %); bulge u_r: 3D {float(r['equator_ux']):.4f}, "
                  f"2D {float(h2[t]['equator_ux']):.4f} mm")
    checks(f"platen force 3D vs axisymmetric, {n} steps 1-10 %: max deviation "
           f"{100 * worst:.3f} % at {worst_t:g} % (<= 1 %)", n >= 10 and worst <= 0.01)
    return checks.exit_status()


if __name__ == "__main__":
    sys.exit(main())
