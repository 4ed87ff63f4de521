#!/usr/bin/python3
"""Adaptive 3D round-die scene against the uniform one (doc/scenes/disk_rolling_3d.md, "Adaptive
round scene"; issue 15 item 4). Reads finished runs, runs nothing:

  --adaptive DIR   output of prm/disk_rolling_3d_round_adaptive.prm (history.csv)
  --log FILE       its stdout (the "mesh adapted: ... (R cells refined, C coarsened)" lines)
  --uniform DIR    optional: output of prm/disk_rolling_3d_round.prm (history.csv)
  --work DIR       writes adaptive.csv (per step: revolution, cells, DoFs, |F| per mm),
                   disk_rolling_3d_adaptive.png (DoFs and force per mm against the revolution)

Prints the mean force per mm of thickness (2 |F_half| / 25.4 mm) over 5-40 and 5-80 degrees of
rolling, the indentation depth and lateral spread at 95-125 degrees after 40 degrees of rolling
(the uniform scene's loaded state, t = 36 in both time lines) and after unloading, and the cells
refined/coarsened per adaptation.
"""
import argparse
import csv
import math
import os
import re

HALF = 12.7


def history(path):
    return {round(float(r["time"]), 6): r for r in csv.DictReader(open(os.path.join(path, "history.csv")))}


def radial(r, a):
    t = math.radians(a)
    return float(r[f"mid{a}_ux"]) * math.cos(t) + float(r[f"mid{a}_uy"]) * math.sin(t)


def summary(name, h, out):
    loaded = [t for t, r in sorted(h.items()) if t > 0 and float(r["die_roll_feed"]) >= 0.762 - 1e-9]
    force = {round(float(h[t]["die_roll_revolution"]), 6): float(h[t]["die_roll_force_magnitude"]) / HALF
             for t in loaded}
    for lo, hi in ((5, 40), (5, 80), (40, 80)):
        v = [f for a, f in force.items() if lo <= a <= hi + 1e-9]
        if v and max(force) >= hi - 1e-9:
            out.append(f"{name}: mean |F| per mm {lo}-{hi} deg {sum(v) / len(v):.0f} N/mm ({len(v)} steps)")
    angles = list(range(95, 126, 5))
    for t, label in ((36.0, "after 40 deg, loaded"), (max(h), "after unloading")):
        d = [-radial(h[t], g) for g in angles]
        s = [float(h[t][f"side{g}_uz"]) for g in angles]
        out.append(f"{name} {label} (t = {t:g}), 95-125 deg: depth {min(d):.3f}..{max(d):.3f} mm, "
                   f"spread {min(s):.3f}..{max(s):.3f} mm, spread/depth {sum(s) / sum(d):.2f}")
    return force


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--adaptive", required=True)
    p.add_argument("--log")
    p.add_argument("--uniform")
    p.add_argument("--work", required=True)
    a = p.parse_args()
    os.makedirs(a.work, exist_ok=True)
    h = history(a.adaptive)
    out = []
    force = summary("adaptive", h, out)
    uni = None
    if a.uniform:
        uni = summary("uniform", history(a.uniform), out)
    if a.log:
        ad = [(int(m.group(1)), int(m.group(2)), int(m.group(3)), int(m.group(4)))
              for m in re.finditer(r"mesh adapted: (\d+) cells, (\d+) DoFs \((\d+) cells refined, (\d+) coarsened\)",
                                   open(a.log).read())]
        out.append("adaptations (cells, DoFs, refined, coarsened): " + " ".join(f"{c}/{d}/{r}/{k}" for c, d, r, k in ad))
        out.append(f"cells coarsened in all: {sum(x[3] for x in ad)}, refined: {sum(x[2] for x in ad)}")
    rows = [(float(r["die_roll_revolution"]), float(r["die_roll_feed"]), int(r["cells"]), int(r["dofs"]),
             float(r["die_roll_force_magnitude"]) / HALF) for t, r in sorted(h.items())]
    with open(os.path.join(a.work, "adaptive.csv"), "w") as f:
        f.write("revolution,feed,cells,dofs,F_per_mm\n")
        for r in rows:
            f.write(",".join(f"{x:.6g}" for x in r) + "\n")
    peak = max(rows, key=lambda r: r[3])
    out.append(f"DoFs: {rows[0][3]} at the start, peak {peak[3]} at {peak[0]:g} deg, {rows[-1][3]} at the end")
    print("\n".join(out))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(6.4, 6.0), sharex=True)
    loaded = [r for r in rows if r[1] >= 0.762 - 1e-9]
    ax1.plot([r[0] for r in loaded], [r[3] for r in loaded], "o-", ms=2, label="adaptive (24 x 2 x 2, level 2)")
    ax1.axhline(12960, color="k", ls="--", lw=0.8, label="uniform 48 x 2 x 4 (12 960)")
    ax1.set_ylabel("DoFs")
    ax1.legend(fontsize=8)
    ax2.plot(sorted(force), [force[x] for x in sorted(force)], label="adaptive")
    if uni:
        ax2.plot(sorted(uni), [uni[x] for x in sorted(uni)], label="uniform")
    ax2.set_xlabel("revolution (deg; 0 = end of the feed)")
    ax2.set_ylabel("|F| per mm of thickness (N/mm)")
    ax2.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(a.work, "disk_rolling_3d_adaptive.png"), dpi=110)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
