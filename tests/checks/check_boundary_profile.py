#!/usr/bin/env python3
"""Check of Postprocess/Boundary profile and Geometry/Type = ring against Lame's solution.

Runs tests/checks/scenes/ring_lame_profile.prm (full ring, bore pressurised, outer circle held)
on 1 rank, on 1 rank with one global refinement plus local refinement (hanging nodes), and on 2
MPI ranks, and checks the last profile_NNNN.csv of each:
  - one row per rim support point (Q2: 2 per cell edge on each circle), sorted by angle, angles
    covering [0, 360) with no duplicate;
  - reference radius equal to the circle radius to 1e-9 (exact circular manifold);
  - bore: radial displacement = Lame's u(a) at every angle within 0.2 % (measured ~1e-4 on the
    24 x 4 Q2 mesh; the bound covers the discretisation error of Q2 on that mesh);
  - outer circle: radial displacement 0 (Dirichlet) to 1e-12 mm;
  - np = 2 writes the same file as np = 1 (1e-9 mm).

Usage: check_boundary_profile.py AUSROLL SOURCE_DIR
"""

import csv
import glob
import math
import os
import subprocess
import sys

from checklist import Checklist  # tests/checks/checklist.py (next to this script)

A_IN, B_OUT, E, NU, P = 17.80, 43.55, 68950.0, 0.33, 100.0


def lame_u_inner():
    lam = E * NU / ((1 + NU) * (1 - 2 * NU))
    mu = E / (2 * (1 + NU))
    a_coef = -P / (2 * (lam + mu) + 2 * mu * B_OUT ** 2 / A_IN ** 2)
    return a_coef * (A_IN ** 2 - B_OUT ** 2) / A_IN


def run(ausroll, source, name, np, overrides):
    prm = f"{name}.prm"
    subprocess.run([sys.executable, os.path.join(source, "scripts", "prm_variant.py"),
                    os.path.join(source, "tests", "checks", "scenes", "ring_lame_profile.prm"),
                    prm, f"Output/Directory = {name}"] + overrides, check=True)
    cmd = [ausroll, prm, "--overwrite"]
    if np > 1:
        cmd = ["mpirun", "-np", str(np)] + cmd
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    result = subprocess.run(cmd, capture_output=True, text=True, env=env)
    if result.returncode != 0:
        print(result.stdout, result.stderr)
        raise SystemExit(f"{name}: ausroll failed with status {result.returncode}")
    last = sorted(glob.glob(os.path.join(name, "profile_*.csv")))[-1]
    with open(last) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def main():
    ausroll, source = sys.argv[1], sys.argv[2]
    check = Checklist()

    u_a = lame_u_inner()
    print(f"Lame: u(a) = {u_a:.8f} mm")
    cases = {
        "serial": (1, [], 24),
        "hanging": (1, ["Geometry/Global refinements = 1", "Geometry/Refinement point = 17.8, 0",
                        "Geometry/Refinement radius = 10", "Geometry/Local refinements = 1"],
                    None),
        "np2": (2, [], 24),
    }
    profiles = {}
    for name, (np, overrides, cells) in cases.items():
        rows = run(ausroll, source, name, np, overrides)
        profiles[name] = rows
        angles = [r["angle"] for r in rows]
        check(f"{name}: {len(rows)} rows sorted by angle",
              all(a <= b for a, b in zip(angles, angles[1:])))
        for bid, radius in ((0, A_IN), (1, B_OUT)):
            part = [r for r in rows if int(r["boundary_id"]) == bid]
            ang = [r["angle"] for r in part]
            distinct = len(set(round(a, 9) for a in ang)) == len(ang)
            check(f"{name}: boundary {bid}: {len(part)} points, distinct angles, sorted, "
                  f"in [0, 360)", distinct and ang == sorted(ang) and 0 <= ang[0] and ang[-1] < 360)
            if cells is not None:
                check(f"{name}: boundary {bid}: 2 x {cells} Q2 support points",
                      len(part) == 2 * cells)
            r0 = max(abs(math.hypot(r["x"], r["y"]) - radius) for r in part)
            check(f"{name}: boundary {bid}: reference points on the circle ({r0:.1e} mm)",
                  r0 < 1e-9)
            if bid == 0:
                err = max(abs(r["radial_displacement"] - u_a) for r in part) / abs(u_a)
                check(f"{name}: bore radial displacement = Lame u(a) at every angle "
                      f"(max rel. error {err:.1e} <= 2e-3)", err <= 2e-3)
                cur = max(abs(r["radius"] - radius - r["radial_displacement"]) for r in part)
                check(f"{name}: radius - reference radius = radial_displacement ({cur:.1e})",
                      cur < 1e-9)
            else:
                u0 = max(abs(r["radial_displacement"]) for r in part)
                check(f"{name}: outer circle held ({u0:.1e} mm)", u0 < 1e-12)
    a, b = profiles["serial"], profiles["np2"]
    same = len(a) == len(b) and all(
        abs(ra[k] - rb[k]) < 1e-9 for ra, rb in zip(a, b) for k in ("x", "y", "current_x",
                                                                     "current_y"))
    check("np = 2 profile equals np = 1 (1e-9 mm)", same)
    return check.exit_status()


if __name__ == "__main__":
    sys.exit(main())
