#!/usr/bin/env python3
"""Parameter studies of the large-deformation scenes (cantilever, upsetting, head forming, flat
punch): run variants of a shipped .prm, collect history.csv, print tables and draw the figures of
doc/figures/ (matplotlib, optional). Not a test: the checks in tests/checks assert the numbers.

Usage (from the repository root, after building):
    python3 benchmarks/studies/study.py cantilever   [--ausroll build/ausroll] [--work /tmp/x]
    python3 benchmarks/studies/study.py upsetting
    python3 benchmarks/studies/study.py head_forming
    python3 benchmarks/studies/study.py flat_punch
Figures go to doc/figures/, tables to stdout (pasted into doc/scenes/*.md). --reuse redraws from
the histories of an earlier run. Figures need matplotlib (Debian: python3-matplotlib, use
/usr/bin/python3).
"""

import argparse
import csv
import math
import os
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def run(args, base, name, overrides):
    """Run a variant of prm/<base>.prm in args.work/<name>; returns (rows, seconds)."""
    os.makedirs(args.work, exist_ok=True)
    prm_dir = os.path.join(ROOT, "prm")
    prm = os.path.join(args.work, f"{name}.prm")
    out = os.path.join(args.work, name)
    history = os.path.join(out, "history.csv")
    if args.reuse and os.path.exists(history):
        rows = list(csv.DictReader(open(history)))
        seconds = float(rows[-1]["wall_seconds"]) if rows else 0.0
        print(f"  {name}: reused {len(rows) - 1} steps ({seconds:.1f} s)")
        return rows, seconds
    subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "prm_variant.py"),
                    os.path.join(prm_dir, f"{base}.prm"), prm, f"Output/Directory = {out}",
                    "Output/Write VTU = false", "Output/Verbosity = quiet"] + overrides,
                   check=True)
    # files named relative to the .prm (meshes) are looked up next to it
    for f in os.listdir(prm_dir):
        if f.endswith(".msh"):
            shutil.copy(os.path.join(prm_dir, f), args.work)
    start = time.time()
    result = subprocess.run([args.ausroll, prm, "--overwrite"], capture_output=True, text=True)
    seconds = time.time() - start
    with open(os.path.join(out, "run.log"), "w") as log:
        log.write(result.stdout + result.stderr)
    if result.returncode != 0:
        print(f"  {name}: ausroll exit {result.returncode}: {result.stderr.strip()[-300:]}")
    path = os.path.join(out, "history.csv")
    rows = list(csv.DictReader(open(path))) if os.path.exists(path) else []
    print(f"  {name}: {len(rows) - 1} steps, {seconds:.1f} s, "
          f"{sum(int(r['newton_iterations']) for r in rows)} Newton iterations, "
          f"{sum(int(r['cutbacks']) for r in rows)} cutbacks")
    return rows, seconds


def column(rows, name, scale=1.0):
    return [scale * float(r[name]) for r in rows]


def pyplot():
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        return plt
    except ImportError:
        print("  (matplotlib not installed: no figure)")
        return None


def interpolate(xs, ys, x):
    for i in range(1, len(xs)):
        if xs[i] >= x - 1e-12:
            t = (x - xs[i - 1]) / (xs[i] - xs[i - 1]) if xs[i] != xs[i - 1] else 1.0
            return ys[i - 1] + t * (ys[i] - ys[i - 1])
    return ys[-1]


