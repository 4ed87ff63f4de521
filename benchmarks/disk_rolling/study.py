#!/usr/bin/env python3
"""Disk rolling study (prm/disk_rolling_uniform.prm, NOFEAP thesis section 4.2).

Runs variants of the scene (one full revolution + unloading each) and writes
  * doc/figures/disk_rolling_force.png    die force vs revolution angle, three meshes (15, 7.5,
                                          3.75 degree cells on the rim, as the thesis) and the
                                          load-increment-ratio run on the 7.5 degree mesh
  * doc/figures/disk_rolling_profile.png  rim radial displacement vs angle during rolling and
                                          after unloading (residual "cam"), polar sketch
  * doc/figures/disk_rolling_kinematics.png small vs finite strain (coarse mesh)
  * doc/figures/disk_rolling_work_precision.png wall time vs error: meshes and step sizes
  * CSVs of all curves in <work>/csv/ (force_<run>.csv, residual_<run>.csv); the shipped
    results are copied to benchmarks/disk_rolling/results/
and prints the tables of doc/scenes/disk_rolling.md (markdown).

Runs: coarse / medium / fine mesh with --steps rolling steps (nested active set); the medium mesh
with a quarter and half as many steps; the medium mesh with the load-increment ratio
(--ratio-steps nominal steps, sub-stepped at every status change: the reference for the step-size
error, since friction makes the result path dependent); the coarse mesh with finite strain.

Usage (repository root, after building):
    /usr/bin/python3 benchmarks/disk_rolling/study.py [--ausroll build/ausroll] [--work DIR]
        [--reuse] [--steps 288] [--ratio-steps 72]
--reuse redraws from the outputs of an earlier run. Times: CPU (user + system) and wall seconds of
the ausroll process, one MPI rank, one thread.
"""

import argparse
import csv
import math
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BASE = os.path.join(ROOT, "prm", "disk_rolling_uniform.prm")
ADAPTIVE = os.path.join(ROOT, "prm", "disk_rolling_adaptive.prm")
sys.path.insert(0, os.path.join(ROOT, "benchmarks", "studies"))
from study import pyplot  # noqa: E402  (matplotlib if installed, else None)
sys.path.insert(0, os.path.join(ROOT, "benchmarks"))
from ausroll_run import run_variant  # noqa: E402

# name: (cells around, cells radially, label)
MESHES = {
    "coarse": (24, 2, "15 deg (24 x 2 Q2)"),
    "medium": (48, 4, "7.5 deg (48 x 4 Q2)"),
    "fine": (96, 6, "3.75 deg (96 x 6 Q2)"),
    # prm/disk_rolling_adaptive.prm: the coarse ring refined twice in a band around the die
    "adaptive": (24, 2, "adaptive: 3.75 deg at the die, 15 deg elsewhere"),
}


def timeline(n_roll, feed_steps=4, unload_steps=4, feed=0.762, retract=-0.3):
    """Entries of the feed / one revolution / retract timeline with n_roll rolling steps."""
    t1 = feed_steps
    t2 = feed_steps + n_roll
    t3 = t2 + unload_steps
    return [
        f"Contact/Die 0/Motion/Rolling/Revolution angle = t <= {t1} ? 0 : (t <= {t2} ? "
        f"{360.0 / n_roll} * (t - {t1}) : 360)",
        f"Contact/Die 0/Motion/Rolling/Feed = t <= {t1} ? {feed} * t / {t1} : (t <= {t2} ? {feed} : "
        f"{feed} - {feed - retract} * (t - {t2}) / {unload_steps})",
        f"Loading/End time = {t3}",
        f"Loading/Number of steps = {t3}",
    ]


def mesh_entries(mesh):
    around, radially, _ = MESHES[mesh]
    return [f"Geometry/Ring/Cells around = {around}", f"Geometry/Ring/Cells radially = {radially}"]


def run(args, name, overrides, base=BASE):
    """Run a variant of @p base in <work>/<name> (benchmarks/ausroll_run.py); returns (history
    rows, CPU s, wall s)."""
    os.makedirs(args.work, exist_ok=True)
    result = run_variant(args.ausroll, base, args.work, name, overrides, reuse=args.reuse)
    if result.returncode != 0:
        print(f"  {name}: ausroll exit {result.returncode}: {result.log.strip()[-300:]}")
    rows = result.rows
    print(f"  {name}: {len(rows) - 1} steps, {result.cpu:.1f} s CPU ({result.wall:.1f} s wall), "
          f"{sum(int(r['newton_iterations']) for r in rows)} Newton iterations, "
          f"{sum(int(r['cutbacks']) for r in rows)} cutbacks", flush=True)
    return rows, result.cpu, result.wall


