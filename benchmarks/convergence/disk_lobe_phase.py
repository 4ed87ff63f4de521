#!/usr/bin/env python3
"""Residual lobe of the disk rolling scene, read two ways, for runs whose die stops at different
positions relative to the mesh (benchmarks/convergence/disk_lobe_phase.sh).

The lobe is the largest residual radial displacement of the rim (last profile_NNNN.csv). It sits
at the leading edge of the last contact footprint, where the rim profile has a kink, so its value
depends on where that edge falls between the nodes. Two readings per run:

  node:  the largest value at the profile points (the face support points of the Q2 element:
         vertices and edge midpoints), as scripts/convergence_study.py reads it;
  face:  the largest value of the quadratic through the three support points of the faces next to
         that point (the Q2 trace of the displacement; the radial displacement of a quadratic
         displacement is quadratic up to terms of order u^2 / R, 1e-5 here).

A face of the ring mesh has its vertices at multiples of its angular length (the coarse ring
starts at 0 degrees), so a profile point at angle a with spacing h is a vertex when a / (2 h) is
an integer. Rotating the die start (Contact/Die 0/Motion/Rolling/Initial line angle) rotates the exact
solution without changing it, so the spread of a level's runs over the die start is a
discretisation error of that level, and their mean is the level's value.

Usage: disk_lobe_phase.py [--csv FILE] RUN_DIR...   (directory names end in L<level>_s<shift>)
"""
import argparse
import csv
import os
import re
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import convergence_study as cs  # noqa: E402


def face_maximum(points, i):
    """Largest value of the quadratic traces of the faces that hold profile point i."""
    n = len(points)
    angle, value = points[i]
    h = min((points[(i + 1) % n][0] - angle) % 360.0, (angle - points[i - 1][0]) % 360.0)
    vertex = abs(angle / (2.0 * h) - round(angle / (2.0 * h))) < 1e-3
    faces = [(i - 2, i - 1, i), (i, i + 1, i + 2)] if vertex else [(i - 1, i, i + 1)]
    best, best_angle = value, angle
    for j0, j1, j2 in faces:
        (a1, u1) = points[j1 % n]
        u0, u2 = points[j0 % n][1], points[j2 % n][1]
        a2 = points[j2 % n][0]
        slope, curvature = 0.5 * (u2 - u0), 0.5 * (u2 + u0) - u1  # u(s) = u1 + slope s + curvature s^2
        if curvature < 0.0:
            s = -slope / (2.0 * curvature)
            if -1.0 <= s <= 1.0 and u1 + slope * s + curvature * s * s > best:
                best = u1 + slope * s + curvature * s * s
                best_angle = a1 + s * ((a2 - a1) % 360.0)
    return best, best_angle, vertex


def read_run(directory):
    rows = list(csv.DictReader(open(os.path.join(directory, "history.csv"))))
    if float(rows[-1]["die_roll_revolution"]) < 360.0 - 1e-9 or float(rows[-1]["die_roll_feed"]) >= 0.0:
        raise RuntimeError(f"{directory}: the run has not finished (revolution {rows[-1]['die_roll_revolution']},"
                           f" feed {rows[-1]['die_roll_feed']}: the die has not retracted)")
    force = cs.history_value(rows, "mean(60,300)", "die_roll_force_magnitude", "die_roll_revolution")
    points = cs.read_profile(directory, dict(file="profile_*.csv", x="angle", y="radial_displacement"), [])
    i = max(range(len(points)), key=lambda k: points[k][1])
    face, face_angle, vertex = face_maximum(points, i)
    m = re.search(r"(?:^|_)L(\d+)_s([0-9.]+)$", os.path.basename(os.path.normpath(directory)))
    if not m:
        raise RuntimeError(f"{directory}: name does not end in L<level>_s<shift>")
    cpu = float("nan")  # user + sys of /usr/bin/time -f "%U %S %e %M" -o DIR.time, if there
    timing = os.path.normpath(directory) + ".time"
    if os.path.exists(timing):
        fields = open(timing).read().split()
        cpu = float(fields[0]) + float(fields[1])
    return dict(level=int(m.group(1)), shift=float(m.group(2)), cpu_s=cpu, F_mean=force,
                lobe_node=points[i][1], node_angle=points[i][0], node_is_vertex=vertex,
                lobe_face=face, face_angle=face_angle, trough=min(u for _, u in points))


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("runs", nargs="+")
    p.add_argument("--csv", help="write the per-run table to this file")
    p.add_argument("--plot", help="draw the lobe against the die start (in rim faces) per level into this PNG")
    args = p.parse_args(argv)
    runs = sorted((read_run(d) for d in args.runs), key=lambda r: (r["level"], r["shift"]))
    print(f"{'level':>5} {'shift':>9} {'CPU s':>7} {'F_mean':>9} {'lobe node':>10} {'at':>8} {'lobe face':>10} {'at':>8} {'trough':>9}")
    for r in runs:
        print(f"{r['level']:5d} {r['shift']:9.5f} {r['cpu_s']:7.1f} {r['F_mean']:9.2f} {r['lobe_node']:10.5f} {r['node_angle']:8.3f}"
              f" {r['lobe_face']:10.5f} {r['face_angle']:8.3f} {r['trough']:9.5f}")
    print("\nper level (mean over the die starts, half the range as the spread):")
    for level in sorted({r["level"] for r in runs}):
        group = [r for r in runs if r["level"] == level]
        for key in ("lobe_node", "lobe_face", "trough", "F_mean"):
            values = [r[key] for r in group]
            mean = statistics.mean(values)
            half = 0.5 * (max(values) - min(values))
            print(f"  level {level} ({len(group)} runs) {key:9s} {mean:10.5f} ± {half:.5f}"
                  f" ({100 * half / abs(mean):.2f} %)")
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(runs[0].keys()))
            w.writeheader()
            w.writerows(runs)
    if args.plot:
        plot(runs, args.plot)
    return 0


def plot(runs, filename):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for level in sorted({r["level"] for r in runs}):
        group = [r for r in runs if r["level"] == level]
        face = 15.0 / 2 ** level  # rim face of the 15-degree coarse ring at this level (degrees)
        x = [r["shift"] / face for r in group]
        ax.plot(x, [r["lobe_node"] for r in group], "o-", label=f"level {level} ({face:g}° faces)")
    ax.set_xlabel("die start rotated by (fraction of a rim face of that level)")
    ax.set_ylabel("residual lobe, largest u_r at the nodes (mm)")
    ax.set_title("prm/disk_rolling.prm, 2304 rolling steps: lobe against where the die stops")
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(filename, dpi=110)


if __name__ == "__main__":
    sys.exit(main())
