#!/usr/bin/python3
"""3D disk rolling study (doc/scenes/disk_rolling_3d.md): runs prm/disk_rolling_3d_round.prm,
prm/disk_rolling_3d_flat.prm and the 2D plane-strain reference with the same section mesh
(tests/checks/scenes/disk_rolling_short.prm on the 48 x 2 Q2 ring, the time line of the round
scene: feed in 4 steps, 40 degrees in 1.25 degree steps, unloading in 4 steps, no predictor; the
flat scene rolls 10 degrees), then writes

  WORK/results.csv          per monitor angle: indentation depth (-u_r at mid-thickness) and
                            lateral spread (u_z of the side-face edge), loaded (last step at
                            full feed) and residual (after unloading), for both dies
  WORK/force.csv            force per mm of thickness against the revolution angle (3D: 2 |F| of
                            the half model / 25.4 mm; 2D: |F| per mm)
  WORK/disk_rolling_3d_spread.png, WORK/disk_rolling_3d_force.png, WORK/disk_rolling_3d_rim.png

and prints the summary quoted on the scene page, with the CPU time of every run.

Usage: study.py --ausroll build/ausroll --work DIR [--np N] [--skip-runs]
"""
import argparse
import csv
import math
import os
import resource
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
ANGLES = list(range(60, 151, 5))
HALF = 12.7
TIMELINE = [
    "Loading/End time = 40", "Loading/Number of steps = 40", "Loading/Predictor = none",
    "Contact/Die 0/Motion/Rolling/Revolution angle = t <= 4 ? 0 : (t <= 36 ? 1.25 * (t - 4) : 40)",
    "Contact/Die 0/Motion/Rolling/Feed = t <= 4 ? 0.762 * t / 4 : "
    "(t <= 36 ? 0.762 : 0.762 - 1.062 * (t - 36) / 4)",
]


def run(ausroll, prm, out, sets, np_):
    cmd = ([] if np_ == 1 else ["mpirun", "-np", str(np_)]) + [ausroll, prm, "--overwrite"]
    for s in sets + [f"Output/Directory = {out}"]:
        cmd += ["--set", s]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.time()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    print(f"{os.path.basename(prm)} -> {out}: CPU {cpu:.1f} s, wall {time.time() - start:.1f} s")


def history(path):
    return {round(float(r["time"]), 6): r for r in csv.DictReader(open(path))}


