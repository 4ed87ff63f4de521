#!/usr/bin/env python3
"""Phase maps of a run with Phases on: fields of one output step on the deformed mesh, as a PNG.

Usage: benchmarks/gear_ausrolling/phase_figure.py OUTPUT_DIR OUT.png [--time T]
           [--fields carbon_content martensite_fraction von_mises_stress] [--window X0 X1 Y0 Y1]

Reads OUTPUT_DIR/solution.pvd (needs python3-vtk9 and python3-matplotlib), takes the output step
closest to T (default: the last) and draws one panel per field (cell fields as flat colours per
cell, point fields interpolated), optionally only the window [X0, X1] x [Y0, Y1] (mm).
"""

import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))),
                                "scripts"))
import vtu_io  # noqa: E402

LABELS = {"carbon_content": "carbon (wt%)", "martensite_fraction": "martensite fraction",
          "von_mises_stress": "von Mises stress (MPa)", "temperature": "temperature (C)"}


def step_file(directory, time):
    sets = vtu_io.datasets(directory)
    return sets[-1] if time is None else min(sets, key=lambda s: abs(s[0] - time))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("directory")
    p.add_argument("png")
    p.add_argument("--time", type=float)
    p.add_argument("--fields", nargs="+", default=["carbon_content", "martensite_fraction", "von_mises_stress"])
    p.add_argument("--window", type=float, nargs=4)
    args = p.parse_args()
    t, path = step_file(args.directory, args.time)
    grid = vtu_io.read_grid(path)
    points = [grid.GetPoint(i)[:2] for i in range(grid.GetNumberOfPoints())]
    cells = []
    for c in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(c).GetPointIds()
        n = [ids.GetId(k) for k in range(ids.GetNumberOfIds())]
        # deal.II's VTU quadrilateral: the first four are the vertices in order
        cells.append([points[k] for k in n[:4]])
    fig, axes = plt.subplots(1, len(args.fields), figsize=(4.2 * len(args.fields), 4.6))
    axes = [axes] if len(args.fields) == 1 else axes
    for ax, field in zip(axes, args.fields):
        array = grid.GetCellData().GetArray(field)
        if array is not None:
            values = [array.GetValue(c) for c in range(grid.GetNumberOfCells())]
        else:
            array = grid.GetPointData().GetArray(field)
            if array is None:
                raise SystemExit(f"phase_figure.py: no field '{field}' in {path}")
            values = []
            for c in range(grid.GetNumberOfCells()):
                ids = grid.GetCell(c).GetPointIds()
                values.append(sum(array.GetValue(ids.GetId(k)) for k in range(4)) / 4.0)
        collection = PolyCollection(cells, array=values, cmap="viridis", edgecolors="face", linewidths=0.2)
        ax.add_collection(collection)
        fig.colorbar(collection, ax=ax, shrink=0.8, label=LABELS.get(field, field))
        ax.set_aspect("equal")
        if args.window:
            ax.set_xlim(args.window[0], args.window[1])
            ax.set_ylim(args.window[2], args.window[3])
        else:
            ax.autoscale_view()
        ax.set_xlabel("x (mm)")
        ax.set_ylabel("y (mm)")
    fig.suptitle(f"{os.path.basename(os.path.normpath(args.directory))}, t = {t:g} s")
    fig.tight_layout()
    fig.savefig(args.png, dpi=80)
    print(f"figure: {args.png} (t = {t:g})")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
