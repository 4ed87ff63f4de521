#!/usr/bin/python3
"""Where the adaptive 3D disk mesh resolves the plastically deformed layer (issue 39 item 1;
doc/scenes/disk_rolling_3d.md, "Mesh study").

Reads the last VTU of every run directory given (the runs of
`benchmarks/convergence/convergence.sh disk_rolling_3d_round|disk_rolling_3d_flat`, which write
the last step) and prints per run, for the output sub-cells whose largest point value of the
equivalent plastic strain exceeds the threshold (default 0.002, the 0.2 % offset):

  - how many there are and which share of them lies on the finest level of the run,
  - the extent of that plastic layer: radial depth below the rim (43.55 mm), height z above the
    mid-plane, and the arc it covers (polar angles, degrees),
  - the same counts for the part of the layer behind the die (polar angle below the die angle
    minus 5 degrees), i.e. the rolled groove that the mesh keeps after the die has passed.

Usage: plastic_layer.py RUN_DIR [RUN_DIR ...] [--threshold 0.002] [--die-angle 105]
"""
import argparse
import glob
import math
import os

import vtk
from vtk.util.numpy_support import vtk_to_numpy

RIM = 43.55


def last_vtu(run):
    files = sorted(glob.glob(os.path.join(run, "solution_*.0.vtu")))
    if not files:
        raise SystemExit(f"plastic_layer.py: no solution_*.0.vtu in {run}")
    return files[-1]


def sub_cells(path):
    """Per output sub-cell: (max plastic strain, max level, centre x, y, z)."""
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    pd = grid.GetPointData()
    eps = vtk_to_numpy(pd.GetArray("equivalent_plastic_strain"))
    level = vtk_to_numpy(pd.GetArray("level"))
    pts = vtk_to_numpy(grid.GetPoints().GetData())
    ids = vtk.vtkIdList()
    for c in range(grid.GetNumberOfCells()):
        grid.GetCellPoints(c, ids)
        idx = [ids.GetId(i) for i in range(ids.GetNumberOfIds())]
        centre = pts[idx].mean(axis=0)
        yield max(eps[idx]), round(max(level[idx])), centre


def main():
    p = argparse.ArgumentParser()
    p.add_argument("runs", nargs="+")
    p.add_argument("--threshold", type=float, default=0.002)
    p.add_argument("--die-angle", type=float, default=105.0,
                   help="polar angle of the die line at the last step (degrees)")
    a = p.parse_args()
    for run in a.runs:
        cells = list(sub_cells(last_vtu(run)))
        finest = max(lev for _, lev, _ in cells)
        plastic = [(e, lev, c) for e, lev, c in cells if e > a.threshold]
        if not plastic:
            print(f"{run}: no sub-cell above {a.threshold}")
            continue
        behind = [x for x in plastic
                  if math.degrees(math.atan2(x[2][1], x[2][0])) < a.die_angle - 5]
        depth = max(RIM - math.hypot(c[0], c[1]) for _, _, c in plastic)
        height = max(c[2] for _, _, c in plastic)
        angles = [math.degrees(math.atan2(c[1], c[0])) for _, _, c in plastic]

        def share(group):
            return sum(1 for _, lev, _ in group if lev == finest) / max(1, len(group))

        levels = sorted({lev for _, lev, _ in plastic})
        print(f"{os.path.basename(os.path.normpath(run))}: finest level {finest}; "
              f"{len(plastic)} of {len(cells)} sub-cells above eps_p {a.threshold}, "
              f"{100 * share(plastic):.0f} % on the finest level (levels {levels}); "
              f"behind the die {len(behind)}, {100 * share(behind):.0f} % on the finest level; "
              f"layer to {depth:.2f} mm below the rim, z <= {height:.2f} mm, "
              f"{min(angles):.1f}-{max(angles):.1f} deg (sub-cell centres)")


if __name__ == "__main__":
    main()
