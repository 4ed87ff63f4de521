#!/usr/bin/python3
"""Plane sections z = const of a 3D ausroll output, written as .vtu for scripts/plot_field.py.

Usage: sections.py FILE.pvtu|FILE.pvd OUT_PREFIX Z1 [Z2 ...]

Cuts the (deformed, `Output/Deformed mesh = true`) hexahedral mesh with the planes z = Zi
(vtkCutter; point and cell fields carried over) and writes OUT_PREFIX_z<Zi>.vtu, an unstructured
grid of the section polygons in the x-y plane, which scripts/plot_field.py draws like a 2D
output (e.g. the equivalent plastic strain at mid-face and at the face end of the gear tooth).
Needs python3-vtk9 (run with /usr/bin/python3).
"""
import os
import sys
import xml.etree.ElementTree as ET

import vtk


def main():
    path, prefix, zs = sys.argv[1], sys.argv[2], [float(z) for z in sys.argv[3:]]
    if path.endswith(".pvd"):
        sets = ET.parse(path).getroot().findall(".//DataSet")
        last = max(sets, key=lambda d: float(d.get("timestep", "0")))
        path = os.path.join(os.path.dirname(path), last.get("file"))
    reader = vtk.vtkXMLPUnstructuredGridReader() if path.endswith(".pvtu") \
        else vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    for z in zs:
        plane = vtk.vtkPlane()
        plane.SetOrigin(0.0, 0.0, z)
        plane.SetNormal(0.0, 0.0, 1.0)
        cutter = vtk.vtkCutter()
        cutter.SetCutFunction(plane)
        cutter.SetInputConnection(reader.GetOutputPort())
        cutter.GenerateTrianglesOff()
        append = vtk.vtkAppendFilter()
        append.AddInputConnection(cutter.GetOutputPort())
        append.Update()
        writer = vtk.vtkXMLUnstructuredGridWriter()
        name = f"{prefix}_z{z:g}.vtu"
        writer.SetFileName(name)
        writer.SetInputData(append.GetOutput())
        writer.Write()
        print(f"wrote {name} ({append.GetOutput().GetNumberOfCells()} polygons)")


if __name__ == "__main__":
    main()
