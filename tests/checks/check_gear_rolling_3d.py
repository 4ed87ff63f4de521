#!/usr/bin/env python3
"""Checks of the 3D gear rolling scene (prm/gear_rolling_3d.prm) on short runs.

Usage:
  check_gear_rolling_3d.py slice AUSROLL PRM_2D PRM_3D
  check_gear_rolling_3d.py short AUSROLL PRM PRM_MIRRORED [--theta0 -8] [--rate 14] [--t-roll 0.1]
                                 [--mu 0.1] [--mu-margin 0.1]

slice: the 3D set-up against the 2D scene. PRM_3D is PRM_2D with the tooth extruded over a 1 mm
  slice with u_z = 0 on both z faces and the 3D spur die (extruded involute profile, rolling about
  Motion/Rolling/Axis = z). The 3D discrete problem is the 2D one repeated along z (the mesh is extruded,
  the die does not vary along z), so every history column both runs write agrees within 1e-8 of
  the column's largest value (only the Newton tolerance and round-off separate them), except
  cells, dofs, wall_seconds and the node counts (three nodes through the slice per 2D node), contact
  length and width (a surface coordinate); the 3D force has no z component (<= 1e-9 |F|).
  This separates set-up errors (geometry, die profile, motion, boundary ids) from 3D effects.

short: a few steps of the 3D scene (half face by symmetry) and its mirror image (the symmetry
  condition on the other z face of the same uniform-layer mesh: the tooth reflected about the
  middle of the mesh).
  1. Force sign: F_x < 0 at every loaded step (the die pushes the right flank towards -x) and
     the force per mm of face, |F_xy| / (Face width / 2), within 50 ... 1340 N/mm (the bounds of
     check/gear_rolling_short, tests/checks/cmake/gear_rolling.cmake: lost contact / plane-strain Prandtl
     pressure over the geometric contact chord).
  2. Coulomb bound, per node (the contact_NNNN.csv of every step): |R_t| <= mu R_n (1 + 1e-8) for
     every node in contact, R_t = (R_t1, R_t2) the tangential nodal force in the die's tangent
     plane, and |R_t| = mu R_n (1e-8 relative) for the slipping nodes (the return map is exact;
     only the Newton tolerance remains: measured 3e-10). For the total die force, |F_t| <=
     (1 + margin) mu F_n at every loaded step, F_n the component along the line of action
     (direction alpha + theta_G in the non-rotating gear frame: the common normal of conjugate
     involutes) and F_t the rest, including F_z. The margin (default 10 %) allows the contact
     nodes of the coarse mesh to sit off the line of action, where the die normal is tilted
     against it (the 2D run on the same section mesh gives max |F_t| / F_n = 0.108).
  3. Symmetry: the mirrored run gives the same F_x, F_y and the opposite F_z (1e-8 of max |F|):
     nothing in the mesh, the contact search or the assembly prefers a z direction.
"""

import argparse
import csv
import glob
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklist import Checklist, CoulombCone  # noqa: E402


def run(ausroll, prm, directory):
    os.makedirs(directory, exist_ok=True)
    r = subprocess.run([ausroll, os.path.abspath(prm), "--overwrite"], cwd=directory)
    if r.returncode != 0:
        print(f"FAIL {prm} exited with {r.returncode}")
        sys.exit(1)
    return list(csv.DictReader(open(os.path.join(directory, "out", "history.csv"))))


def slice_check(a):
    here = os.path.dirname(os.path.abspath(__file__))
    checks = Checklist()
    run(a.ausroll, a.prm, "2d")
    rows = run(a.ausroll, a.other, "3d")
    compare = subprocess.run([sys.executable, os.path.join(here, "compare_histories.py"),
                              os.path.join("2d", "out", "history.csv"),
                              os.path.join("3d", "out", "history.csv"), "--rel-tol", "1e-8",
                              "--ignore", "wall_seconds", "dofs", "cells", "die_stick_nodes",
                              "die_slip_nodes", "die_die_stick_nodes", "die_die_slip_nodes",
                              "die_die_contact_length", "die_die_contact_width",
                              # the planar rolling columns (2D only)
                              "die_die_revolution", "die_die_feed", "die_die_force_radial",
                              "die_die_force_tangential", "die_die_force_magnitude"])
    checks("3D slice history equals the 2D plane-strain history (1e-8)", compare.returncode == 0)
    fxy = max(math.hypot(float(r["die_die_force_x"]), float(r["die_die_force_y"])) for r in rows)
    fz = max(abs(float(r["die_die_force_z"])) for r in rows)
    checks(f"3D die force: max |F_xy| = {fxy:.6g} N, max |F_z| = {fz:.3g} N",
           fxy > 100 and fz <= 1e-9 * fxy)
    return checks.exit_status()