def profiles(args, name):
    """All profile_NNNN.csv of a run: list of (time, angles, radial displacements)."""
    out = os.path.join(args.work, name)
    result = []
    for f in sorted(os.listdir(out)):
        if f.startswith("profile_") and f.endswith(".csv"):
            rows = list(csv.DictReader(open(os.path.join(out, f))))
            if rows:
                result.append((float(rows[0]["time"]), [float(r["angle"]) for r in rows],
                               [float(r["radial_displacement"]) for r in rows]))
    return result


def periodic_interp(xs, ys, x):
    """Linear interpolation of a curve sampled on [0, 360) with period 360."""
    n = len(xs)
    for i in range(n):
        a, b = xs[i], xs[(i + 1) % n] + (360.0 if i + 1 == n else 0.0)
        xx = x if x >= xs[0] else x + 360.0
        if a <= xx <= b:
            t = (xx - a) / (b - a) if b > a else 0.0
            return ys[i] + t * (ys[(i + 1) % n] - ys[i])
    return ys[-1]


def rolling_rows(rows):
    """History rows of the rolling phase (revolution strictly between 0 and 360)."""
    return [r for r in rows if 0.0 < float(r["die_roll_revolution"]) < 360.0 - 1e-9]


def force_stats(rows):
    """Mean and relative spread of |F| over 60..300 degrees of steady rolling."""
    f = [float(r["die_roll_force_magnitude"]) for r in rows
         if 60.0 <= float(r["die_roll_revolution"]) <= 300.0]
    mean = sum(f) / len(f)
    return mean, (max(f) - min(f)) / mean


def write_csvs(args, name, rows, prof):
    d = os.path.join(args.work, "csv")
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, f"force_{name}.csv"), "w") as f:
        f.write("revolution_deg,feed_mm,force_magnitude,force_radial,force_tangential,"
                "force_x,force_y\n")
        for r in rows:
            f.write(",".join(r[c] for c in (
                "die_roll_revolution", "die_roll_feed", "die_roll_force_magnitude",
                "die_roll_force_radial", "die_roll_force_tangential", "die_roll_force_x",
                "die_roll_force_y")) + "\n")
    if float(rows[-1]["die_roll_feed"]) >= 0.0:  # no unloading (the fine mesh): no residual
        return
    t, ang, ur = prof[-1]
    with open(os.path.join(d, f"residual_{name}.csv"), "w") as f:
        f.write("angle_deg,radial_displacement_mm\n")
        for a, u in zip(ang, ur):
            f.write(f"{a},{u}\n")


def nearest_profile(prof, rows, angle):
    """Profile written closest to die revolution @p angle during full feed."""
    best, dist = None, 1e30
    by_time = {round(float(r["time"]), 9): r for r in rows}
    for p in prof:
        r = by_time.get(round(p[0], 9))
        if r is None or float(r["die_roll_feed"]) < 0.76:
            continue
        d = abs(float(r["die_roll_revolution"]) - angle)
        if d < dist:
            best, dist = (p, float(r["die_roll_revolution"])), d
    return best


def window_mean(rows, lo, hi):
    f = [float(r["die_roll_force_magnitude"]) for r in rows
         if lo <= float(r["die_roll_revolution"]) <= hi and float(r["die_roll_feed"]) > 0.76]
    return sum(f) / len(f)


def grid_mean(rows, lo, hi, grid):
    """Mean |F| over the history rows at full feed whose revolution lies in [lo, hi] on a grid of
    @p grid degrees (the nominal steps: the load-increment ratio adds sub-steps at its events,
    which would weight the mean unevenly)."""
    f = [float(r["die_roll_force_magnitude"]) for r in rows
         if lo <= float(r["die_roll_revolution"]) <= hi and float(r["die_roll_feed"]) > 0.76
         and abs(float(r["die_roll_revolution"]) / grid - round(float(r["die_roll_revolution"]) / grid)) < 1e-6]
    return sum(f) / len(f)


