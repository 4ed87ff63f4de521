#!/usr/bin/env python3
"""Temperature field of a thermal run on the deformed mesh (one output step), as a PNG.

Usage: benchmarks/gear_ausrolling/temperature_figure.py OUTPUT_DIR OUT.png [--time T]

Reads OUTPUT_DIR/solution.pvd (VTU with `Output/Deformed mesh = true` and the point field
`temperature`; needs python3-vtk9 and python3-matplotlib), takes the output step closest to T
(default: the one with the lowest temperature) and draws the whole section and a close-up of
2 mm around the coolest point, coloured by temperature.
"""

import argparse
import os
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLPUnstructuredGridReader  # noqa: E402


def read(path):
    reader = vtkXMLPUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    T = grid.GetPointData().GetArray("temperature")
    x = [grid.GetPoint(i)[0] for i in range(grid.GetNumberOfPoints())]
    y = [grid.GetPoint(i)[1] for i in range(grid.GetNumberOfPoints())]
    triangles = []
    for c in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(c).GetPointIds()
        n = [ids.GetId(k) for k in range(ids.GetNumberOfIds())]
        if len(n) == 4:
            triangles += [[n[0], n[1], n[2]], [n[0], n[2], n[3]]]
        elif len(n) == 3:
            triangles.append(n)
    return x, y, triangles, [T.GetValue(i) for i in range(grid.GetNumberOfPoints())]


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("directory")
    p.add_argument("png")
    p.add_argument("--time", type=float)
    a = p.parse_args()
    sets = ET.parse(os.path.join(a.directory, "solution.pvd")).getroot().findall(".//DataSet")
    data = [(float(d.get("timestep")), os.path.join(a.directory, d.get("file"))) for d in sets]
    if a.time is not None:
        t, path = min(data, key=lambda d: abs(d[0] - a.time))
        x, y, tri, T = read(path)
    else:
        best = None
        for t_, path_ in data:
            field = read(path_)
            if best is None or min(field[3]) < min(best[1][3]):
                best = ((t_, path_), field)
        (t, path), (x, y, tri, T) = best
    triangulation = mtri.Triangulation(x, y, tri)
    k = min(range(len(T)), key=lambda i: T[i])
    fig, axes = plt.subplots(1, 2, figsize=(11, 5.5))
    for ax, zoom in zip(axes, (False, True)):
        shade = ax.tripcolor(triangulation, T, shading="gouraud", cmap="coolwarm")
        ax.set_aspect("equal")
        ax.set_xlabel("x (mm)")
        ax.set_ylabel("y (mm)")
        if zoom:
            ax.set_xlim(x[k] - 1.0, x[k] + 1.0)
            ax.set_ylim(y[k] - 1.0, y[k] + 1.0)
            ax.triplot(triangulation, lw=0.2, color="k", alpha=0.4)
            ax.set_title(f"2 mm around the coolest point ({min(T):.1f} C)")
        else:
            ax.set_title(f"t = {t:.4f} s: temperature (C)")
        fig.colorbar(shade, ax=ax, shrink=0.8)
    fig.tight_layout()
    fig.savefig(a.png, dpi=110)
    print(f"{a.png}: t = {t} s, T from {min(T):.2f} to {max(T):.2f} C")


if __name__ == "__main__":
    main()