def short_check(a):
    checks = Checklist()
    rows = run(a.ausroll, a.prm, "half")
    mirrored = run(a.ausroll, a.other, "mirrored")
    worst, loaded, positive = 0.0, 0, []
    for r in rows:
        t = float(r["time"])
        f = [float(r[f"die_die_force_{c}"]) for c in "xyz"]
        if math.hypot(f[0], f[1]) <= 10.0:
            continue
        loaded += 1
        if not f[0] < 0.0:
            positive.append(t)
        theta = a.theta0 + a.rate * max(t - a.t_roll, 0.0)
        psi = math.radians(a.pressure_angle + theta)
        f_n = -(f[0] * math.cos(psi) + f[1] * math.sin(psi))
        f_t = math.hypot(-f[0] * math.sin(psi) + f[1] * math.cos(psi), f[2])
        worst = max(worst, f_t / f_n)
    checks(f"{loaded} loaded steps", loaded >= 3)
    checks(f"force sign: F_x < 0 at every loaded step (not at t = {positive})", not positive)
    checks(f"Coulomb bound, total force: max |F_t| / F_n = {worst:.4f} <= "
           f"{(1 + a.mu_margin) * a.mu:.4f}", worst <= (1 + a.mu_margin) * a.mu)
    cone = CoulombCone(sorted(glob.glob(os.path.join("half", "out", "contact_*.csv"))), a.mu)
    nodes, worst_node, worst_slip = len(cone.closed), cone.excess, cone.slip
    checks(f"Coulomb bound per node: {nodes} node-steps in contact, max |R_t| / (mu R_n) - 1 = "
           f"{worst_node:.2e} <= 1e-8; slipping nodes |R_t| = mu R_n within {worst_slip:.2e}",
           nodes > 0 and worst_node <= 1e-8 and worst_slip <= 1e-8)
    last = rows[-1]
    per_mm = math.hypot(float(last["die_die_force_x"]), float(last["die_die_force_y"])) / a.half
    checks(f"force per mm of face at t = {last['time']}: {per_mm:.1f} N/mm in [50, 1340]",
           50.0 <= per_mm <= 1340.0)
    scale = max(math.hypot(*(float(r[f"die_die_force_{c}"]) for c in "xyz")) for r in rows)
    worst_sym = 0.0
    checks(f"mirrored run: {len(mirrored)} rows as the half run", len(mirrored) == len(rows))
    for r, m in zip(rows, mirrored):
        for c, s in (("x", 1.0), ("y", 1.0), ("z", -1.0)):
            k = f"die_die_force_{c}"
            worst_sym = max(worst_sym, abs(float(r[k]) - s * float(m[k])) / scale)
    checks(f"symmetry: mirrored F_x, F_y equal, F_z opposite: worst {worst_sym:.2e} of max |F| "
           f"(<= 1e-8)", worst_sym <= 1e-8)
    return checks.exit_status()


def main():
    p = argparse.ArgumentParser()
    p.add_argument("mode", choices=["slice", "short"])
    p.add_argument("ausroll")
    p.add_argument("prm")
    p.add_argument("other")
    p.add_argument("--theta0", type=float, default=-8.0)
    p.add_argument("--rate", type=float, default=14.0)
    p.add_argument("--t-roll", type=float, default=0.1)
    p.add_argument("--pressure-angle", type=float, default=22.0)
    p.add_argument("--mu", type=float, default=0.1)
    p.add_argument("--mu-margin", type=float, default=0.10)
    p.add_argument("--half", type=float, default=12.7, help="half face width of the mesh (mm)")
    a = p.parse_args()
    return slice_check(a) if a.mode == "slice" else short_check(a)


if __name__ == "__main__":
    sys.exit(main())
