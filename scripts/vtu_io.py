"""Reading ausroll's VTU output: shared by the scripts and benchmarks that post-process it.

Needs Debian's python3-vtk9 (run with /usr/bin/python3); VTK is imported only when a grid is read,
so that a script can print its --help without it.

* datasets(directory): the (time, path) of every data set that DIRECTORY/solution.pvd lists;
* read_grid(path): the unstructured grid of a .vtu or .pvtu file;
* point_array(grid, name, default): a nodal field as a numpy array (default per point if absent);
* unique_nodes(grid, field): each distinct node once (every cell writes its own copies), with its
  reference position X = x - displacement, its current position x and the value of FIELD.
"""

import os
import xml.etree.ElementTree as ET


def datasets(directory):
    """[(time, path)] of the data sets of DIRECTORY/solution.pvd, in the order of the file."""
    pvd = os.path.join(directory, "solution.pvd")
    if not os.path.exists(pvd):
        raise SystemExit(f"no solution.pvd in {directory}")
    root = ET.parse(pvd).getroot()
    return [(float(ds.get("timestep")), os.path.join(directory, ds.get("file")))
            for ds in root.iter("DataSet")]


def read_grid(path):
    """The vtkUnstructuredGrid of a .vtu (one piece) or .pvtu (all pieces merged) file."""
    try:
        import vtk
    except ImportError:
        raise SystemExit("reading VTU files needs VTK's Python module: apt-get install python3-vtk9 "
                         "(and run the script with /usr/bin/python3)")

    if not os.path.isfile(path):
        raise SystemExit(f"no such file: {path}")
    reader = (vtk.vtkXMLUnstructuredGridReader() if path.endswith(".vtu")
              else vtk.vtkXMLPUnstructuredGridReader())
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def point_array(grid, name, default=None):
    """Nodal field NAME of GRID as a numpy array; [default] * points if the file has no such field
    (None: the field is required)."""
    from vtk.util.numpy_support import vtk_to_numpy

    array = grid.GetPointData().GetArray(name)
    if array is None:
        if default is None:
            raise SystemExit(f"the output has no nodal field '{name}'")
        return [default] * grid.GetNumberOfPoints()
    return vtk_to_numpy(array)


def unique_nodes(grid, field="contact_pressure"):
    """[(X, x, value)] for every distinct node of GRID: reference position X = x - displacement and
    current position x (lists of three coordinates; written with `Output/Deformed mesh = true` the
    points are the current positions) and the nodal FIELD (0 if the output has none). Copies of a
    node are recognised by their position rounded to 1e-5 mm; the first copy is kept."""
    from vtk.util.numpy_support import vtk_to_numpy

    x = vtk_to_numpy(grid.GetPoints().GetData())
    u = point_array(grid, "displacement")
    values = point_array(grid, field, 0.0)
    seen, nodes = set(), []
    for k in range(len(x)):
        key = tuple(round(float(v), 5) for v in x[k])
        if key in seen:
            continue
        seen.add(key)
        current = [float(v) for v in x[k]]
        reference = [current[d] - float(u[k][d]) for d in range(len(u[k]))]
        reference += current[len(reference):]
        nodes.append((reference, current, float(values[k])))
    return nodes
