#!/usr/bin/env python3
"""Figures of a gear rolling run for doc/scenes/gear_rolling.md: deformed mesh coloured by the
equivalent plastic strain (or another VTU point field) at one output step.

Usage: /usr/bin/python3 benchmarks/gear_rolling/figures.py OUT_DIR STEP FIGURE.png
           [--field equivalent_plastic_strain] [--title TEXT] [--zoom x0 x1 y0 y1]
STEP indexes the datasets of OUT_DIR/solution.pvd (-1: the last). Needs python3-vtk9, matplotlib.
"""

import argparse
import os
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import vtk  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402


def main():
    p = argparse.ArgumentParser()
    p.add_argument("out")
    p.add_argument("step", type=int)
    p.add_argument("figure")
    p.add_argument("--field", default="equivalent_plastic_strain")
    p.add_argument("--title", default="")
    p.add_argument("--zoom", type=float, nargs=4)
    a = p.parse_args()
    datasets = list(ET.parse(os.path.join(a.out, "solution.pvd")).getroot().iter("DataSet"))
    ds = datasets[a.step]
    reader = vtk.vtkXMLPUnstructuredGridReader()
    reader.SetFileName(os.path.join(a.out, ds.get("file")))
    reader.Update()
    grid = reader.GetOutput()
    x = vtk_to_numpy(grid.GetPoints().GetData())
    field = vtk_to_numpy(grid.GetPointData().GetArray(a.field))
    polygons, values = [], []
    for c in range(grid.GetNumberOfCells()):
        cell = grid.GetCell(c)
        ids = [cell.GetPointId(k) for k in range(cell.GetNumberOfPoints())]
        polygons.append([(x[i][0], x[i][1]) for i in ids])
        values.append(sum(field[i] for i in ids) / len(ids))
    fig, ax = plt.subplots(figsize=(5.5, 6.5))
    coll = PolyCollection(polygons, array=values, cmap="viridis", edgecolors="k", linewidths=0.15)
    ax.add_collection(coll)
    fig.colorbar(coll, ax=ax, label=a.field.replace("_", " "))
    ax.autoscale_view()
    if a.zoom:
        ax.set_xlim(a.zoom[0], a.zoom[1])
        ax.set_ylim(a.zoom[2], a.zoom[3])
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    ax.set_title(f"{a.title} t = {float(ds.get('timestep')):.2f}")
    fig.tight_layout()
    fig.savefig(a.figure, dpi=110)


if __name__ == "__main__":
    main()