# ---------------------------------------------------------------------------------- cantilever
def cantilever(args):
    sys.path.insert(0, os.path.join(ROOT, "benchmarks", "reference"))
    import elastica
    L = 254.0
    nu, lh = 0.2, 10.0
    kappa = 10 * (1 + nu) / (12 + 11 * nu)
    beam = (12 * lh ** 2, 12 * kappa * lh ** 2 / (2 * (1 + nu)))
    dead = {}
    pred = ["Loading/Predictor = linear extrapolation"]
    for kin in ("total Lagrangian", "updated Lagrangian", "finite strain", "small strain"):
        dead[kin] = run(args, "cantilever", "dead_" + kin.replace(" ", "_"),
                        [f"Model/Kinematics = {kin}"] + pred)[0]
    five = run(args, "cantilever", "dead_TL_5", ["Model/Kinematics = total Lagrangian",
                                                 "Loading/Number of steps = 5"])[0]
    follower = ["Boundary conditions/Condition 1/Type = pressure",
                "Boundary conditions/Condition 1/Value = 6.895e-4 * t",
                "Boundary conditions/Condition 2/Type = pressure",
                "Boundary conditions/Condition 2/Value = -6.895e-4 * t"]
    fol = {}
    for kin in ("total Lagrangian", "updated Lagrangian", "finite strain"):
        fol[kin] = run(args, "cantilever", "follower_" + kin.replace(" ", "_"),
                       [f"Model/Kinematics = {kin}"] + follower + pred)[0]

    print("\n| k | elastica | Reissner | TL | UL | finite strain | TL 5 incr. | linear | "
          "TL vs UL | TL vs elastica | TL vs Reissner |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    ks = [1, 2, 4, 5, 8, 10, 12, 16, 20]
    for k in ks:
        t = round(k / 0.2, 6)
        el = elastica.solve(k, False, 1000)
        rb = elastica.solve(k, False, 1000, el[0], beam)
        w = {kin: -float(next(r for r in rows if abs(float(r["time"]) - t) < 1e-6)["tip_uy"])
             for kin, rows in dead.items()}
        w5 = next((-float(r["tip_uy"]) for r in five if abs(float(r["time"]) - t) < 1e-6), None)
        print(f"| {k} | {-el[2] * L:.2f} | {-rb[2] * L:.2f} | {w['total Lagrangian']:.2f} | "
              f"{w['updated Lagrangian']:.2f} | {w['finite strain']:.2f} | "
              f"{'' if w5 is None else f'{w5:.2f}'} | {w['small strain']:.2f} | "
              f"{(w['total Lagrangian'] - w['updated Lagrangian']) / w['total Lagrangian']:+.2%} | "
              f"{(w['total Lagrangian'] + el[2] * L) / (-el[2] * L):+.2%} | "
              f"{(w['total Lagrangian'] + rb[2] * L) / (-rb[2] * L):+.2%} |")
    print("\nfollower pressure:\n| k | elastica (follower) | Reissner (follower) | TL | UL | "
          "finite strain |")
    print("|---:|---:|---:|---:|---:|---:|")
    for k in ks:
        t = round(k / 0.2, 6)
        el = elastica.solve(k, True, 1000)
        rb = elastica.solve(k, True, 1000, el[0], beam)
        w = {kin: -float(next(r for r in rows if abs(float(r["time"]) - t) < 1e-6)["tip_uy"])
             for kin, rows in fol.items()}
        print(f"| {k} | {-el[2] * L:.2f} | {-rb[2] * L:.2f} | {w['total Lagrangian']:.2f} | "
              f"{w['updated Lagrangian']:.2f} | {w['finite strain']:.2f} |")

    plt = pyplot()
    if plt is None:
        return
    kk = [20 * i / 100 for i in range(101)]
    el_dead = [0.0]
    el_fol = [0.0]
    g1 = g2 = None
    for k in kk[1:]:
        a = elastica.solve(k, False, 500, g1)
        b = elastica.solve(k, True, 500, g2)
        g1, g2 = a[0], b[0]
        el_dead.append(-a[2] * L)
        el_fol.append(-b[2] * L)
    fig, ax = plt.subplots(figsize=(7, 5))
    ax.plot(kk, el_dead, "k-", lw=2.5, alpha=0.4, label="elastica, dead load")
    ax.plot(kk, el_fol, "k--", lw=2.5, alpha=0.4, label="elastica, follower load")
    styles = {"total Lagrangian": "C0", "updated Lagrangian": "C1", "finite strain": "C2"}
    for kin, rows in dead.items():
        if kin == "small strain":
            ax.plot([0.2 * t for t in column(rows, "time")], column(rows, "tip_uy", -1), "C7:",
                    label="linear (small strain)")
        else:
            ax.plot([0.2 * t for t in column(rows, "time")], column(rows, "tip_uy", -1),
                    styles[kin], label=f"{kin}, dead")
    for kin, rows in fol.items():
        ax.plot([0.2 * t for t in column(rows, "time")], column(rows, "tip_uy", -1),
                styles[kin], ls="--", label=f"{kin}, follower")
    ax.plot([0.2 * t for t in column(five, "time")], column(five, "tip_uy", -1), "C3o",
            label="total Lagrangian, 5 increments")
    ax.set_xlim(0, 20)
    ax.set_ylim(0, 260)
    ax.set_xlabel("k = q L^3 / EI  (q = 2 p b, p = 689.5 Pa per increment)")
    ax.set_ylabel("tip deflection -u_y (mm)")
    ax.set_title("Cantilever L = 254 mm, 25.4 x 25.4 mm, E = 82.74 MPa, nu = 0.2")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "doc", "figures", "cantilever_tip_deflection.png"), dpi=110)
    print("  wrote doc/figures/cantilever_tip_deflection.png")


