#!/usr/bin/env python3
"""A scene on an Abaqus mesh (.inp through deal.II's GridIn::read_abaqus) runs and agrees with
the same mesh built internally and with the analytic answer.

Usage: check_abaqus_mesh.py AUSROLL SOURCE_DIR

tests/checks/scenes/abaqus_block_press.prm reads block_5x2.inp (10 x 2 mm, 5 x 2 CPE4 elements,
surfaces SS1, SS2, SS3 -> boundary ids 1, 2, 3; the conditions on ids 0, 2 and the die's candidate
boundary 3 are refused unless the ids were mapped). Expected:
- the same scene with Geometry/Type = rectangle, Cells = 5, 2 (colorized ids 0..3 on x = 0,
  x = 10, y = 0, y = 2): every history column equal within 1e-9 relative to the column's scale
  (the same discrete problem; only the cell and DoF numbering differ, so round-off);
- the die force at t = 1: E/(1 - nu^2) * (0.010/2) * 10 = 11538.46154 N/mm within 1e-6 relative
  (the uniform state is exact for bilinear elements; the solver tolerance limits the digits).
"""

import csv
import os
import shutil
import subprocess
import sys


def main():
    ausroll, source = sys.argv[1], sys.argv[2]
    here = os.getcwd()
    prm = os.path.join(source, "tests", "checks", "scenes", "abaqus_block_press.prm")
    runs = {
        "abaqus": [],
        "internal": ["--set", "Geometry/Type=rectangle",
                     "--set", "Geometry/Rectangle/Upper right corner=10, 2",
                     "--set", "Geometry/Rectangle/Cells=5, 2"],
    }
    for name, args in runs.items():
        shutil.rmtree(os.path.join(here, name), ignore_errors=True)
        result = subprocess.run([ausroll, prm, "--set", f"Output/Directory={name}"] + args,
                                cwd=here, capture_output=True, text=True, timeout=300)
        if result.returncode != 0:
            print(f"FAIL: the {name} run ended with {result.returncode}:\n{result.stderr}")
            return 1
    compare = subprocess.run([sys.executable, os.path.join(source, "tests", "checks",
                                                           "compare_histories.py"),
                              os.path.join(here, "abaqus", "history.csv"),
                              os.path.join(here, "internal", "history.csv"),
                              "--rel-tol", "1e-9"])
    if compare.returncode != 0:
        print("FAIL: the Abaqus mesh and the internal mesh give different histories")
        return 1
    with open(os.path.join(here, "abaqus", "history.csv"), newline="") as f:
        last = list(csv.DictReader(f))[-1]
    force = -float(last["die_punch_force_y"])
    exact = 210000 / (1 - 0.3 ** 2) * 0.010 / 2 * 10
    error = abs(force - exact) / exact
    print(f"die force {force:.8f} N/mm, analytic {exact:.8f}, relative error {error:.2e}")
    if error > 1e-6:
        print("FAIL: the die force differs from the analytic one")
        return 1
    print("ok: the Abaqus mesh agrees with the internal mesh (1e-9) and the analytic force (1e-6)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
