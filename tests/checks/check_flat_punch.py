#!/usr/bin/env python3
"""Scene check of prm/flat_punch.prm: volumetric locking and the Prandtl limit load.

Plane-strain rough flat punch on a perfectly plastic block (small strain), limit pressure
p_lim = (2 + pi) sigma_y / sqrt(3) = 593.65 MPa. On the graded mesh with smallest cell 0.025 mm
(prm/flat_punch_mesh.py --h 0.025 --growth 1.1, 49 x 34 cells):
  - Q1 with F-bar: the pressure reaches a plateau (last two steps within 0.1 %) within 3 % of
    p_lim (measured +1.7 %; +3.2 % with 0.05 mm cells, +1.0 % with 0.0125 mm: converges from above);
  - Q1 with full 2x2 integration, no treatment: locks; at the same indentation (0.06 mm) the
    pressure is more than 8 % above p_lim (measured +13.6 %) and still rising (no limit load).

Usage: check_flat_punch.py AUSROLL SOURCE_DIR
"""

import csv
import math
import os
import subprocess
import sys

from checklist import Checklist  # tests/checks/checklist.py (next to this script)


def run(ausroll, source, name, overrides):
    subprocess.run([sys.executable, os.path.join(source, "prm", "flat_punch_mesh.py"),
                    "punch.msh", "--h", "0.025", "--growth", "1.1"], check=True,
                   stdout=subprocess.DEVNULL)
    prm = f"{name}.prm"
    subprocess.run([sys.executable, os.path.join(source, "scripts", "prm_variant.py"),
                    os.path.join(source, "prm", "flat_punch.prm"), prm,
                    "Geometry/Mesh file = punch.msh", f"Output/Directory = {name}",
                    "Output/Write VTU = false", "Output/Verbosity = quiet"] + overrides,
                   check=True)
    result = subprocess.run([ausroll, prm, "--overwrite"], capture_output=True, text=True)
    if result.returncode != 0:
        print(result.stdout, result.stderr)
        raise SystemExit(f"{name}: ausroll failed with status {result.returncode}")
    with open(os.path.join(name, "history.csv")) as f:
        return [-float(r["reaction_4_y"]) for r in csv.DictReader(f)]


def main():
    ausroll, source = sys.argv[1], sys.argv[2]
    p_lim = (2 + math.pi) * 200 / math.sqrt(3)
    check = Checklist()

    fbar = run(ausroll, source, "q1_fbar", ["Model/Volumetric locking treatment = F-bar"])
    full = run(ausroll, source, "q1_full", ["Model/Volumetric locking treatment = none"])
    print("indentation steps:", len(fbar) - 1)
    print("Q1 F-bar    p / p_lim:", " ".join(f"{p / p_lim:.4f}" for p in fbar[1:]))
    print("Q1 full int p / p_lim:", " ".join(f"{p / p_lim:.4f}" for p in full[1:]))
    check(f"Q1 F-bar plateau: last steps {fbar[-2]:.2f}, {fbar[-1]:.2f} MPa within 0.1 %",
          abs(fbar[-1] - fbar[-2]) <= 1e-3 * fbar[-1])
    check(f"Q1 F-bar limit pressure {fbar[-1]:.2f} MPa within 3 % of (2 + pi) k = {p_lim:.2f}"
          f" ({fbar[-1] / p_lim - 1:+.2%})", abs(fbar[-1] / p_lim - 1) <= 0.03)
    check(f"Q1 full integration locks: {full[-1]:.2f} MPa = {full[-1] / p_lim - 1:+.2%} > +8 %",
          full[-1] > 1.08 * p_lim)
    check("Q1 full integration still rising at the end (no limit load)",
          full[-1] - full[-2] > 2e-3 * full[-1])
    return check.exit_status()


if __name__ == "__main__":
    sys.exit(main())
