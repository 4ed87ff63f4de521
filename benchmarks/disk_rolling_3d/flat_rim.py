#!/usr/bin/python3
"""Residual rim of the flat-faced 3D die against plane strain (doc/scenes/disk_rolling_3d.md,
"Flat die after unloading"): reads the history of a finished prm/disk_rolling_3d_flat.prm run
(feed 4 steps, 10 degrees in 8 steps of 1.25 degrees, unloading in 4 steps), runs the 2D
plane-strain reference tests/checks/scenes/disk_rolling_short.prm on the same 48 x 2 section mesh
with the same time line (no predictor), and prints per monitor angle (60-150 deg, 0.05 mm inside
the rim) the radial displacement at mid-thickness under load and after unloading (3D, 2D), the
lateral spread u_z of the side-face edge and the differences; writes WORK/flat_rim.csv and
WORK/disk_rolling_3d_flat_rim.png.

Usage: flat_rim.py --ausroll build/ausroll --flat FLAT_OUTPUT_DIR --work DIR
"""
import argparse
import csv
import math
import os
import resource
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
ANGLES = list(range(60, 151, 5))
TIMELINE = [
    "Loading/End time = 16", "Loading/Number of steps = 16", "Loading/Predictor = none",
    "Contact/Die 0/Motion/Rolling/Revolution angle = t <= 4 ? 0 : (t <= 12 ? 1.25 * (t - 4) : 10)",
    "Contact/Die 0/Motion/Rolling/Feed = t <= 4 ? 0.762 * t / 4 : "
    "(t <= 12 ? 0.762 : 0.762 - 1.062 * (t - 12) / 4)",
    "Geometry/Ring/Cells around = 48",
]


sys.path.insert(0, HERE)
from study import history, radial  # noqa: E402  (the readers of the 3D study)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--ausroll", required=True)
    p.add_argument("--flat", required=True)
    p.add_argument("--work", required=True)
    a = p.parse_args()
    os.makedirs(a.work, exist_ok=True)
    out2d = os.path.join(a.work, "2d_flat_timeline")
    mon = "; ".join(f"mid{g}: {43.5 * math.cos(math.radians(g)):.5f}, "
                    f"{43.5 * math.sin(math.radians(g)):.5f}" for g in ANGLES)
    cmd = [a.ausroll, os.path.join(ROOT, "tests", "checks", "scenes", "disk_rolling_short.prm"),
           "--overwrite"]
    for s in TIMELINE + [f"Postprocess/Monitor points = {mon}", f"Output/Directory = {out2d}"]:
        cmd += ["--set", s]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    print(f"2D reference: CPU {after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime:.1f} s")
    h3 = history(os.path.join(a.flat, "history.csv"))
    h2 = history(os.path.join(out2d, "history.csv"))
    loaded, final = 12.0, 16.0
    for k, h in (("3D flat", h3), ("2D", h2)):
        if loaded not in h or final not in h:
            raise SystemExit(f"{k}: history lacks t = 12 (end of rolling) or t = 16 (unloaded)")
    rows = []
    for g in ANGLES:
        rows.append(dict(angle=g, u3_loaded=radial(h3[loaded], g), u2_loaded=radial(h2[loaded], g),
                         u3_residual=radial(h3[final], g), u2_residual=radial(h2[final], g),
                         spread_loaded=float(h3[loaded][f"side{g}_uz"]),
                         spread_residual=float(h3[final][f"side{g}_uz"])))
    with open(os.path.join(a.work, "flat_rim.csv"), "w") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        for r in rows:
            w.writerow({k: f"{v:.6g}" for k, v in r.items()})
    print("angle  u_r 3D loaded  2D loaded  3D residual  2D residual  diff residual  spread res.")
    for r in rows:
        print(f"{r['angle']:5d}  {r['u3_loaded']:12.4f}  {r['u2_loaded']:9.4f}  "
              f"{r['u3_residual']:11.4f}  {r['u2_residual']:11.4f}  "
              f"{r['u3_residual'] - r['u2_residual']:13.4f}  {r['spread_residual']:11.4f}")
    rolled = [r for r in rows if 90 <= r["angle"] <= 95]
    print("rolled arc 90-95 deg: residual depth 3D "
          f"{min(-r['u3_residual'] for r in rolled):.3f}..{max(-r['u3_residual'] for r in rolled):.3f}"
          f" mm, 2D {min(-r['u2_residual'] for r in rolled):.3f}..{max(-r['u2_residual'] for r in rolled):.3f}"
          f" mm; residual spread {min(r['spread_residual'] for r in rolled):.3f}.."
          f"{max(r['spread_residual'] for r in rolled):.3f} mm")
    print(f"max |3D - 2D| residual over 60-150 deg: "
          f"{max(abs(r['u3_residual'] - r['u2_residual']) for r in rows):.3f} mm; loaded: "
          f"{max(abs(r['u3_loaded'] - r['u2_loaded']) for r in rows):.3f} mm")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    ax.plot(ANGLES, [r["u3_residual"] for r in rows], "s-", ms=3, label="3D flat die, mid-thickness")
    ax.plot(ANGLES, [r["u2_residual"] for r in rows], "o-", ms=3, label="2D plane strain")
    ax.plot(ANGLES, [r["u3_loaded"] for r in rows], "s:", ms=2, label="3D flat die, under load")
    ax.plot(ANGLES, [r["u2_loaded"] for r in rows], "o:", ms=2, label="2D, under load")
    ax.set_xlabel("polar angle (deg; die fed at 90, rolled 10 deg towards larger angles)")
    ax.set_ylabel("radial displacement of the rim (mm)")
    ax.set_title("flat-faced die: rim after unloading (solid) and under load (dotted)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(a.work, "disk_rolling_3d_flat_rim.png"), dpi=110)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
