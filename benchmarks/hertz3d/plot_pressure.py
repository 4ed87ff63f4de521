#!/usr/bin/env python3
"""Plot the nodal contact pressures of a 3D Hertz run against the Hertz distribution.

Usage: plot_pressure.py RUN_DIRECTORY OUTPUT.png  (a run of tests/checks/scenes/hertz3d.prm:
sphere R = 50 mm, E = 210 GPa, nu = 0.3, quarter model). Dots: p_n of the closed nodes against
r = sqrt(X^2 + Z^2); lines: Hertz p0 sqrt(1 - r^2 / a^2) at the measured force (4 |F_y|).
"""

import csv
import glob
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests", "checks"))
from check_hertz import closed_nodes  # noqa: E402
from check_hertz_3d import hertz_at_force  # noqa: E402

RADIUS, E_STAR = 50.0, 210000 / (1 - 0.3 ** 2)


def main():
    run, png = sys.argv[1], sys.argv[2]
    with open(os.path.join(run, "history.csv")) as h:
        history = {float(r["time"]): r for r in csv.DictReader(h)}
    fig, ax = plt.subplots(figsize=(6, 4))
    for f in sorted(glob.glob(os.path.join(run, "contact_*.csv"))):
        lines = open(f).read().splitlines()
        t = float(lines[0].split("=")[1].split(";")[0])
        rows = closed_nodes(lines)
        F = -4 * float(history[min(history, key=lambda s: abs(s - t))]["die_sphere_force_y"])
        if not rows or F <= 0:
            continue
        a, p0 = hertz_at_force(F, RADIUS, E_STAR)
        r = [math.hypot(float(q["X"]), float(q["Z"])) for q in rows]
        line, = ax.plot(r, [float(q["p_n"]) for q in rows], "o", ms=3,
                        label=f"t = {t:g}: F = {F:.0f} N")
        xs = [a * k / 200 for k in range(201)]
        ax.plot(xs, [p0 * math.sqrt(max(0.0, 1 - (x / a) ** 2)) for x in xs], "-",
                color=line.get_color(), lw=1)
    ax.set_xlabel("r = sqrt(x² + z²) (mm)")
    ax.set_ylabel("contact pressure p_n (MPa)")
    ax.set_title("3D Hertz: nodal pressures (dots) and Hertz at the measured force (lines)")
    ax.title.set_fontsize(9)
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


if __name__ == "__main__":
    main()
