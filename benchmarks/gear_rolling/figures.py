#!/usr/bin/env python3
"""Figures of a gear rolling run for doc/scenes/gear_rolling.md: deformed mesh coloured by the
equivalent plastic strain (or another VTU point field) at one output step.

Usage: /usr/bin/python3 benchmarks/gear_rolling/figures.py OUT_DIR STEP FIGURE.png
           [--field equivalent_plastic_strain] [--title TEXT] [--zoom x0 x1 y0 y1]
STEP indexes the datasets of OUT_DIR/solution.pvd (-1: the last). The drawing is done by
scripts/plot_field.py (cell edges on; the run writes the deformed mesh, so no warp). Needs
python3-vtk9, matplotlib.
"""

import argparse
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


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
    command = [sys.executable, os.path.join(ROOT, "scripts", "plot_field.py"),
               os.path.join(a.out, ds.get("file")), a.field, "-o", a.figure, "--edges",
               "--title", f"{a.title} t = {float(ds.get('timestep')):.2f}".strip()]
    if a.zoom:
        command += ["--window"] + [str(v) for v in a.zoom]
    return subprocess.run(command).returncode


if __name__ == "__main__":
    sys.exit(main())
