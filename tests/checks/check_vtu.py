#!/usr/bin/env python3
"""ParaView check: open solution.pvd and its .pvtu files with VTK's readers and check fields.

  check_vtu.py OUTPUT_DIR [--expect-cell FIELD VALUE RELTOL] [--expect-point-component FIELD COMP
                            MIN MAX] ...

Checks that solution.pvd lists existing .pvtu files with increasing times, that every .pvtu
(and its .vtu pieces) is read by vtkXMLPUnstructuredGridReader, that the fields a user looks at
are present (displacement with 3 components, stress_xx/yy/zz/xy, von_mises_stress,
equivalent_plastic_strain, subdomain, level), and then the value assertions on the LAST output:
  --expect-cell F V T             cell field F is V everywhere within relative T (deal.II writes
                                  cell-wise fields as point data of its patches)
  --expect-point-range F C LO HI  component C of point field F lies in [LO, HI] at every point
Exit status: 0 ok, 1 failed, 77 skipped (VTK for Python not installed).
"""

import argparse
import os
import sys
import xml.etree.ElementTree as ET

SKIP = 77


def main():
    p = argparse.ArgumentParser()
    p.add_argument("directory")
    p.add_argument("--expect-cell", nargs=3, action="append", default=[])
    p.add_argument("--expect-point-range", nargs=4, action="append", default=[])
    a = p.parse_args()
    try:
        import vtk  # noqa: F401
        from vtkmodules.vtkIOXML import vtkXMLPUnstructuredGridReader
    except ImportError:
        print("SKIPPED: VTK for Python is not installed (apt-get install python3-vtk9)")
        return SKIP

    pvd = os.path.join(a.directory, "solution.pvd")
    try:
        root = ET.parse(pvd).getroot()
    except (OSError, ET.ParseError) as e:
        print(f"FAIL: cannot parse {pvd}: {e}")
        return 1
    datasets = root.findall(".//DataSet")
    if not datasets:
        print(f"FAIL: {pvd} lists no data sets")
        return 1
    times = [float(d.get("timestep")) for d in datasets]
    if any(t1 < t0 for t0, t1 in zip(times, times[1:])):
        print(f"FAIL: times in {pvd} are not increasing: {times}")
        return 1

    required_cell = ["stress_xx", "stress_yy", "stress_zz", "stress_xy", "von_mises_stress",
                     "equivalent_plastic_strain", "subdomain", "level"]
    failures = 0
    grid = None
    for d in datasets:
        path = os.path.join(a.directory, d.get("file"))
        if not os.path.exists(path):
            print(f"FAIL: {path} listed in solution.pvd does not exist")
            return 1
        reader = vtkXMLPUnstructuredGridReader()
        reader.SetFileName(path)
        reader.Update()
        grid = reader.GetOutput()
        if grid.GetNumberOfCells() == 0:
            print(f"FAIL: {path} has no cells")
            return 1
        disp = grid.GetPointData().GetArray("displacement")
        if disp is None or disp.GetNumberOfComponents() != 3:
            print(f"FAIL: {path}: point field 'displacement' (3 components) missing")
            return 1
        # deal.II writes cell-wise fields as (piecewise constant) point data of its patches
        missing = [f for f in required_cell if grid.GetPointData().GetArray(f) is None]
        if missing:
            print(f"FAIL: {path}: cell fields missing: {missing}")
            return 1
    print(f"{len(datasets)} outputs read; last: {grid.GetNumberOfPoints()} points, "
          f"{grid.GetNumberOfCells()} cells (patch subdivisions included)")

    for field, value, tol in a.expect_cell:
        arr = grid.GetPointData().GetArray(field)
        if arr is None:
            print(f"FAIL: cell field {field} missing")
            failures += 1
            continue
        value, tol = float(value), float(tol)
        worst = max(abs(arr.GetValue(i) - value) for i in range(arr.GetNumberOfTuples()))
        ok = worst <= tol * max(abs(value), 1e-30)
        failures += not ok
        print(f"{'ok  ' if ok else 'FAIL'} cell field {field} = {value} everywhere "
              f"(max deviation {worst:.3g}, tol {tol:g} relative)")
    for field, comp, lo, hi in a.expect_point_range:
        arr = grid.GetPointData().GetArray(field)
        if arr is None:
            print(f"FAIL: point field {field} missing")
            failures += 1
            continue
        c = int(comp)
        vals = [arr.GetComponent(i, c) for i in range(arr.GetNumberOfTuples())]
        ok = float(lo) <= min(vals) and max(vals) <= float(hi)
        failures += not ok
        print(f"{'ok  ' if ok else 'FAIL'} point field {field}[{c}] in [{lo}, {hi}] "
              f"(found [{min(vals):.6g}, {max(vals):.6g}])")
    print("passed" if not failures else "FAILED")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
