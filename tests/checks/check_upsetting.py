#!/usr/bin/env python3
"""Scene check of prm/upsetting.prm (coarse and short: Q2 8x6 with F-bar, steps of 0.5 % and 1 %
of the initial height instead of 0.25 %; about 25 s on one core).

Asserts:
  - step size: the platen force of the 1 % run agrees within 0.5 % with the 0.5 % run
    (interpolated) at every reduction >= 1 % except within 1 % after a fold-over event (a node of
    the free surface touching the platen adds a force jump that the two runs see a step apart);
  - mesh: the force and the bulge radius at 30 % agree with the fine reference (Q2 16 x 12,
    0.25 % steps: 1682.0 kN, 24.629 mm; doc/scenes/upsetting.md) within 2 % and 1 %;
  - small strain underestimates the load at 30 % by more than 20 % (thesis section 3.4);
  - at most one cutback (the first 1 % step crosses the yield point and is cut back once).

Usage: check_upsetting.py AUSROLL SOURCE_DIR
"""

import csv
import os
import subprocess
import sys

from checklist import Checklist  # tests/checks/checklist.py (next to this script)

REFERENCE_FORCE_30 = 1682.0  # kN, Q2 16x12, 0.25 % steps
REFERENCE_BULGE_30 = 24.629  # mm


def run(ausroll, source, name, overrides):
    prm = f"{name}.prm"
    subprocess.run([sys.executable, os.path.join(source, "scripts", "prm_variant.py"),
                    os.path.join(source, "prm", "upsetting.prm"), prm,
                    f"Output/Directory = {name}", "Output/Write VTU = false",
                    "Output/Verbosity = quiet"] + overrides, check=True)
    result = subprocess.run([ausroll, prm, "--overwrite"], capture_output=True, text=True)
    if result.returncode != 0:
        print(result.stdout, result.stderr)
        raise SystemExit(f"{name}: ausroll failed with status {result.returncode}")
    with open(os.path.join(name, "history.csv")) as f:
        return list(csv.DictReader(f))


def main():
    ausroll, source = sys.argv[1], sys.argv[2]
    check = Checklist()

    half = run(ausroll, source, "step_050", ["Loading/Number of steps = 60"])
    one = run(ausroll, source, "step_100", ["Loading/Number of steps = 30"])
    small = run(ausroll, source, "small", ["Loading/Number of steps = 30",
                                           "Model/Kinematics = small strain"])

    def force(r):
        return -1e-3 * float(r["die_platen_force_y"])

    def events(rows):
        """Reductions at which the number of sticking nodes changes (fold-over)."""
        return [float(r["time"]) for p, r in zip(rows, rows[1:])
                if p["die_platen_stick_nodes"] != r["die_platen_stick_nodes"]]

    def interpolate(rows, t):
        for p, r in zip(rows, rows[1:]):
            t0, t1 = float(p["time"]), float(r["time"])
            if t1 >= t - 1e-12:
                return force(p) + (t - t0) / (t1 - t0) * (force(r) - force(p))
        return force(rows[-1])

    skip = events(half) + events(one)
    worst, compared = 0.0, 0
    for r in one:
        t = float(r["time"])
        if t < 1 or any(e - 1e-9 <= t <= e + 1.0 for e in skip):
            continue
        f_half = interpolate(half, t)
        worst = max(worst, abs(force(r) - f_half) / f_half)
        compared += 1
    print(f"{compared} points compared; fold-over events at {sorted(set(skip))} %")
    print(f"steps 0.5 % vs 1 %: max force deviation {worst:.3%} (outside fold-over events)")
    check("step size: forces within 0.5 %", worst <= 5e-3)

    f30, bulge30 = force(half[-1]), 20 + float(half[-1]["equator_ux"])
    print(f"30 %: force {f30:.1f} kN (reference {REFERENCE_FORCE_30}), bulge radius "
          f"{bulge30:.3f} mm (reference {REFERENCE_BULGE_30})")
    check("force at 30 % within 2 % of the fine mesh",
          abs(f30 / REFERENCE_FORCE_30 - 1) <= 0.02)
    check("bulge radius at 30 % within 1 % of the fine mesh",
          abs(bulge30 / REFERENCE_BULGE_30 - 1) <= 0.01)
    f30_small = force(small[-1])
    print(f"small strain at 30 %: {f30_small:.1f} kN ({f30_small / f30 - 1:+.1%})")
    check("small strain underestimates the load at 30 % by more than 20 %",
          f30_small < 0.8 * f30)
    cutbacks = sum(int(r["cutbacks"]) for r in half + one)
    check(f"at most one cutback (finite strain runs: {cutbacks}; the first 1 % step crosses "
          "the yield point)", cutbacks <= 1)
    return check.exit_status()


if __name__ == "__main__":
    sys.exit(main())
