#!/usr/bin/env python3
"""The output files a ParaView or spreadsheet user relies on, on scenes/cylinder_block_{2d,3d}.prm
(a cylinder die of radius R = 20, axis along z through (0, 25.001 - 0.02 t) (3D: z = 0.5, width
4), pressed into a block 10 x 5 (3D: x 1) in 4 steps; elastic, small strain), run with VTU output
every step:

1. Dies (dies.pvd): one entry per output, at the same times as solution.pvd; each entry a .vtm
   whose block is named after the die ("roll") and whose .vtu carries die_id = 0 on every point
   and cell. Every written point lies on the analytic die in its pose at that time (independently
   computed here from the .prm: the circle |x - c(t)| = R (2D, z = 0); the boundary of the solid
   cylinder r <= R, |z - 0.5| <= 2, i.e. max(r - R, |z - 0.5| - 2) = 0 (3D)) to 1e-10 R (round-off
   of the pose and of 17-digit ASCII); the drawn part covers the die's lowest line x = 0 (over the
   block) and spans at least the block's width 10 mm along x (the part facing the workpiece). On
   2 ranks (2D) the same holds and dies.pvd lists the same outputs (written once, by rank 0);
   a 2D run stopped after step 2 (Checkpoint/Abort after step) and resumed has the dies.pvd of
   the uninterrupted run.
2. Units: history_units.csv lists every history.csv column in order with a known unit;
   solution_units.csv lists every array of the VTU files with a known unit.
3. parameters.prm: written before the first step; the run of parameters.prm (another
   Output/Directory) gives the same history.csv (every column but wall_seconds, exactly: the same
   parameters, the same arithmetic); `ausroll --print-parameters FILE.prm --set ...` prints the
   same entries.
4. Summary at Verbosity = quiet: the lines "steps: 4 converged, 0 cutbacks", "peak die force: roll
   |F|max = F N at t = 1" with F the largest |force| of history.csv (to its 6 printed digits) and
   "time: ... wall, ... CPU".
5. 3D VTU stress and strain (needs VTK for Python: exit 77 = skipped without it): the arrays
   stress_xx ... stress_yz (all six) and strain_xx ... strain_yz exist; the material is linear
   elastic with small strain, so every cell satisfies Hooke's law sigma = lambda tr(eps) I + 2 mu eps
   (E = 210000, nu = 0.3) on the cell averages (both are averages of the same quadrature points,
   and Hooke's law is linear) to 1e-5 of max |sigma| (float32 VTU arrays: 6e-8 relative, times the
   condition of the sum).

Usage: check_output_files.py AUSROLL SOURCE_DIR
"""

import csv
import math
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

from checklist import Checklist  # tests/checks/checklist.py (next to this script)

SKIP = 77
R, WIDTH, ZC = 20.0, 4.0, 0.5


def die_center(t):
    return 0.0, 25.001 - 0.02 * t


def run(ausroll, prm, out, extra=(), np=1, expect=0, resume=False):
    cmd = [ausroll, prm, "--overwrite", "--set", f"Output/Directory = {out}",
           "--set", "Output/Write VTU = true", "--set", "Output/Interval = 1",
           "--set", "Output/Verbosity = quiet"]
    for e in extra:
        cmd += ["--set", e]
    if resume:
        cmd = [c for c in cmd if c != "--overwrite"] + ["--resume"]
    env = os.environ
    if np > 1:
        cmd = ["mpirun", "-np", str(np)] + cmd
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                   OMPI_MCA_rmaps_base_oversubscribe="1")
    r = subprocess.run(cmd, capture_output=True, text=True, env=env)
    print(r.stdout)
    if r.returncode != expect:
        print(r.stderr)
        raise SystemExit(f"FAIL {prm} exited with {r.returncode} (expected {expect})")
    return r.stdout