# ---------------------------------------------------------------------------------- upsetting
def upsetting(args):
    def force(rows):
        return column(rows, "die_platen_force_y", -1e-3)  # kN, compression positive

    runs = {}
    runs["Q2 8x6, 0.25 %"] = run(args, "upsetting", "q2_8x6_025", [])
    runs["Q2 8x6, 0.5 %"] = run(args, "upsetting", "q2_8x6_050", ["Loading/Number of steps = 60"])
    runs["Q2 4x3, 0.25 %"] = run(args, "upsetting", "q2_4x3_025",
                                 ["Geometry/Rectangle/Cells = 4, 3"])
    runs["Q2 16x12, 0.25 %"] = run(args, "upsetting", "q2_16x12_025",
                                   ["Geometry/Rectangle/Cells = 16, 12"])
    runs["Q1 F-bar 16x12, 0.25 %"] = run(args, "upsetting", "q1_16x12_025",
                                         ["Geometry/Rectangle/Cells = 16, 12",
                                          "Model/Polynomial degree = 1"])
    runs["Q1 F-bar 32x24, 0.25 %"] = run(args, "upsetting", "q1_32x24_025",
                                         ["Geometry/Rectangle/Cells = 32, 24",
                                          "Model/Polynomial degree = 1"])
    runs["small strain, Q2 8x6"] = run(args, "upsetting", "small_strain",
                                       ["Model/Kinematics = small strain"])
    runs["updated Lagrangian, Q2 8x6"] = run(args, "upsetting", "ul",
                                             ["Model/Kinematics = updated Lagrangian"])
    runs["Q2 8x6, no F-bar"] = run(args, "upsetting", "q2_nofbar",
                                   ["Model/Volumetric locking treatment = none"])

    ref = runs["Q2 16x12, 0.25 %"][0]
    xr, fr = column(ref, "time"), force(ref)
    print("\n| variant | force at 10 % (kN) | at 20 % | at 30 % | bulge radius at 30 % (mm) | "
          "max dev. from Q2 16x12 (10-30 %) | wall time (s) | Newton its | cutbacks |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for label, (rows, seconds) in runs.items():
        if len(rows) < 2:
            print(f"| {label} | failed | | | | | {seconds:.0f} | | |")
            continue
        x, f = column(rows, "time"), force(rows)
        dev = max(abs(fi - interpolate(xr, fr, xi)) / interpolate(xr, fr, xi)
                  for xi, fi in zip(x, f) if xi >= 10 - 1e-9)
        at = [interpolate(x, f, v) for v in (10, 20, 30)]
        bulge = 20 + float(rows[-1]["equator_ux"])
        print(f"| {label} | {at[0]:.1f} | {at[1]:.1f} | {at[2]:.1f} | {bulge:.3f} | {dev:.2%} | "
              f"{seconds:.0f} | {sum(int(r['newton_iterations']) for r in rows)} | "
              f"{sum(int(r['cutbacks']) for r in rows)} |")
    a, b = runs["Q2 8x6, 0.25 %"][0], runs["Q2 8x6, 0.5 %"][0]
    xa, fa = column(a, "time"), force(a)
    dev = max(abs(interpolate(xa, fa, float(r["time"])) + 1e-3 * float(r["die_platen_force_y"]))
              / interpolate(xa, fa, float(r["time"])) for r in b[1:] if float(r["time"]) >= 1)
    print(f"\nstep size: max |F(0.5 %) - F(0.25 %)| / F(0.25 %) over 1-30 %: {dev:.3%}")

    plt = pyplot()
    if plt is None:
        return
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.5))
    for label, (rows, _) in runs.items():
        if len(rows) < 2:
            continue
        ls = "--" if "0.5" in label else "-"
        ax1.plot(column(rows, "time"), force(rows), ls=ls, label=label)
        ax2.plot(column(rows, "time"), [20 + u for u in column(rows, "equator_ux")], ls=ls,
                 label=label)
    ax1.set_xlabel("height reduction (%)")
    ax1.set_ylabel("platen force (kN, full 2 pi)")
    ax2.set_xlabel("height reduction (%)")
    ax2.set_ylabel("bulge radius at the equator (mm)")
    for ax in (ax1, ax2):
        ax.grid(alpha=0.3)
    ax1.legend(fontsize=7)
    fig.suptitle("Upsetting, R = 20 mm, H = 30 mm, sticking platen, E = 200 GPa, "
                 "sigma_y = 700 MPa, H' = 300 MPa")
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "doc", "figures", "upsetting.png"), dpi=110)
    print("  wrote doc/figures/upsetting.png")