def residual_error(prof_a, prof_ref):
    """Max difference of two residual rims, relative to the largest |u_r| of the reference."""
    t, ang, ur = prof_ref[-1]
    ta, anga, ura = prof_a[-1]
    return max(abs(periodic_interp(anga, ura, a) - u) for a, u in zip(ang, ur)) / max(abs(u) for u in ur)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--ausroll", default=os.path.join(ROOT, "build", "ausroll"))
    parser.add_argument("--work", default="/tmp/ausroll_disk_rolling_study")
    parser.add_argument("--reuse", action="store_true")
    parser.add_argument("--steps", type=int, default=288, help="rolling steps per revolution")
    parser.add_argument("--ratio-steps", type=int, default=72,
                        help="nominal steps of the load-increment-ratio reference (it sub-steps "
                             "at every status change)")
    args = parser.parse_args()
    args.work = os.path.abspath(args.work)
    figures = os.path.join(ROOT, "doc", "figures")
    n = args.steps
    nested = ["Contact/Strategy = nested active set"]

    runs = {}
    for m in ("coarse", "medium", "fine"):
        runs[m] = run(args, m, mesh_entries(m) + timeline(n) + nested)
    runs["adaptive"] = run(args, "adaptive", timeline(n) + nested + ["Output/Write VTU = false"],
                           base=ADAPTIVE)
    step_study = [s for s in (n // 4, n // 2) if s >= 36]
    for s in step_study:
        runs[f"medium_s{s}"] = run(args, f"medium_s{s}", mesh_entries("medium") + timeline(s) + nested)
    runs["medium_ratio"] = run(args, "medium_ratio", mesh_entries("medium") + timeline(args.ratio_steps)
                               + ["Contact/Strategy = load increment ratio",
                                  "Loading/Predictor = none"])
    runs["coarse_finite"] = run(args, "coarse_finite", mesh_entries("coarse") + timeline(n) + nested
                                + ["Model/Kinematics = finite strain"])
    prof = {m: profiles(args, m) for m in runs}
    for m in runs:
        write_csvs(args, m, runs[m][0], prof[m])

    grid = 360.0 / math.gcd(n, args.ratio_steps, *step_study)  # common angles of all runs
    lo, hi = 60.0, 300.0
    ref = grid_mean(runs["fine"][0], lo, hi, grid)
    print(f"\nMesh sequence ({360.0 / n:g} degree steps, nested active set). Error: mean |F| over "
          f"{lo:.0f}-{hi:.0f} deg (every {grid:g} deg) and residual rim vs the fine mesh.\n")
    print("| mesh | cells | DoFs | steps | Newton iterations | CPU s | wall s | mean \\|F\\| "
          f"{lo:.0f}-{hi:.0f} deg (N/mm) | error | spread | residual rim error |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    table = {}
    for m in ("coarse", "medium", "fine", "adaptive", "coarse_finite"):
        rows, cpu, wall = runs[m]
        mean = grid_mean(rows, lo, hi, grid)
        spread = force_stats(rows)[1]
        err_u = residual_error(prof[m], prof["fine"]) if m != "fine" else 0.0
        table[m] = (cpu, abs(mean - ref) / ref, err_u)
        print(f"| {m} ({MESHES[m.split('_')[0]][2]}) | {rows[-1]['cells']} | "
              f"{max(int(r['dofs']) for r in rows)} | "
              f"{len(rows) - 1} | {sum(int(r['newton_iterations']) for r in rows)} | {cpu:.1f} | "
              f"{wall:.1f} | {mean:.0f} | {(mean - ref) / ref:+.1%} | {spread:.0%} | {err_u:.0%} |")

    ratio = grid_mean(runs["medium_ratio"][0], lo, hi, grid)
    print(f"\nStep size (medium mesh). Error: mean |F| over {lo:.0f}-{hi:.0f} deg against the "
          f"load-increment ratio (statuses resolved at every event).\n")
    print("| strategy | rolling steps | steps incl. sub-steps | Newton iterations | CPU s | wall s | "
          "mean \\|F\\| (N/mm) | vs ratio | residual rim vs ratio |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for name, label, s in ([(f"medium_s{s}", "nested active set", s) for s in step_study]
                           + [("medium", "nested active set", n),
                              ("medium_ratio", "load increment ratio", args.ratio_steps)]):
        rows, cpu, wall = runs[name]
        mean = grid_mean(rows, lo, hi, grid)
        err_u = residual_error(prof[name], prof["medium_ratio"]) if name != "medium_ratio" else 0.0
        print(f"| {label} | {s} ({360.0 / s:g} deg) | {len(rows) - 1} | "
              f"{sum(int(r['newton_iterations']) for r in rows)} | {cpu:.1f} | {wall:.1f} | "
              f"{mean:.0f} | {(mean - ratio) / ratio:+.1%} | {err_u:.0%} |")

    for m in ("coarse", "medium", "fine", "adaptive"):
        ang, ur = prof[m][-1][1], prof[m][-1][2]
        i_min = min(range(len(ur)), key=lambda i: ur[i])
        i_max = max(range(len(ur)), key=lambda i: ur[i])
        print(f"\nResidual rim ({m}): deepest {ur[i_min] * 1000:.1f} um at {ang[i_min]:.1f} deg, "
              f"highest {ur[i_max] * 1000:.1f} um at {ang[i_max]:.1f} deg; mean "
              f"{1000 * sum(ur) / len(ur):.1f} um")
    ps, pf = prof["coarse"][-1], prof["coarse_finite"][-1]
    du = max(abs(periodic_interp(ps[1], ps[2], a) - u) for a, u in zip(pf[1], pf[2]))
    ms, mf = force_stats(runs["coarse"][0])[0], force_stats(runs["coarse_finite"][0])[0]
    print(f"\nSmall vs finite strain (coarse): mean |F| 60-300 deg {ms:.0f} vs {mf:.0f} N/mm "
          f"({(ms - mf) / mf:+.2%}); residual rim max difference {du * 1000:.2f} um "
          f"({du / max(abs(u) for u in pf[2]):.1%} of max |u_r|)")

    plt = pyplot()
    if plt is None:
        return 0
    os.makedirs(figures, exist_ok=True)
    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    for m in ("coarse", "medium", "fine"):
        rows = rolling_rows(runs[m][0])
        x = [float(r["die_roll_revolution"]) for r in rows]
        ax[0].plot(x, [float(r["die_roll_force_magnitude"]) for r in rows], lw=0.8,
                   label=MESHES[m][2])
        if m != "coarse":
            ax[1].plot(x, [-float(r["die_roll_force_radial"]) for r in rows], lw=0.8,
                       label=f"{m}: -F_r")
            ax[1].plot(x, [float(r["die_roll_force_tangential"]) for r in rows], lw=0.8,
                       label=f"{m}: F_t")
    rows = rolling_rows(runs["medium_ratio"][0])
    ax[0].plot([float(r["die_roll_revolution"]) for r in rows],
               [float(r["die_roll_force_magnitude"]) for r in rows], "k:", lw=0.8,
               label="7.5 deg, load increment ratio")
    ax[0].set_xlabel("die revolution angle (deg)")
    ax[0].set_ylabel("|F| on the disk (N per mm thickness)")
    ax[0].set_title("die force vs rolling angle")
    ax[0].legend(fontsize=8)
    ax[1].set_xlabel("die revolution angle (deg)")
    ax[1].set_ylabel("N/mm")
    ax[1].set_title("radial (pressing) and tangential components")
    ax[1].legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(figures, "disk_rolling_force.png"), dpi=110)
    plt.close(fig)

    fig = plt.figure(figsize=(12, 4.5))
    ax = fig.add_subplot(1, 2, 1)
    for angle in (90.0, 180.0, 270.0, 355.0):
        found = nearest_profile(prof["medium"], runs["medium"][0], angle)
        if found:
            (t, ang, ur), rev = found
            ax.plot(ang, [1000 * u for u in ur], lw=0.8, label=f"rolling, die revolved {rev:.0f} deg (at {(90 + rev) % 360:.0f} deg)")
    for m, style in (("fine", "r-"), ("medium", "k-"), ("coarse", "k:")):
        t, ang, ur = prof[m][-1]
        ax.plot(ang, [1000 * u for u in ur], style, lw=1.6,
                label=f"after unloading, {MESHES[m][2]}")
    ax.set_xlabel("polar angle on the rim (deg)")
    ax.set_ylabel("radial displacement of the rim (um)")
    ax.set_title("rim profile (die starts at 90 deg, revolves counter-clockwise)")
    ax.legend(fontsize=7)
    ax2 = fig.add_subplot(1, 2, 2, projection="polar")
    t, ang, ur = prof["fine"][-1]
    u_scale = max(abs(u) for u in ur)
    th = [math.radians(a) for a in ang] + [math.radians(ang[0])]
    R = 43.55
    mag = 0.3 * R / max(u_scale, 1e-12)
    ax2.plot(th, [R] * len(th), "k-", lw=1, label="undeformed")
    ax2.plot(th, [R + mag * u for u in ur + [ur[0]]], "r-", lw=1.5,
             label=f"residual (3.75 deg mesh) x{mag:.0f}")
    ax2.set_rlim(0, 1.4 * R)
    ax2.set_title("residual rim shape, magnified")
    ax2.legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    fig.savefig(os.path.join(figures, "disk_rolling_profile.png"), dpi=110)
    plt.close(fig)

    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    for m, label in (("coarse", "small strain"), ("coarse_finite", "finite strain")):
        rr = rolling_rows(runs[m][0])
        ax[0].plot([float(r["die_roll_revolution"]) for r in rr],
                   [float(r["die_roll_force_magnitude"]) for r in rr], lw=0.8, label=label)
        ax[1].plot(prof[m][-1][1], [1000 * u for u in prof[m][-1][2]], label=label)
    ax[0].set_xlabel("die revolution angle (deg)")
    ax[0].set_ylabel("|F| (N/mm)")
    ax[0].legend()
    ax[1].set_xlabel("polar angle (deg)")
    ax[1].set_ylabel("residual radial displacement (um)")
    ax[1].legend()
    fig.suptitle("small vs finite strain, coarse mesh (24 x 2 Q2)")
    fig.tight_layout()
    fig.savefig(os.path.join(figures, "disk_rolling_kinematics.png"), dpi=110)
    plt.close(fig)

    # time vs error: meshes (error vs the fine mesh) and step sizes (error vs the ratio). CPU time
    # of the one-rank run (the wall time equals it on an idle core; the machine was shared).
    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    for m, color in (("coarse", "C0"), ("medium", "C1"), ("adaptive", "C2")):
        cpu, err_f, err_u = table[m]
        ax[0].loglog([cpu], [max(err_f, 1e-4)], "o", color=color, label=f"{MESHES[m][2]}: mean |F|")
        ax[0].loglog([cpu], [max(err_u, 1e-4)], "s", color=color, mfc="none",
                     label=f"{MESHES[m][2]}: residual rim")
    ax[0].axvline(60.0, color="gray", ls="--", lw=0.8)
    ax[0].axvline(runs["fine"][1], color="k", ls=":", lw=0.8)
    ax[0].annotate("3.75 deg mesh (reference)", (runs["fine"][1], 0.5), rotation=90, fontsize=7,
                   ha="right")
    ax[0].annotate("60 s", (60.0, 0.5), rotation=90, fontsize=7, ha="right")
    ax[0].set_xlim(2, 400)
    ax[0].set_xlabel("CPU time of the 360 deg run, one core (s)")
    ax[0].set_ylabel("error vs the 3.75 deg mesh")
    ax[0].set_title(f"mesh ({360.0 / n:g} deg steps, nested active set)")
    ax[0].legend(fontsize=6)
    xs, es = [], []
    for s in step_study + [n]:
        name = f"medium_s{s}" if s != n else "medium"
        rows, cpu, wall = runs[name]
        xs.append(cpu)
        es.append(abs(grid_mean(rows, lo, hi, grid) - ratio) / ratio)
        ax[1].annotate(f"{360.0 / s:g} deg steps", (xs[-1], es[-1]), fontsize=7)
    ax[1].loglog(xs, es, "o-", label="nested active set")
    ax[1].axvline(runs["medium_ratio"][1], color="k", ls=":", lw=0.8)
    ax[1].annotate("load increment ratio (reference)", (runs["medium_ratio"][1], 0.02),
                   rotation=90, fontsize=7, ha="right")
    ax[1].axvline(60.0, color="gray", ls="--", lw=0.8)
    ax[1].set_xlim(10, 400)
    ax[1].set_xlabel("CPU time of the 360 deg run, one core (s)")
    ax[1].set_ylabel("error of mean |F| vs the ratio strategy")
    ax[1].set_title("step size, 7.5 deg mesh")
    ax[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(figures, "disk_rolling_work_precision.png"), dpi=110)
    plt.close(fig)
    return 0


if __name__ == "__main__":
    sys.exit(main())
