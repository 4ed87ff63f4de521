#!/usr/bin/python3
"""Deformed flank of the extruded gear tooth (prm/gear_rolling_3d*.prm) against the involute,
along the face width.

Usage: gear_flank_3d.py OUTPUT_DIR [--step -1 | --time T] [--flank negative|positive]
                        [--radii R1 R2 ...] [--plot FILE.png] [--compare-2d FLANK_CSV
                        [--compare-2d-time T]] [--tag TAG] [--title TEXT]
                        (gear data options as scripts/gear_flank_analysis.py, with --scale,
                        --sap-radius, --tip-chamfer-radius, --evaluation-fraction)

Reads one output step (default the last; --time: the output nearest to the time T, e.g. the
end of a chain's rolling stage) of OUTPUT_DIR/solution.pvd (3D VTU written with
`Output/Deformed mesh = true`; current positions x and the nodal displacement; needs
python3-vtk9, run with /usr/bin/python3). For every node whose reference position X = x - u lies
on the involute of the chosen flank it computes, as gear_flank_analysis.py does in 2D, the normal
deviation d_n of the current position from the original involute in the plane z = const
(d_n = r_b (sign phi - theta_h(r)), exact: the involute normal is the tangent to the base
circle), the tangential displacement u_t along the flank (towards the tip) and the axial
displacement u_z. Nodes are grouped by their reference z (the layers of the mesh).

Writes OUTPUT_DIR/flank_deviation_3d.csv (Z,R,d_n,u_t,u_z,p_n) and prints a summary: d_n min /
max at the symmetry face z = 0 (mid-face) and at the face end, and d_n along z at the --radii
(linear interpolation in R within each layer). ISO 1328-1 profile quantities F_alpha, f_f_alpha and
f_H_alpha of every layer (gear_flank_analysis.profile_deviations(): the trace d_n against the roll
length, the evaluation range L_alpha from the mid-face layer's flank nodes or the --sap-radius and
--tip-chamfer-radius, the same range for every layer) go to OUTPUT_DIR/flank_iso1328_3d.csv
(Z,L_alpha_R0,L_alpha_R1,F_alpha,f_f_alpha,f_H_alpha; mm) and the summary prints those of the
mid-face and the face end. --scale S measures against the involute contracted by S about the gear
axis (a cooled gear: S = 1 + alpha (T - T_ref)). --tag TAG names the files
flank_deviation_3d_TAG.csv and flank_iso1328_3d_TAG.csv (e.g. rolled and cooled states of a
chain). With --compare-2d (the flank_deviation.csv of a 2D run, its last step or with
--compare-2d-time the output nearest to that time) the mid-face profile is compared with the 2D
profile on the 2D radii (max |d_n,3D(z = 0) - d_n,2D|), and the ISO quantities of the 2D trace
over the same L_alpha are printed beside the mid-face ones. --plot draws d_n(R) for every layer, d_n(z) at the radii and a map of d_n over the flank (z, R).
"""

import argparse
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import vtu_io  # noqa: E402
from gear_flank_analysis import (Flank, add_gear_options, evaluation_range,  # noqa: E402
                                 gear_data, profile_deviations)


def select(items, step, time):
    """The element of ITEMS ((time, ...) tuples) at index STEP, or nearest to TIME if given."""
    if time is None:
        return items[step]
    return min(items, key=lambda item: abs(item[0] - time))


def analyse(args):
    """(time, [(Z, R, d_n, u_t, u_z, p_n)], r_p) of the flank nodes at output step args.step
    (or the output nearest to args.time)."""
    flank = Flank(args)
    time, path = select(vtu_io.datasets(args.directory), args.step, args.time)
    rows = []
    for X, x, p_n in vtu_io.unique_nodes(vtu_io.read_grid(path)):
        m = flank.measure(X, x)
        if m is None:
            continue
        R, _, d_n, u_t = m
        # reference z from single-precision VTU values: layers are >= 0.1 mm apart
        rows.append((round(X[2], 2), R, d_n, u_t, x[2] - X[2], p_n))
    rows.sort()
    return time, rows, flank.rp


def layers(rows):
    out = {}
    for r in rows:
        out.setdefault(r[0], []).append(r)
    return dict(sorted(out.items()))


def interpolate(profile, R):
    """d_n at radius R by linear interpolation in a layer's (R, d_n) list (sorted by R)."""
    for a, b in zip(profile, profile[1:]):
        if a[1] <= R <= b[1]:
            w = (R - a[1]) / (b[1] - a[1]) if b[1] > a[1] else 0.0
            return (1 - w) * a[2] + w * b[2]
    return float("nan")


def iso_of_layer(layer, rb, r0, r1):
    """(F_alpha, f_f_alpha, f_H_alpha) of a layer's (Z, R, d_n, ...) rows over the radii [r0, r1]."""
    trace = sorted((math.sqrt(max(r[1] ** 2 - rb * rb, 0.0)), r[2]) for r in layer
                   if not math.isnan(r[2]))
    xi = [math.sqrt(max(r * r - rb * rb, 0.0)) for r in (r0, r1)]
    return profile_deviations(trace, xi[0], xi[1])