# ---------------------------------------------------------------------------------- head forming
def head_forming(args):
    runs = {}
    runs["frictionless"] = run(args, "head_forming", "frictionless",
                               ["Contact/Die 0/Friction = frictionless",
                                "Contact/Die 1/Friction = frictionless"])
    runs["no-slip top"] = run(args, "head_forming", "no_slip", [])
    print("\n| case | punch force at 10 % (kN) | 20 % | 30 % | 40 % | shoulder force at 40 % "
          "(kN) | first shoulder contact (%) | wall time (s) |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for label, (rows, seconds) in runs.items():
        if len(rows) < 2:
            print(f"| {label} | failed | | | | | | {seconds:.0f} |")
            continue
        x = column(rows, "time")
        f = column(rows, "die_punch_force_y", -1e-3)
        s = column(rows, "die_shoulder_force_y", 1e-3)
        first = next((xi for xi, r in zip(x, rows)
                      if int(r["die_shoulder_stick_nodes"]) + int(r["die_shoulder_slip_nodes"])
                      > 0), float("nan"))
        at = [interpolate(x, f, v) for v in (10, 20, 30, 40)]
        print(f"| {label} | {at[0]:.1f} | {at[1]:.1f} | {at[2]:.1f} | {at[3]:.1f} | "
              f"{s[-1]:.1f} | {first:.2f} | {seconds:.0f} |")
    plt = pyplot()
    if plt is None:
        return
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.5))
    for label, (rows, _) in runs.items():
        if len(rows) < 2:
            continue
        x = column(rows, "time")
        ax1.plot(x, column(rows, "die_punch_force_y", -1e-3), label=label)
        ax2.plot(x, column(rows, "die_shoulder_force_y", 1e-3), label=f"{label}: normal (y)")
        ax2.plot(x, column(rows, "die_shoulder_force_x", 1e-3), ls="--",
                 label=f"{label}: tangential (x)")
    ax1.set_xlabel("height reduction (% of the initial height)")
    ax1.set_ylabel("punch force (kN, full 2 pi)")
    ax2.set_xlabel("height reduction (%)")
    ax2.set_ylabel("force of the shoulder on the workpiece (kN)")
    for ax in (ax1, ax2):
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Head forming: load-deflection and shoulder contact forces")
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "doc", "figures", "head_forming.png"), dpi=110)
    print("  wrote doc/figures/head_forming.png")


