#!/usr/bin/env python3
"""Benchmark: upsetting to 30 % height reduction, quarter cylinder (prm/upsetting_3d.prm, 3D)
against the axisymmetric scene (prm/upsetting.prm) at matched resolutions (issue 14, 6b).

For each level g (default 1 2) runs the quarter cylinder with `Global refinements = g`
(2^(g+1) Q2 cells along the radius on y = 0 and through the half height) and the axisymmetric
rectangle with n x n Q2 cells, n = 2^(g+1), both with 0.5 % steps (60 steps), and prints a
Markdown table: platen force (kN; 3D: 4 x the quarter's), its deviation, bulge u_r of the equator
and the CPU time (user + sys of the ausroll process) of every run. No pass/fail.

Usage: upsetting_3d.py --ausroll BUILD/ausroll [--work DIR] [--levels 1 2] [--steps 60]
"""

import argparse
import csv
import os
import resource
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(os.path.dirname(HERE))


def run(ausroll, work, base, name, overrides):
    prm = os.path.join(work, f"{name}.prm")
    subprocess.run([sys.executable, os.path.join(SOURCE, "scripts", "prm_variant.py"),
                    os.path.join(SOURCE, "prm", base), prm, f"Output/Directory = {name}",
                    "Output/Write VTU = false", "Output/Verbosity = quiet"] + overrides,
                   check=True)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([ausroll, prm, "--overwrite"], cwd=work, check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    with open(os.path.join(work, name, "history.csv")) as f:
        return {round(float(r["time"]), 9): r for r in csv.DictReader(f)}, cpu


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--ausroll", required=True)
    p.add_argument("--work", default="upsetting_3d")
    p.add_argument("--levels", type=int, nargs="+", default=[1, 2])
    p.add_argument("--steps", type=int, default=60)
    a = p.parse_args()
    os.makedirs(a.work, exist_ok=True)
    print("| mesh (3D / axisymmetric) | reduction | F 3D (kN) | F axisym. (kN) | deviation | "
          "bulge u_r 3D / axisym. (mm) |")
    print("|---|---:|---:|---:|---:|---:|")
    cpu_rows = []
    for g in a.levels:
        n = 2 ** (g + 1)
        h3, c3 = run(a.ausroll, a.work, "upsetting_3d.prm", f"quarter_g{g}",
                     [f"Geometry/Global refinements = {g}", f"Loading/Number of steps = {a.steps}"])
        h2, c2 = run(a.ausroll, a.work, "upsetting.prm", f"axisym_{n}x{n}",
                     [f"Geometry/Rectangle/Cells = {n}, {n}", f"Loading/Number of steps = {a.steps}"])
        common = sorted(t for t in h3 if t in h2 and t > 0)
        worst = max(common, key=lambda t: abs(4 * float(h3[t]["die_platen_force_z"])
                                               / float(h2[t]["die_platen_force_y"]) - 1))
        for t in sorted({5.0, 10.0, 20.0, 30.0, worst} & set(common)):
            f3 = -4e-3 * float(h3[t]["die_platen_force_z"])
            f2 = -1e-3 * float(h2[t]["die_platen_force_y"])
            note = " (largest)" if t == worst else ""
            print(f"| g = {g} / {n} x {n} | {t:g} %{note} | {f3:.1f} | {f2:.1f} | "
                  f"{100 * (f3 - f2) / f2:+.2f} % | {float(h3[t]['equator_ux']):.4f} / "
                  f"{float(h2[t]['equator_ux']):.4f} |")
        cpu_rows.append((g, n, int(h3[common[-1]]["dofs"]), c3, int(h2[common[-1]]["dofs"]), c2))
    print()
    print("| level | 3D DoFs | 3D CPU (s) | axisym. DoFs | axisym. CPU (s) |")
    print("|---|---:|---:|---:|---:|")
    for g, n, d3, c3, d2, c2 in cpu_rows:
        print(f"| g = {g} / {n} x {n} | {d3} | {c3:.1f} | {d2} | {c2:.1f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
