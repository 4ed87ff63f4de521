#!/usr/bin/env pvpython
"""Picture of an ausroll run with real ParaView: the workpiece coloured by a field, the dies beside it.

Usage (optional developer tool, needs ParaView's pvpython; off-screen under xvfb):

    xvfb-run -a pvpython benchmarks/figures/render_scene.py OUTPUT_DIR FIGURE.png [options]

OUTPUT_DIR is the Output/Directory of a run (it holds solution.pvd, dies.pvd, parameters.prm and
solution_units.csv). The script loads the workpiece (solution.pvd) and the dies (dies.pvd, one
surface per die and output step, in the pose of that step, written by every run), picks one output
step, shows the deformed workpiece (warped by `displacement` unless the run wrote the deformed mesh,
Output/Deformed mesh = true, read from OUTPUT_DIR/parameters.prm), colours it by --field with a
colour bar titled by the field and its unit (from solution_units.csv), draws the dies in grey and
writes FIGURE.png.

Options:
  --field NAME        point array to colour by (default equivalent_plastic_strain); a vector
                      (displacement) is shown by its magnitude, --component I picks a component
  --step N            output step: index into solution.pvd, negative from the end (default -1)
  --time T            output step nearest to time T instead of --step
  --range LO,HI       colour range (default: the data range of the step)
  --colormap NAME     ParaView preset (default: Turbo; stresses read well in Cool to Warm)
  --reverse           reverse the colour map (e.g. Reds from white at 0 to dark red)
  --symmetric         colour range symmetric about 0 (stress components)
  --view DX,DY,DZ     direction from the focal point to the camera (default 0,0,1: the xy plane)
  --up UX,UY,UZ       camera up vector (default 0,1,0)
  --focus X,Y,Z       focal point (default: centre of the workpiece's bounds)
  --scale S           half height of the picture in mm (parallel projection; default: fit)
  --reflect-z         also show the mirror image about z = 0 (half models with u_z = 0 on z = 0)
  --no-dies           leave the dies out
  --die-opacity A     opacity of the dies (default 0.35 in 3D, 1 in 2D)
  --edges             draw the mesh edges on the workpiece
  --size WxH          picture size in pixels (default 1200x800)
  --title TEXT        text in the upper left corner (default: scene name and time)
A vector that starts with a minus sign needs the '=' form: --focus=-14,36,0.

Examples (doc/manual.md, "Pictures with pvpython"):
    xvfb-run -a pvpython benchmarks/figures/render_scene.py output/gear_rolling_3d g.png \\
        --field stress_xx --symmetric --view 1,0.6,1.2 --reflect-z
"""

import argparse
import csv
import math
import os
import sys



def open_display_once():
    """pvpython 5.11 (Debian 12) under xvfb-run aborts with "bad X server connection" when
    ParaView opens the display first in the process (pvbatch does not; measured 2026-12-07, every
    time). Opening it once with Xlib before ParaView does avoids that; the connection stays open
    until the process ends."""
    if not os.environ.get("DISPLAY"):
        return
    try:
        import ctypes

        xlib = ctypes.cdll.LoadLibrary("libX11.so.6")
        xlib.XOpenDisplay.restype = ctypes.c_void_p
        xlib.XOpenDisplay(None)
    except OSError:
        pass


open_display_once()
from paraview import simple as pv  # noqa: E402 (pvpython provides it)


def vector(text, n=3):
    values = [float(v) for v in text.split(",")]
    if len(values) != n:
        raise argparse.ArgumentTypeError(f"expected {n} comma-separated numbers, got '{text}'")
    return values