def read_2d(filename, time):
    """[(R, d_n)] of the last output step of a 2D flank_deviation.csv, or of the output nearest to
    TIME."""
    with open(filename) as f:
        rows = list(csv.DictReader(f))
    steps = sorted({(float(r["time"]), int(r["step"])) for r in rows}, key=lambda s: s[1])
    step = select(steps, -1, time)[1]
    return sorted((float(r["R"]), float(r["d_n"])) for r in rows if int(r["step"]) == step)


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("directory")
    p.add_argument("--step", type=int, default=-1)
    p.add_argument("--time", type=float, help="the output nearest to this time (instead of --step)")
    p.add_argument("--tag", help="file name suffix of the CSV files")
    p.add_argument("--radii", type=float, nargs="*", default=[45.5, 46.32, 47.5, 48.5])
    p.add_argument("--plot")
    p.add_argument("--title", default="3D gear flank")
    p.add_argument("--compare-2d")
    p.add_argument("--compare-2d-time", type=float,
                   help="the 2D output nearest to this time (default: its last)")
    add_gear_options(p)
    args = p.parse_args()
    time, rows, rp = analyse(args)
    if not rows:
        raise SystemExit("gear_flank_3d.py: no flank nodes found")
    suffix = f"_{args.tag}" if args.tag else ""
    with open(os.path.join(args.directory, f"flank_deviation_3d{suffix}.csv"), "w") as f:
        f.write("Z,R,d_n,u_t,u_z,p_n\n")
        for r in rows:
            f.write(",".join(f"{v:.10g}" for v in r) + "\n")
    by_z = layers(rows)
    zs = list(by_z)
    mid, end = by_z[zs[0]], by_z[zs[-1]]
    print(f"time={time:.6g} layers={len(zs)} z_mid={zs[0]:.4g} z_end={zs[-1]:.4g}")
    print(f"mid-face d_n_min={min(r[2] for r in mid):.6g} d_n_max={max(r[2] for r in mid):.6g} "
          f"face-end d_n_min={min(r[2] for r in end):.6g} d_n_max={max(r[2] for r in end):.6g} "
          f"u_z_max={max(abs(r[4]) for r in rows):.6g}")
    for R in args.radii:
        line = " ".join(f"{z:.3g}:{1000 * interpolate(by_z[z], R):+.3f}" for z in zs)
        print(f"d_n(z) um at R={R}: {line}")
    rb = gear_data(args)[1]
    r0, r1 = evaluation_range([(None, None, r[1]) for r in mid], rb, gear_data(args)[2], args)
    iso = {z: iso_of_layer(by_z[z], rb, r0, r1) for z in zs}
    with open(os.path.join(args.directory, f"flank_iso1328_3d{suffix}.csv"), "w") as f:
        f.write("Z,L_alpha_R0,L_alpha_R1,F_alpha,f_f_alpha,f_H_alpha\n")
        for z in zs:
            f.write(",".join(f"{v:.10g}" for v in (z, r0, r1) + iso[z]) + "\n")
    words = lambda v: f"F_alpha={v[0]:.6g} f_f_alpha={v[1]:.6g} f_H_alpha={v[2]:.6g}"
    print(f"ISO 1328 over L_alpha_R0={r0:.6g} L_alpha_R1={r1:.6g}: mid-face {words(iso[zs[0]])}; "
          f"face-end {words(iso[zs[-1]])}")
    if args.compare_2d:
        ref = read_2d(args.compare_2d, args.compare_2d_time)
        diffs = [abs(interpolate(mid, R) - d) for R, d in ref if not math.isnan(interpolate(mid, R))]
        print(f"mid-face against 2D: max |d_n,3D - d_n,2D| = {max(diffs):.6g} mm over "
              f"{len(diffs)} radii; 2D d_n_min={min(d for _, d in ref):.6g}")
        iso_2d = iso_of_layer([(None, R, d) for R, d in ref], rb, r0, r1)
        print(f"2D over the same L_alpha: {words(iso_2d)}")
    if args.plot:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, axes = plt.subplots(1, 3, figsize=(16, 4.4), constrained_layout=True)
        cmap = plt.get_cmap("viridis")
        for i, z in enumerate(zs):
            c = cmap(i / max(len(zs) - 1, 1))
            axes[0].plot([r[1] for r in by_z[z]], [1000 * r[2] for r in by_z[z]], color=c,
                         label=f"z = {z:.2f}" if i in (0, len(zs) - 1) or len(zs) <= 6 else None)
        if args.compare_2d:
            axes[0].plot([R for R, _ in ref], [1000 * d for _, d in ref], "k--", lw=1,
                         label="2D run (--compare-2d)")
        axes[0].axvline(rp, color="gray", ls=":", lw=1)
        axes[0].set_xlabel("reference radius R (mm); dotted: pitch circle")
        axes[0].set_ylabel("normal deviation d_n (um)")
        axes[0].legend(fontsize=8)
        for R in args.radii:
            axes[1].plot(zs, [1000 * interpolate(by_z[z], R) for z in zs], "o-", ms=3,
                         label=f"R = {R} mm")
        axes[1].set_xlabel("z (mm): 0 mid-face, right end the face end")
        axes[1].set_ylabel("d_n (um)")
        axes[1].legend(fontsize=8)
        tri = axes[2].tricontourf([r[0] for r in rows], [r[1] for r in rows],
                                  [1000 * r[2] for r in rows], levels=20, cmap="RdBu_r")
        fig.colorbar(tri, ax=axes[2], label="d_n (um)")
        axes[2].set_xlabel("z (mm)")
        axes[2].set_ylabel("reference radius R (mm)")
        axes[2].set_title("d_n over the flank", fontsize=9)
        for ax in axes[:2]:
            ax.grid(alpha=0.3)
        fig.suptitle(f"{args.title} (t = {time:g})")
        fig.savefig(args.plot, dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main())
