#!/usr/bin/python3
"""Deformed flank of the extruded gear tooth (prm/gear_rolling_3d*.prm) against the involute,
along the face width.

Usage: gear_flank_3d.py OUTPUT_DIR [--step -1] [--flank negative|positive] [--radii R1 R2 ...]
                        [--plot FILE.png] [--compare-2d FLANK_CSV] [--title TEXT]
                        (gear data options as scripts/gear_flank_analysis.py)

Reads one output step (default the last) of OUTPUT_DIR/solution.pvd (3D VTU written with
`Output/Deformed mesh = true`; current positions x and the nodal displacement; needs
python3-vtk9, run with /usr/bin/python3). For every node whose reference position X = x - u lies
on the involute of the chosen flank it computes, as gear_flank_analysis.py does in 2D, the normal
deviation d_n of the current position from the original involute in the plane z = const
(d_n = r_b (sign phi - theta_h(r)), exact: the involute normal is the tangent to the base
circle), the tangential displacement u_t along the flank (towards the tip) and the axial
displacement u_z. Nodes are grouped by their reference z (the layers of the mesh).

Writes OUTPUT_DIR/flank_deviation_3d.csv (Z,R,d_n,u_t,u_z,p_n) and prints a summary: d_n min /
max at the symmetry face z = 0 (mid-face) and at the face end, and d_n along z at the --radii
(linear interpolation in R within each layer). With --compare-2d (the flank_deviation.csv of a 2D
run, its last step) the mid-face profile is compared with the 2D profile on the 2D radii
(max |d_n,3D(z = 0) - d_n,2D|). --plot draws d_n(R) for every layer, d_n(z) at the radii and a map of d_n over the flank (z, R).
"""

import argparse
import csv
import math
import os
import sys
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gear_flank_analysis import gear_data  # noqa: E402


def read_step(directory, step):
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy

    pvd = ET.parse(os.path.join(directory, "solution.pvd")).getroot()
    datasets = list(pvd.iter("DataSet"))
    ds = datasets[step]
    reader = (vtk.vtkXMLUnstructuredGridReader() if ds.get("file").endswith(".vtu")
              else vtk.vtkXMLPUnstructuredGridReader())
    reader.SetFileName(os.path.join(directory, ds.get("file")))
    reader.Update()
    grid = reader.GetOutput()
    x = vtk_to_numpy(grid.GetPoints().GetData())
    u = vtk_to_numpy(grid.GetPointData().GetArray("displacement"))
    pressure = grid.GetPointData().GetArray("contact_pressure")
    p = vtk_to_numpy(pressure) if pressure is not None else [0.0] * len(x)
    seen, nodes = set(), []
    for k in range(len(x)):
        X = [float(x[k][d] - u[k][d]) for d in range(3)]
        key = tuple(round(v, 5) for v in X)
        if key in seen:
            continue
        seen.add(key)
        nodes.append((X, [float(v) for v in x[k]], float(p[k])))
    return float(ds.get("timestep")), nodes


def analyse(args):
    rp, rb, rt, theta_h = gear_data(args)
    axis = math.radians(args.axis_angle)
    sign = 1.0 if args.flank == "positive" else -1.0
    time, nodes = read_step(args.directory, args.step)
    rows = []
    for X, x, p_n in nodes:
        R = math.hypot(X[0], X[1])
        if R < rb * (1.0 + 1e-9) or R > rt * (1.0 - 1e-9) or R < args.min_radius:
            continue
        phi_ref = math.remainder(math.atan2(X[1], X[0]) - axis, 2.0 * math.pi)
        if abs(sign * phi_ref - theta_h(R)) * R > args.tolerance:
            continue
        r = math.hypot(x[0], x[1])
        phi = math.remainder(math.atan2(x[1], x[0]) - axis, 2.0 * math.pi)
        d_n = rb * (sign * phi - theta_h(r))
        u = math.sqrt(R * R / (rb * rb) - 1.0)
        th = axis + sign * theta_h(R)
        t = (math.cos(th) + sign * u * math.sin(th), math.sin(th) - sign * u * math.cos(th))
        tn = math.hypot(*t)
        u_t = ((x[0] - X[0]) * t[0] + (x[1] - X[1]) * t[1]) / tn
        # reference z from single-precision VTU values: layers are >= 0.1 mm apart
        rows.append((round(X[2], 2), R, d_n, u_t, x[2] - X[2], p_n))
    rows.sort()
    return time, rows, rp


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


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("directory")
    p.add_argument("--step", type=int, default=-1)
    p.add_argument("--flank", choices=["negative", "positive"], default="negative")
    p.add_argument("--radii", type=float, nargs="*", default=[45.5, 46.32, 47.5, 48.5])
    p.add_argument("--plot")
    p.add_argument("--title", default="3D gear flank")
    p.add_argument("--compare-2d")
    p.add_argument("--teeth", type=int, default=31)
    p.add_argument("--diametral-pitch", type=float, default=8.5)
    p.add_argument("--pressure-angle", type=float, default=22.0)
    p.add_argument("--thickness", type=float, default=4.69392)
    p.add_argument("--axis-angle", type=float, default=90.0)
    p.add_argument("--min-radius", type=float, default=0.0)
    p.add_argument("--tolerance", type=float, default=2e-4)
    args = p.parse_args()
    time, rows, rp = analyse(args)
    if not rows:
        raise SystemExit("gear_flank_3d.py: no flank nodes found")
    with open(os.path.join(args.directory, "flank_deviation_3d.csv"), "w") as f:
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
    if args.compare_2d:
        with open(args.compare_2d) as f:
            ref = list(csv.DictReader(f))
        last = max(int(r["step"]) for r in ref)
        ref = [(float(r["R"]), float(r["d_n"])) for r in ref if int(r["step"]) == last]
        diffs = [abs(interpolate(mid, R) - d) for R, d in ref if not math.isnan(interpolate(mid, R))]
        print(f"mid-face against 2D: max |d_n,3D - d_n,2D| = {max(diffs):.6g} mm over "
              f"{len(diffs)} radii; 2D d_n_min={min(d for _, d in ref):.6g}")
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
                         label="2D plane strain")
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