def parse_arguments(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("output_dir")
    parser.add_argument("figure")
    parser.add_argument("--field", default="equivalent_plastic_strain")
    parser.add_argument("--component", type=int, default=-1)
    parser.add_argument("--step", type=int, default=-1)
    parser.add_argument("--time", type=float)
    parser.add_argument("--range", type=lambda t: vector(t, 2))
    parser.add_argument("--colormap", default="Turbo")
    parser.add_argument("--reverse", action="store_true")
    parser.add_argument("--symmetric", action="store_true")
    parser.add_argument("--view", type=vector, default=[0.0, 0.0, 1.0])
    parser.add_argument("--up", type=vector, default=[0.0, 1.0, 0.0])
    parser.add_argument("--focus", type=vector)
    parser.add_argument("--scale", type=float)
    parser.add_argument("--reflect-z", action="store_true")
    parser.add_argument("--no-dies", action="store_true")
    parser.add_argument("--die-opacity", type=float)
    parser.add_argument("--edges", action="store_true")
    parser.add_argument("--size", default="1200x800")
    parser.add_argument("--title")
    return parser.parse_args(argv)


def fail(message):
    print(f"render_scene.py: {message}", file=sys.stderr)
    sys.exit(2)


def read_units(output_dir):
    """array name -> unit from solution_units.csv ('1' means dimensionless)."""
    units = {}
    path = os.path.join(output_dir, "solution_units.csv")
    if os.path.exists(path):
        with open(path, newline="") as f:
            for row in csv.DictReader(f):
                units[row["array"]] = row["unit"]
    return units


def read_entries(output_dir):
    """Scene name and whether the VTU points are already deformed, from parameters.prm."""
    scene, deformed = os.path.basename(os.path.normpath(output_dir)), False
    path = os.path.join(output_dir, "parameters.prm")
    if os.path.exists(path):
        with open(path) as f:
            for line in f:
                text = line.split("#")[0].strip()
                if text.startswith("set Scene name"):
                    scene = text.split("=", 1)[1].strip()
                elif text.startswith("set Deformed mesh"):
                    deformed = text.split("=", 1)[1].strip().lower() in ("true", "1", "yes")
    return scene, deformed


def main(argv):
    args = parse_arguments(argv)
    solution_pvd = os.path.join(args.output_dir, "solution.pvd")
    dies_pvd = os.path.join(args.output_dir, "dies.pvd")
    if not os.path.exists(solution_pvd):
        fail(f"no solution.pvd in '{args.output_dir}' (Output/Write VTU = false?)")
    width, height = (int(v) for v in args.size.lower().split("x"))
    units = read_units(args.output_dir)
    scene, deformed = read_entries(args.output_dir)

    solution = pv.PVDReader(FileName=solution_pvd)
    times = list(solution.TimestepValues) if solution.TimestepValues else [0.0]
    if args.time is not None:
        index = min(range(len(times)), key=lambda i: abs(times[i] - args.time))
    else:
        index = args.step if args.step >= 0 else len(times) + args.step
        if not 0 <= index < len(times):
            fail(f"--step {args.step}: solution.pvd has {len(times)} output steps")
    time = times[index]

    point_arrays = solution.PointData.keys()
    if args.field not in point_arrays:
        fail(f"--field {args.field}: not in solution.pvd (point arrays: {', '.join(point_arrays)})")

    workpiece = solution
    if not deformed and "displacement" in point_arrays:
        workpiece = pv.WarpByVector(Input=solution, Vectors=["POINTS", "displacement"], ScaleFactor=1.0)
    workpiece = pv.MergeBlocks(Input=workpiece)
    pieces = [workpiece]
    if args.reflect_z:
        pieces.append(pv.Reflect(Input=workpiece, Plane="Z Min", Center=0.0, CopyInput=0))

    view = pv.CreateView("RenderView")
    view.ViewSize = [width, height]
    view.ViewTime = time
    view.OrientationAxesVisibility = 1
    view.Background = [1.0, 1.0, 1.0]
    try:  # ParaView >= 5.10 keeps the background in the colour palette unless told otherwise
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    pv.SetActiveView(view)

    lut = pv.GetColorTransferFunction(args.field)
    if not lut.ApplyPreset(args.colormap, True):
        fail(f"--colormap {args.colormap}: not a ParaView colour preset (e.g. Turbo, Reds, 'Cool to Warm')")
    if args.reverse:
        lut.InvertTransferFunction()
    if args.component >= 0:
        lut.VectorMode = "Component"
        lut.VectorComponent = args.component
    else:
        lut.VectorMode = "Magnitude"

    for piece in pieces:
        display = pv.Show(piece, view)
        pv.ColorBy(display, ("POINTS", args.field))
        display.LookupTable = lut
        display.Ambient = 0.25  # flat faces turned away from ParaView's key light stay readable
        display.Diffuse = 0.85
        if args.edges:
            display.SetRepresentationType("Surface With Edges")
            display.EdgeColor = [0.3, 0.3, 0.3]

    # Colour range: the data of this step (both halves share it), or as given.
    workpiece.UpdatePipeline(time)
    info = workpiece.PointData[args.field]
    lo, hi = info.GetRange(args.component if args.component >= 0 else -1)
    if args.range:
        lo, hi = args.range
    elif args.symmetric:
        bound = max(abs(lo), abs(hi))
        lo, hi = -bound, bound
    if hi <= lo:
        hi = lo + 1e-12
    lut.RescaleTransferFunction(lo, hi)
    lut.AutomaticRescaleRangeMode = "Never"

    unit = units.get(args.field, "")
    label = args.field.replace("_", " ")
    if args.component >= 0:
        label += f" [{args.component}]"
    bar = pv.GetScalarBar(lut, view)
    bar.Title = f"{label} ({unit})" if unit and unit != "1" else f"{label} (-)"
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    bar.TitleFontSize = 18
    bar.LabelFontSize = 16
    bar.RangeLabelFormat = "%.4g"
    bar.WindowLocation = "Any Location"
    bar.Orientation = "Vertical"
    bar.Position = [0.88, 0.12]
    bar.ScalarBarLength = 0.7
    bar.Visibility = 1

    bounds = workpiece.GetDataInformation().GetBounds()
    three_d = bounds[5] - bounds[4] > 1e-9

    if not args.no_dies and os.path.exists(dies_pvd):
        dies = pv.PVDReader(FileName=dies_pvd)
        die_pieces = [dies]
        if args.reflect_z and three_d:
            die_pieces.append(pv.Reflect(Input=dies, Plane="Z Min", Center=0.0, CopyInput=0))
        for piece in die_pieces:
            display = pv.Show(piece, view)
            display.ColorArrayName = ["POINTS", ""]
            display.AmbientColor = display.DiffuseColor = [0.45, 0.45, 0.5]
            display.Opacity = args.die_opacity if args.die_opacity is not None else (0.35 if three_d else 1.0)
            display.LineWidth = 3.0
            display.SetScalarBarVisibility(view, False)

    pv.Render(view)  # the first render resets the camera: place it afterwards
    # Camera: parallel projection along --view onto --focus, fitted to the workpiece or --scale.
    focus = args.focus or [0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
                           0.0 if args.reflect_z else 0.5 * (bounds[4] + bounds[5])]
    norm = math.sqrt(sum(c * c for c in args.view))
    if norm == 0.0:
        fail("--view: a zero direction")
    diagonal = math.sqrt(sum((bounds[2 * i + 1] - bounds[2 * i]) ** 2 for i in range(3)))
    distance = 4.0 * diagonal + 1.0
    camera = view.GetActiveCamera()
    camera.SetFocalPoint(*focus)
    camera.SetPosition(*[focus[i] + distance * args.view[i] / norm for i in range(3)])
    camera.SetViewUp(*args.up)
    view.CameraParallelProjection = 1
    if args.scale:
        view.CameraParallelScale = args.scale
    else:
        view.ResetCamera(False)
        camera.SetFocalPoint(*focus)
        camera.SetPosition(*[focus[i] + distance * args.view[i] / norm for i in range(3)])
        view.CameraParallelScale = 0.55 * diagonal if three_d else 0.55 * max(
            bounds[3] - bounds[2], (bounds[1] - bounds[0]) * height / width)

    title = args.title if args.title is not None else f"{scene}, t = {time:g}"
    if title:
        text = pv.Text(Text=title)
        text_display = pv.Show(text, view)
        text_display.Color = [0.0, 0.0, 0.0]
        text_display.FontSize = 20
        text_display.WindowLocation = "Upper Left Corner"

    pv.Render(view)
    pv.SaveScreenshot(args.figure, view, ImageResolution=[width, height], CompressionLevel="9")
    print(f"render_scene.py: wrote {args.figure} (step {index} of {len(times)}, t = {time:g}, "
          f"{args.field} {lo:.4g} ... {hi:.4g} {unit})")


if __name__ == "__main__":
    main(sys.argv[1:])
