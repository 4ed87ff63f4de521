#!/usr/bin/python3
"""Meridian sections of the 3D disk rolling runs (doc/scenes/disk_rolling_3d.md): the deformed
cross-section (r, z) near the rim at a polar angle, coloured by the equivalent plastic strain,
one panel per run, from the last VTU output (after unloading). The 3D counterpart of
scripts/plot_field.py (which draws 2D meshes): the VTU is warped by the displacement (true
scale, or --warp) and cut with the plane through the disk axis at the angle.

Usage: section_plot.py OUT.png --angle DEG [--warp S] LABEL=RUN_DIR ...
Needs Debian's python3-vtk9 and python3-matplotlib (run with /usr/bin/python3).
"""
import argparse
import glob
import math
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import vtk
from matplotlib.collections import PolyCollection
from vtk.util.numpy_support import vtk_to_numpy


def section(pvtu, angle, warp):
    reader = vtk.vtkXMLPUnstructuredGridReader()
    reader.SetFileName(pvtu)
    reader.Update()
    grid = reader.GetOutput()
    grid.GetPointData().SetActiveVectors("displacement")
    warped = vtk.vtkWarpVector()
    warped.SetInputData(grid)
    warped.SetScaleFactor(warp)
    phi = math.radians(angle)
    plane = vtk.vtkPlane()
    plane.SetOrigin(0, 0, 0)
    plane.SetNormal(-math.sin(phi), math.cos(phi), 0)
    cut = vtk.vtkCutter()
    cut.SetCutFunction(plane)
    cut.SetInputConnection(warped.GetOutputPort())
    cut.Update()
    poly = cut.GetOutput()
    pts = vtk_to_numpy(poly.GetPoints().GetData())
    eps = vtk_to_numpy(poly.GetPointData().GetArray("equivalent_plastic_strain"))
    r = pts[:, 0] * math.cos(phi) + pts[:, 1] * math.sin(phi)
    rz = np.column_stack([r, pts[:, 2]])
    polygons, values = [], []
    for c in range(poly.GetNumberOfCells()):
        ids = poly.GetCell(c).GetPointIds()
        nodes = [ids.GetId(i) for i in range(ids.GetNumberOfIds())]
        if r[nodes].mean() < 0:  # the other half of the plane
            continue
        polygons.append(rz[nodes])
        values.append(eps[nodes].mean())
    return polygons, np.asarray(values)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("output")
    p.add_argument("--angle", type=float, required=True)
    p.add_argument("--warp", type=float, default=1.0)
    p.add_argument("runs", nargs="+")
    a = p.parse_args()
    fig, axes = plt.subplots(1, len(a.runs), figsize=(4.2 * len(a.runs), 4.4), squeeze=False)
    for ax, spec in zip(axes[0], a.runs):
        label, run = spec.split("=", 1)
        last = sorted(glob.glob(os.path.join(run, "solution_*.pvtu")))[-1]
        polygons, values = section(last, a.angle, a.warp)
        coll = PolyCollection(polygons, array=values, cmap="viridis", edgecolors="face")
        coll.set_clim(0, max(values.max(), 1e-6))
        ax.add_collection(coll)
        ax.plot([43.55, 43.55, 17.8], [0, 12.7, 12.7], "w--", lw=0.8)  # undeformed rim and side
        ax.set_xlim(30, 44.5)
        ax.set_ylim(0, 14.0)
        ax.set_aspect("equal")
        ax.set_xlabel("r (mm)")
        ax.set_ylabel("z (mm; 0 = mid-thickness)")
        ax.set_title(f"{label}, {a.angle:g} deg, after unloading", fontsize=9)
        fig.colorbar(coll, ax=ax, fraction=0.046, pad=0.03, label="equivalent plastic strain")
    fig.tight_layout()
    fig.savefig(a.output, dpi=120)
    print(f"wrote {a.output}")


if __name__ == "__main__":
    main()
