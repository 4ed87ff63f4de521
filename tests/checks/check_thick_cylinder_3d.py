#!/usr/bin/env python3
"""Plane-strain thick cylinder as a 3D slice (issue 14, 6c): scenes/thick_cylinder_3d.prm (thick
ring sector of 90 degrees, symmetry planes, u_z = 0 on both z faces) against the 2D scene
prm/thick_cylinder.prm and its reference.

Asserts:
  * u(b) of the 3D run within 0.5 % of the independent 1D radial solution along the whole load
    path (reference/thick_cylinder_load.csv, compare_curves.py: the 2D scene's check and
    tolerance; measured 3e-4);
  * every history column the 2D run also has (u(b), u(a), pressure, yield excess) equals the 2D
    run's within 1e-8 relative to the column's largest value: the in-plane mesh is the same and
    u_z = 0 makes the 3D problem the plane-strain one, so only the Newton tolerance and round-off
    separate them (measured 5e-11). Not compared: dofs, wall_seconds, newton_iterations (the
    3D residual norm has more entries, so a step can take one iteration more or less).

Usage: check_thick_cylinder_3d.py AUSROLL SOURCE_DIR
"""

import os
import subprocess
import sys

from checklist import Checklist  # tests/checks/checklist.py (next to this script)


def main():
    ausroll, source = sys.argv[1], sys.argv[2]
    here = os.path.dirname(os.path.abspath(__file__))
    checks = Checklist()
    subprocess.run([sys.executable, os.path.join(source, "scripts", "prm_variant.py"),
                    os.path.join(source, "prm", "thick_cylinder.prm"), "thick_cylinder_2d.prm",
                    "Output/Directory = out2d", "Output/Write VTU = false",
                    "Output/Verbosity = quiet"], check=True)
    for prm, name in (("thick_cylinder_2d.prm", "2D"),
                      (os.path.join(here, "scenes", "thick_cylinder_3d.prm"), "3D")):
        run = subprocess.run([ausroll, prm, "--overwrite"])
        if run.returncode != 0:
            print(f"FAIL {name} run exited with {run.returncode}")
            return 1
    h2, h3 = os.path.join("out2d", "history.csv"), os.path.join("out", "history.csv")
    curve = subprocess.run([sys.executable, os.path.join(here, "compare_curves.py"),
                            "--result", h3, "--reference",
                            os.path.join(here, "reference", "thick_cylinder_load.csv"),
                            "--x-result", "pressure_0", "--y-result", "outer_ux",
                            "--x-reference", "pressure", "--y-reference", "u_outer",
                            "--rel-tol", "0.005", "--x-min", "1"])
    checks("3D u(b) within 0.5 % of the 1D reference along the load path", curve.returncode == 0)
    same = subprocess.run([sys.executable, os.path.join(here, "compare_histories.py"), h2, h3,
                           "--rel-tol", "1e-8", "--ignore", "wall_seconds", "dofs",
                           "newton_iterations"])
    checks("3D history equals the 2D plane-strain history (1e-8)", same.returncode == 0)
    return checks.exit_status()


if __name__ == "__main__":
    sys.exit(main())