def radial(r, a, prefix="mid"):
    t = math.radians(a)
    return float(r[f"{prefix}{a}_ux"]) * math.cos(t) + float(r[f"{prefix}{a}_uy"]) * math.sin(t)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--ausroll", required=True)
    p.add_argument("--work", required=True)
    p.add_argument("--np", type=int, default=1)
    p.add_argument("--skip-runs", action="store_true")
    a = p.parse_args()
    os.makedirs(a.work, exist_ok=True)
    out = {k: os.path.join(a.work, k) for k in ("round", "flat", "2d")}
    mon2d = "; ".join(f"mid{g}: {43.5 * math.cos(math.radians(g)):.5f}, "
                      f"{43.5 * math.sin(math.radians(g)):.5f}" for g in ANGLES)
    if not a.skip_runs:
        for die in ("round", "flat"):
            run(a.ausroll, os.path.join(ROOT, "prm", f"disk_rolling_3d_{die}.prm"), out[die],
                ["Output/Write VTU = true"], a.np)
        run(a.ausroll, os.path.join(ROOT, "tests", "checks", "scenes", "disk_rolling_short.prm"),
            out["2d"], TIMELINE + ["Geometry/Ring/Cells around = 48",
                                   f"Postprocess/Monitor points = {mon2d}"], a.np)
    h = {k: history(os.path.join(v, "history.csv")) for k, v in out.items()}
    # per run: the last loaded state (feed still 0.762 mm) and the state after unloading
    loaded = {k: max(t for t, r in v.items() if float(r["die_roll_feed"]) >= 0.762 - 1e-9)
              for k, v in h.items()}
    final = {k: max(v) for k, v in h.items()}
    rev = {k: float(h[k][loaded[k]]["die_roll_revolution"]) for k in h}

    with open(os.path.join(a.work, "results.csv"), "w") as f:
        f.write("angle,die,depth_loaded,spread_loaded,depth_residual,spread_residual\n")
        for die in ("round", "flat"):
            tl, tr = loaded[die], final[die]
            for g in ANGLES:
                f.write(f"{g},{die},{-radial(h[die][tl], g):.6g},"
                        f"{float(h[die][tl][f'side{g}_uz']):.6g},{-radial(h[die][tr], g):.6g},"
                        f"{float(h[die][tr][f'side{g}_uz']):.6g}\n")

    force = {}
    for k in h:
        scale = 2.0 / (2 * HALF) if k != "2d" else 1.0
        force[k] = {round(float(r["die_roll_revolution"]), 6):
                    scale * float(r["die_roll_force_magnitude"])
                    for t, r in sorted(h[k].items()) if 0 < t <= loaded[k] + 1e-9}
    with open(os.path.join(a.work, "force.csv"), "w") as f:
        f.write("revolution,round_N_per_mm,flat_N_per_mm,plane_strain_N_per_mm\n")
        for ang in sorted(force["2d"]):
            f.write(f"{ang:.4g}," + ",".join(f"{force[k][ang]:.6g}" if ang in force[k] else ""
                                              for k in ("round", "flat", "2d")) + "\n")

    def mean(k, lo, hi):
        v = [fv for ang, fv in force[k].items() if lo <= ang <= hi]
        return sum(v) / len(v)

    print(f"end of feed: |F| per mm round {force['round'][0.0]:.0f}, "
          f"flat {force['flat'][0.0]:.0f}, plane strain {force['2d'][0.0]:.0f} N/mm")
    for die in ("round", "flat"):
        lo, hi = min(5.0, rev[die]), rev[die]
        print(f"mean |F| per mm over {lo:g}-{hi:g} deg: {die} {mean(die, lo, hi):.0f}, "
              f"plane strain {mean('2d', lo, hi):.0f} N/mm")
    for die in ("round", "flat"):
        rolled = [g for g in ANGLES if 90 <= g <= 90 + rev[die] - 5 + 1e-9] or [90]
        for t, label in ((loaded[die], "loaded"), (final[die], "residual")):
            d = [-radial(h[die][t], g) for g in rolled]
            sp = [float(h[die][t][f"side{g}_uz"]) for g in rolled]
            print(f"{die} {label} ({rolled[0]}-{rolled[-1]} deg): depth {min(d):.3f}..{max(d):.3f}"
                  f" mm, spread {min(sp):.3f}..{max(sp):.3f} mm, spread/depth "
                  f"{sum(sp) / sum(d):.2f}")
    for die in ("round", "flat"):
        # the 2D run at the same revolution, unloaded: the 2D history at the time of that angle
        # is loaded; compare residuals of the same time line only when the angles agree
        t2 = max(t for t, r in h["2d"].items() if float(r["die_roll_revolution"]) <= rev[die] + 1e-9
                 and float(r["die_roll_feed"]) >= 0.762 - 1e-9)
        diff = max(abs(radial(h[die][loaded[die]], g) - radial(h["2d"][t2], g)) for g in ANGLES)
        print(f"loaded rim at mid-thickness after {rev[die]:g} deg, {die} vs plane strain: "
              f"max |difference| {diff:.3f} mm")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for die, m in (("round", "o"), ("flat", "s")):
        states = [(loaded[die], "full")] + ([(final[die], "none")] if final[die] != loaded[die] else [])
        for t, fill in states:
            ax.plot([-radial(h[die][t], g) for g in ANGLES],
                    [float(h[die][t][f"side{g}_uz"]) for g in ANGLES], m, fillstyle=fill,
                    label=f"{die} die, {'under load' if t == loaded[die] else 'after unloading'}")
    lim = max(0.9, max(-radial(h["flat"][loaded["flat"]], g) for g in ANGLES))
    ax.plot([0, lim], [0, lim], "k--", lw=0.8, label="spread = depth")
    ax.set_xlabel("indentation depth -u_r at mid-thickness (mm)")
    ax.set_ylabel("lateral spread u_z of the side-face edge (mm)")
    ax.set_title("3D disk rolling: lateral spread, rim points 60-150 deg")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(a.work, "disk_rolling_3d_spread.png"), dpi=110)

    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    for k, lab in (("round", "3D round die"), ("flat", "3D flat die"), ("2d", "2D plane strain")):
        ax.plot(sorted(force[k]), [force[k][x] for x in sorted(force[k])], label=lab)
    ax.set_xlabel("revolution (deg; 0 = end of the feed)")
    ax.set_ylabel("|F| per mm of thickness (N/mm)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(a.work, "disk_rolling_3d_force.png"), dpi=110)

    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    for k, lab in (("round", "3D round die, mid-thickness"), ("flat", "3D flat die, mid-thickness"),
                   ("2d", "2D plane strain")):
        ax.plot(ANGLES, [radial(h[k][final[k]], g) for g in ANGLES], "o-", ms=3,
                label=f"{lab}, {rev[k]:g} deg" + (", under load" if final[k] == loaded[k] else ""))
    ax.set_xlabel("polar angle (deg; die fed at 90, rolled towards larger angles)")
    ax.set_ylabel("radial displacement of the rim after unloading (mm)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(a.work, "disk_rolling_3d_rim.png"), dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main())