def read_history(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def pvd_entries(path):
    root = ET.parse(path).getroot()
    return [(float(d.get("timestep")), d.get("file")) for d in root.iter("DataSet")]


def read_die_vtu(path):
    """Points, die_id point and cell data, cell count of a die .vtu (ASCII, written by ausroll)."""
    root = ET.parse(path).getroot()
    piece = root.find("./UnstructuredGrid/Piece")
    pts = [float(v) for v in piece.find("./Points/DataArray").text.split()]
    points = [pts[i:i + 3] for i in range(0, len(pts), 3)]
    pid = [int(v) for v in piece.find("./PointData/DataArray[@Name='die_id']").text.split()]
    cid = [int(v) for v in piece.find("./CellData/DataArray[@Name='die_id']").text.split()]
    return points, pid, cid, int(piece.get("NumberOfCells"))


def check_dies(checks, out, dim, label=None):
    """The assertions of part 1 on the outputs in out (label: how the lines are prefixed)."""
    label = label or f"{dim}D"
    dies = pvd_entries(os.path.join(out, "dies.pvd"))
    solution = pvd_entries(os.path.join(out, "solution.pvd"))
    checks(f"{label}: dies.pvd has one entry per output ({len(dies)} = {len(solution)} = 5: the "
           "initial state and 4 steps)", len(dies) == len(solution) == 5)
    checks(f"{label}: dies.pvd times are those of solution.pvd",
           [t for t, _ in dies] == [t for t, _ in solution])
    worst, covered, all_ids = 0.0, True, True
    names = set()
    for t, vtm in dies:
        blocks = ET.parse(os.path.join(out, vtm)).getroot().findall(".//DataSet")
        names |= {b.get("name") for b in blocks}
        for b in blocks:
            points, pid, cid, n_cells = read_die_vtu(os.path.join(out, b.get("file")))
            all_ids &= set(pid) == {0} and set(cid) == {0} and len(cid) == n_cells > 0
            cx, cy = die_center(t)
            for x, y, z in points:
                r = math.hypot(x - cx, y - cy)
                if dim == 2:
                    worst = max(worst, abs(r - R), abs(z))
                else:
                    worst = max(worst, abs(max(r - R, abs(z - ZC) - 0.5 * WIDTH)))
            xs = [p[0] for p in points]
            covered &= min(xs) < 0.0 < max(xs) and max(xs) - min(xs) >= 10.0
    checks(f"{label}: the die block is named 'roll' ({sorted(names)})", names == {"roll"})
    checks(f"{label}: die_id = 0 on every point and cell", all_ids)
    checks(f"{label}: every die point lies on the analytic cylinder at its time (worst "
           f"{worst:.2e} <= {1e-10 * R:.0e})", worst <= 1e-10 * R)
    checks(f"{label}: the drawn die covers x = 0 and spans >= 10 mm along x", covered)


def check_units(checks, out, dim):
    with open(os.path.join(out, "history.csv")) as f:
        header = f.readline().strip().split(",")
    units = read_history(os.path.join(out, "history_units.csv"))
    checks(f"{dim}D: history_units.csv lists the history columns in order",
           [u["column"] for u in units] == header)
    unknown = [u["column"] for u in units if "unknown" in (u["quantity"], u["unit"])]
    checks(f"{dim}D: every history column has a unit (unknown: {unknown})", not unknown)
    force = {u["unit"] for u in units if u["column"].startswith("die_roll_force")}
    checks(f"{dim}D: die force columns in N ({force})", force == {"N"})
    vtu_units = {u["array"]: u for u in read_history(os.path.join(out, "solution_units.csv"))}
    unknown = [a for a, u in vtu_units.items() if "unknown" in (u["quantity"], u["unit"])]
    checks(f"{dim}D: every VTU array in solution_units.csv has a unit (unknown: {unknown})",
           not unknown)
    with open(os.path.join(out, "solution_0000.pvtu")) as f:
        arrays = set(re.findall(r'<PDataArray[^>]*Name="([^"]+)"', f.read()))
    missing = sorted(arrays - set(vtu_units))
    checks(f"{dim}D: solution_units.csv covers every array of solution_0000.pvtu (missing: "
           f"{missing})", not missing and arrays)
    return vtu_units


def check_parameters(checks, ausroll, prm, out, dim):
    copy = os.path.join(out, "parameters.prm")
    checks(f"{dim}D: {copy} written", os.path.exists(copy))
    again = out + "_again"
    run(ausroll, copy, again)
    a, b = read_history(os.path.join(out, "history.csv")), read_history(
        os.path.join(again, "history.csv"))
    same = len(a) == len(b) and all(
        ra[k] == rb[k] for ra, rb in zip(a, b) for k in ra if k != "wall_seconds")
    checks(f"{dim}D: the run of parameters.prm repeats history.csv exactly", same)
    printed = subprocess.run(
        [ausroll, "--print-parameters", prm, "--set", f"Output/Directory = {out}",
         "--set", "Output/Write VTU = true", "--set", "Output/Interval = 1",
         "--set", "Output/Verbosity = quiet", "--set", "Output/Overwrite = true"],
        capture_output=True, text=True)
    with open(copy) as f:
        body = "".join(line for line in f if not line.startswith("# The effective")
                       and not line.startswith("# --set") and not line.startswith("# ends in"))
    sets = lambda text: [l.strip() for l in text.splitlines() if l.strip().startswith("set ")]
    checks(f"{dim}D: --print-parameters FILE.prm --set ... prints the entries of parameters.prm "
           f"(exit {printed.returncode})",
           printed.returncode == 0 and sets(printed.stdout) == sets(body) and sets(body))


def check_summary(checks, stdout, out, dim):
    rows = read_history(os.path.join(out, "history.csv"))
    comps = ["die_roll_force_x", "die_roll_force_y"] + (["die_roll_force_z"] if dim == 3 else [])
    peak = max(math.sqrt(sum(float(r[c]) ** 2 for c in comps)) for r in rows)
    m = re.search(r"peak die force: roll\s+\|F\|max = (\S+) N at t = (\S+)", stdout)
    checks(f"{dim}D quiet: 'steps: 4 converged, 0 cutbacks' printed",
           "steps: 4 converged, 0 cutbacks" in stdout)
    checks(f"{dim}D quiet: peak die force {m.group(1) if m else None} = max |F| of history.csv "
           f"{peak:.6g} (6 digits)", m is not None and abs(float(m.group(1)) - peak) <= 1e-5 * peak)
    checks(f"{dim}D quiet: wall and CPU time printed",
           re.search(r"time: \S+ s wall, \S+ s CPU", stdout) is not None)


def check_hooke(checks, out):
    try:
        from vtkmodules.vtkIOXML import vtkXMLPUnstructuredGridReader
    except ImportError:
        print("SKIPPED part 5: VTK for Python is not installed (apt-get install python3-vtk9)")
        return False
    reader = vtkXMLPUnstructuredGridReader()
    reader.SetFileName(os.path.join(out, "solution_0004.pvtu"))
    reader.Update()
    data = reader.GetOutput().GetPointData()  # deal.II writes cell fields as patch point data
    comps = ["xx", "yy", "zz", "xy", "xz", "yz"]
    names = [f"stress_{c}" for c in comps] + [f"strain_{c}" for c in comps]
    missing = [n for n in names if data.GetArray(n) is None]
    checks(f"3D VTU: six stress and six strain components (missing: {missing})", not missing)
    if missing:
        return True
    E, nu = 210000.0, 0.3
    lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
    arr = {n: data.GetArray(n) for n in names}
    n = arr["stress_xx"].GetNumberOfTuples()
    smax, worst = 0.0, 0.0
    for i in range(n):
        eps = {c: arr[f"strain_{c}"].GetValue(i) for c in comps}
        tr = eps["xx"] + eps["yy"] + eps["zz"]
        for c in comps:
            s = arr[f"stress_{c}"].GetValue(i)
            expected = 2 * mu * eps[c] + (lam * tr if c in ("xx", "yy", "zz") else 0.0)
            smax, worst = max(smax, abs(s)), max(worst, abs(s - expected))
    checks(f"3D VTU: cell stresses obey Hooke's law on the cell strains (worst {worst:.3g} MPa "
           f"<= 1e-5 max|sigma| = {1e-5 * smax:.3g}; max|sigma| {smax:.3g} MPa)",
           smax > 0 and worst <= 1e-5 * smax)
    return True


def main():
    ausroll = sys.argv[1]
    here = os.path.dirname(os.path.abspath(__file__))
    checks = Checklist()
    vtk_ran = True
    for dim in (2, 3):
        prm = os.path.join(here, "scenes", f"cylinder_block_{dim}d.prm")
        out = os.path.abspath(f"out{dim}d")
        stdout = run(ausroll, prm, out)
        check_dies(checks, out, dim)
        check_units(checks, out, dim)
        check_parameters(checks, ausroll, prm, out, dim)
        check_summary(checks, stdout, out, dim)
        if dim == 3:
            vtk_ran = check_hooke(checks, out)
    # 2D on 2 ranks: the die files are written once (rank 0), at the same times, on the die
    prm = os.path.join(here, "scenes", "cylinder_block_2d.prm")
    out2 = os.path.abspath("out2d_np2")
    if subprocess.run(["which", "mpirun"], capture_output=True).returncode == 0:
        run(ausroll, prm, out2, np=2)
        check_dies(checks, out2, 2, label="2D np = 2")
        checks("2D np = 2: dies.pvd lists the outputs of the run on 1 rank",
               pvd_entries(os.path.join(out2, "dies.pvd"))
               == pvd_entries(os.path.join("out2d", "dies.pvd")))
    # 2D stopped after step 2 and resumed: dies.pvd lists the same outputs as the uninterrupted run
    out3 = os.path.abspath("out2d_resumed")
    stop = ["Checkpoint/Interval = 1", "Checkpoint/Abort after step = 2"]
    run(ausroll, prm, out3, extra=stop, expect=99)
    run(ausroll, prm, out3, extra=stop, resume=True)
    checks("2D resumed after step 2: dies.pvd has the entries of the uninterrupted run",
           pvd_entries(os.path.join(out3, "dies.pvd"))
           == pvd_entries(os.path.join("out2d", "dies.pvd")))
    status = checks.exit_status()
    if status == 0 and not vtk_ran:
        return SKIP
    return status


if __name__ == "__main__":
    sys.exit(main())