# ---------------------------------------------------------------------------------- flat punch
def flat_punch(args):
    p_lim = (2 + math.pi) * 200 / math.sqrt(3)
    meshes = [("0.05", "1.15"), ("0.025", "1.1"), ("0.0125", "1.08")]
    results = {}
    for h, g in meshes:
        mesh = os.path.join(args.work, f"punch_{h}.msh")
        os.makedirs(args.work, exist_ok=True)
        subprocess.run([sys.executable, os.path.join(ROOT, "prm", "flat_punch_mesh.py"), mesh,
                        "--h", h, "--growth", g], check=True, stdout=subprocess.DEVNULL)
        for label, over in (("Q1 full", ["Model/Volumetric locking treatment = none"]),
                            ("Q1 F-bar", []),
                            ("Q2 full", ["Model/Polynomial degree = 2",
                                         "Model/Volumetric locking treatment = none"]),
                            ("Q2 F-bar", ["Model/Polynomial degree = 2"])):
            if label.startswith("Q2") and h == "0.0125":
                continue
            rows, sec = run(args, "flat_punch", f"{label.replace(' ', '_')}_{h}",
                            [f"Geometry/Mesh file = {mesh}"] + over)
            results[(label, h)] = (rows, sec)
    print("\n| element | smallest cell (mm) | p / p_lim at 0.03 mm | at 0.06 mm | wall time (s) |")
    print("|---|---:|---:|---:|---:|")
    for (label, h), (rows, sec) in results.items():
        x, p = column(rows, "time"), column(rows, "reaction_4_y", -1.0)
        print(f"| {label} | {h} | {interpolate(x, p, 0.03) / p_lim:.4f} | "
              f"{p[-1] / p_lim:.4f} | {sec:.1f} |")
    plt = pyplot()
    if plt is None:
        return
    fig, ax = plt.subplots(figsize=(7, 5))
    for (label, h), (rows, _) in results.items():
        ax.plot(column(rows, "time"), [v / p_lim for v in column(rows, "reaction_4_y", -1.0)],
                label=f"{label}, h = {h}")
    ax.axhline(1.0, color="k", lw=1)
    ax.set_xlabel("punch displacement (mm), b = 1 mm")
    ax.set_ylabel("mean punch pressure / (2 + pi) k")
    ax.set_title("Rough flat punch, plane strain, small strain, perfectly plastic")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "doc", "figures", "flat_punch.png"), dpi=110)
    print("  wrote doc/figures/flat_punch.png")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("study", choices=["cantilever", "upsetting", "head_forming", "flat_punch"])
    ap.add_argument("--ausroll", default=os.path.join(ROOT, "build", "ausroll"))
    ap.add_argument("--work", default=None)
    ap.add_argument("--reuse", action="store_true",
                    help="reuse the histories of an earlier run in the work directory")
    args = ap.parse_args()
    args.work = os.path.abspath(args.work or f"/tmp/ausroll_study_{args.study}")
    os.makedirs(os.path.join(ROOT, "doc", "figures"), exist_ok=True)
    print(f"{args.study}: runs in {args.work}")
    globals()[args.study](args)
    return 0


if __name__ == "__main__":
    sys.exit(main())
