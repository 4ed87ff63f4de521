#!/usr/bin/python3
"""Draw one field of an ausroll VTU/PVTU output on the (optionally deformed) mesh as a PNG.

Usage:
  scripts/plot_field.py FILE.pvtu FIELD [-o OUT.png] [--warp SCALE] [--component N]
                        [--edges] [--range MIN MAX] [--window XMIN XMAX YMIN YMAX]
                        [--mirror x|y] [--title TEXT] [--cmap NAME]

FILE may be a .pvtu (all ranks) or a single .vtu, or a .pvd (the last time step is used).
FIELD is a point or cell array name as listed by --list (e.g. equivalent_plastic_strain,
von_mises_stress, displacement, contact_pressure); vectors are drawn as their magnitude unless
--component selects one. --warp moves the points by SCALE x displacement (use 1 for the true
deformed shape unless the run already wrote the deformed mesh, Output/Deformed mesh = true).
Needs Debian's python3-vtk9 and python3-matplotlib (run with /usr/bin/python3).
"""
import argparse
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np

try:
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError:
    sys.exit("plot_field.py: needs VTK's Python module (apt-get install python3-vtk9; use /usr/bin/python3)")
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import PolyCollection



def field_unit(name):
    """Unit of a VTU field of ausroll for the colour bar (the shipped scenes use mm, N, MPa)."""
    if "stress" in name or name in ("contact_pressure", "contact_traction"):
        return " (MPa)"
    if name in ("displacement", "contact_gap") or name.startswith("displacement"):
        return " (mm)"
    if name == "equivalent_plastic_strain":
        return " (-)"
    return ""

def resolve(path):
    """A .pvd resolves to its last data set."""
    if not path.endswith(".pvd"):
        return path
    sets = ET.parse(path).getroot().findall(".//DataSet")
    if not sets:
        sys.exit(f"plot_field.py: {path} lists no data sets")
    last = max(sets, key=lambda d: float(d.get("timestep", "0")))
    return os.path.join(os.path.dirname(path), last.get("file"))


def read(path):
    reader = vtk.vtkXMLPUnstructuredGridReader() if path.endswith(".pvtu") else vtk.vtkXMLUnstructuredGridReader()
    if not os.path.isfile(path):
        sys.exit(f"plot_field.py: no such file: {path}")
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def array(grid, name):
    for data, where in ((grid.GetPointData(), "point"), (grid.GetCellData(), "cell")):
        a = data.GetArray(name)
        if a is not None:
            return vtk_to_numpy(a), where
    return None, None


def names(grid):
    out = []
    for data, where in ((grid.GetPointData(), "point"), (grid.GetCellData(), "cell")):
        for i in range(data.GetNumberOfArrays()):
            out.append(f"{data.GetArrayName(i)} ({where}, {data.GetArray(i).GetNumberOfComponents()} components)")
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("file")
    p.add_argument("field", nargs="?")
    p.add_argument("-o", "--output")
    p.add_argument("--warp", type=float, default=0.0)
    p.add_argument("--component", type=int)
    p.add_argument("--edges", action="store_true", help="draw cell edges")
    p.add_argument("--range", type=float, nargs=2, help="colour range")
    p.add_argument("--window", type=float, nargs=4, metavar=("XMIN", "XMAX", "YMIN", "YMAX"), help="zoom")
    p.add_argument("--title")
    p.add_argument("--cmap", default="viridis")
    p.add_argument("--mirror", action="append", choices=["x", "y"], default=[],
                   help="also draw the mirror image about the line x = 0 (x) or y = 0 (y); repeatable")
    p.add_argument("--list", action="store_true", help="list the fields and exit")
    args = p.parse_args()

    grid = read(resolve(args.file))
    if args.list or not args.field:
        print("\n".join(names(grid)))
        return
    values, where = array(grid, args.field)
    if values is None:
        sys.exit(f"plot_field.py: no field '{args.field}'; available:\n  " + "\n  ".join(names(grid)))
    if values.ndim > 1:
        values = values[:, args.component] if args.component is not None else np.linalg.norm(values, axis=1)

    points = vtk_to_numpy(grid.GetPoints().GetData())[:, :2].copy()
    if args.warp:
        u, _ = array(grid, "displacement")
        if u is None:
            sys.exit("plot_field.py: --warp needs the displacement field")
        points += args.warp * u[:, :2]

    polygons, cell_values = [], []
    for c in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(c).GetPointIds()
        nodes = [ids.GetId(i) for i in range(ids.GetNumberOfIds())]
        polygons.append(points[nodes])
        cell_values.append(values[c] if where == "cell" else values[nodes].mean())
    for axis in args.mirror:
        flip = np.array([-1.0, 1.0]) if axis == "x" else np.array([1.0, -1.0])
        polygons += [poly * flip for poly in polygons]
        cell_values += cell_values
    cell_values = np.asarray(cell_values)
    allpts = np.vstack(polygons)
    width, height = np.ptp(allpts[:, 0]) or 1.0, np.ptp(allpts[:, 1]) or 1.0
    aspect = min(max(height / width, 0.25), 2.0)

    fig, ax = plt.subplots(figsize=(8, 8 * aspect + 1.0))
    coll = PolyCollection(polygons, array=cell_values, cmap=args.cmap,
                          edgecolors="k" if args.edges else "face", linewidths=0.15 if args.edges else 0.05)
    if args.range:
        coll.set_clim(*args.range)
    ax.add_collection(coll)
    ax.autoscale_view()
    if args.window:
        ax.set_xlim(args.window[0], args.window[1])
        ax.set_ylim(args.window[2], args.window[3])
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    fig.colorbar(coll, ax=ax, fraction=0.046, pad=0.03,
                 label=args.field + (f"[{args.component}]" if args.component is not None else "")
                 + field_unit(args.field))
    ax.set_title(args.title or os.path.basename(args.file))
    out = args.output or os.path.splitext(os.path.basename(args.file))[0] + f"_{args.field}.png"
    fig.savefig(out, dpi=150, bbox_inches="tight")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
