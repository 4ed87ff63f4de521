#!/usr/bin/env python3
"""Generalized plane strain (Model/Planar model = generalized plane strain): the out-of-plane
stretch lambda = F_zz is one unknown of the whole section, found with the displacements from the
axial force on the section, N = int sigma_zz da = Model/Axial force (here 0: free ends).

free         a 2 x 1 mm section (Q2, 4 x 2 cells, held only on its symmetry edges x = 0, y = 0)
             heated uniformly from 20 to 120 C (alpha = 1.2e-5, Thermal/Number of conditions = 0):
             a free body expands freely, so every stress component vanishes (the VTU cell
             line probe, below 1e-8 E alpha dT), the axial force is 0 (1e-8 E alpha dT A) and the
             stretch is the thermal stretch, lambda = theta = 1 + alpha dT (the model's thermal
             strain is the stretch theta = 1 + alpha (T - T_ref) in every kinematics: small strain
             eps_zz = lambda - 1 = alpha dT, multiplicative F_theta = theta I) to 1e-12; small
             strain and finite strain with F-bar (Q1: in-plane F-bar, F_bar_zz = lambda).
plane_strain the same section in plane strain (F_zz = 1): sigma_xx = sigma_yy = 0 and
             sigma_zz = -E alpha dT (small strain) to 1e-8: the difference GPS makes.
cylinder     the elastic thick cylinder of prm/thick_cylinder.prm (a = 100, b = 200 mm, Q2 on
             8 x 4 cells refined once, small strain) under p = 100 MPa with free ends. Lame:
             sigma_r,theta = A -/+ B / r^2, A = p a^2 / (b^2 - a^2), B = A b^2; with a uniform
             eps_zz = eps_0, sigma_zz = 2 nu A + E eps_0 is uniform too, and N = 0 gives
             eps_0 = -2 nu A / E (= -2 nu p a^2 / (E (b^2 - a^2)), the open-ended cylinder),
             sigma_zz = 0, u(r) = r / E (sigma_theta - nu sigma_r): u(a) = a / E ((1 + nu) B / a^2
             + (1 - nu) A), u(b) = 2 A b / E (plane strain: 2 (1 - nu^2) A b / E). Tolerance
             1e-5 relative for u and eps_0: the FE error of this mesh, which the same run in plane
             strain shows on u (printed, 2.4e-6). Along the radial line probe sigma_zz = nu
             (sigma_r + sigma_theta) + E eps_0 at every point (1e-8 p: a uniform eps_zz), so
             |sigma_zz| is nu times the FE error of sigma_r + sigma_theta (Lame: 2 A; 0.6 MPa at
             the bore), which is checked instead of a fixed tolerance.
np2          the cylinder on 2 ranks: u and stretch_z equal to np = 1 to 1e-10 of each column's
             largest magnitude, the axial force (round-off at equilibrium, 1e-7 N) to 1e-10 of
             p (b^2 - a^2) pi / 4 (the axial force and k_eu . du are sums over the ranks).
resume       the cylinder in 4 steps (p = 100 t), checkpoints every 2 steps, stopped after step 3
             and resumed from step 2: history identical to the uninterrupted run (lambda is in the
             checkpoint).

Usage: check_generalized_plane_strain.py AUSROLL SOURCE_DIR [CASE ...]
"""

import csv
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from checklist import Checklist  # noqa: E402
from check_thermal import history, last, run  # noqa: E402  (runs with one thread, MPI as root)

E, ALPHA, DT = 200000.0, 1.2e-5, 100.0  # the section of thermal_conduction.prm
GPS = "Model/Planar model=generalized plane strain"


def probe_stresses(directory, name):
    """{component: [values]} of the stress along the line probe NAME in its last file (the probe
    files carry 10 digits; the VTU fields are single precision)."""
    files = sorted(f for f in os.listdir(directory) if f.startswith(f"probe_{name}_"))
    with open(os.path.join(directory, files[-1])) as f:
        rows = list(csv.DictReader(f))
    return {c: [float(r["stress_" + c]) for r in rows] for c in ("xx", "yy", "zz", "xy")}


def section(temperature_settings):
    """--set entries of the heated section (on tests/checks/scenes/thermal_conduction.prm)."""
    return ["Geometry/Rectangle/Upper right corner=2, 1", "Geometry/Rectangle/Cells=4, 2",
            f"Thermal/Thermal expansion={ALPHA}", "Thermal/Number of conditions=0",
            "Loading/End time=1", "Loading/Number of steps=1", "Output/Interval=1",
            "Boundary conditions/Number of conditions=2",
            "Boundary conditions/Condition 0/Type=displacement",
            "Boundary conditions/Condition 0/Components=x",
            "Boundary conditions/Condition 0/Value=0",
            "Boundary conditions/Condition 1/Boundary id=2",
            "Boundary conditions/Condition 1/Type=displacement",
            "Boundary conditions/Condition 1/Components=y",
            "Boundary conditions/Condition 1/Value=0",
            "Postprocess/Line probes=diagonal: 0.1, 0.1, 1.9, 0.9, 7"] + temperature_settings


def main():
    ausroll, source = sys.argv[1], sys.argv[2]
    cases = sys.argv[3:] or ["free", "plane_strain", "cylinder", "np2", "resume"]
    strip = os.path.join(source, "tests", "checks", "scenes", "thermal_conduction.prm")
    cylinder = os.path.join(source, "prm", "thick_cylinder.prm")
    checks = Checklist()
    heated = section([f"Thermal/Initial temperature={20.0 + DT}"])
    scale = E * ALPHA * DT

    if "free" in cases:
        for label, settings in (("small strain", ["Model/Kinematics=small strain"]),
                                ("finite strain, Q1 F-bar",
                                 ["Model/Kinematics=finite strain", "Model/Polynomial degree=1",
                                  "Model/Volumetric locking treatment=F-bar"])):
            directory = "free_" + label.split(",")[0].replace(" ", "_")
            run(ausroll, strip, heated + settings + [GPS], directory)
            row = last(directory)
            stresses = probe_stresses(directory, "diagonal")
            worst = max(abs(s) for values in stresses.values() for s in values)
            theta = 1.0 + ALPHA * DT
            print(f"free ({label}): stretch_z - 1 = {row['stretch_z'] - 1:.15e} (alpha dT = "
                  f"{ALPHA * DT:.15e}), axial force {row['axial_force']:.3e} N, largest stress "
                  f"{worst:.3e} MPa")
            checks(f"free ({label}): lambda = 1 + alpha dT to 1e-12", abs(row["stretch_z"] - theta) < 1e-12)
            checks(f"free ({label}): stress-free (1e-8 E alpha dT)", worst < 1e-8 * scale)
            checks(f"free ({label}): axial force 0 (1e-8 E alpha dT A)",
                   abs(row["axial_force"]) < 1e-8 * scale * 2.0)

    if "plane_strain" in cases:
        run(ausroll, strip, heated + ["Model/Kinematics=small strain"], "plane_strain")
        stresses = probe_stresses("plane_strain", "diagonal")
        in_plane = max(abs(s) for c in ("xx", "yy", "xy") for s in stresses[c])
        zz = max(abs(s + scale) for s in stresses["zz"])
        print(f"plane strain: sigma_zz + E alpha dT: {zz:.3e} MPa (E alpha dT = {scale} MPa), "
              f"largest in-plane stress {in_plane:.3e} MPa")
        checks("plane strain: sigma_zz = -E alpha dT, in-plane stress-free (1e-8)",
               zz < 1e-8 * scale and in_plane < 1e-8 * scale)

    a, b, p = 100.0, 200.0, 100.0
    E_c, nu = 210000.0, 0.3
    A = p * a * a / (b * b - a * a)
    B = A * b * b
    elastic = ["Material/Yield criterion=none", "Boundary conditions/Condition 0/Value=100 * t",
               "Loading/End time=1", "Loading/Number of steps=1", "Output/Interval=1"]
    if "cylinder" in cases:
        run(ausroll, cylinder, elastic, "cylinder_plane_strain")
        row = last("cylinder_plane_strain")
        plane = abs(row["outer_ux"] / (2 * (1 - nu * nu) * A * b / E_c) - 1)
        run(ausroll, cylinder, elastic + [GPS], "cylinder")
        row = last("cylinder")
        eps0 = -2 * nu * A / E_c
        u_a = a / E_c * ((1 + nu) * B / (a * a) + (1 - nu) * A)
        u_b = 2 * A * b / E_c
        e_a = abs(row["inner_ux"] / u_a - 1)
        e_b = abs(row["outer_ux"] / u_b - 1)
        e_z = abs((row["stretch_z"] - 1) / eps0 - 1)
        probe = probe_stresses("cylinder", "radial")  # on the x axis: xx = r, yy = theta
        trace_error = max(abs(xx + yy - 2 * A) for xx, yy in zip(probe["xx"], probe["yy"]))
        relation = max(abs(zz - nu * (xx + yy) - E_c * eps0)
                       for xx, yy, zz in zip(probe["xx"], probe["yy"], probe["zz"]))
        zz = max(abs(s) for s in probe["zz"])
        print(f"cylinder: u(a) {row['inner_ux']:.9f} (Lame {u_a:.9f}, {e_a:.1e}), u(b) "
              f"{row['outer_ux']:.9f} ({u_b:.9f}, {e_b:.1e}), eps_zz {row['stretch_z'] - 1:.9e} "
              f"({eps0:.9e}, {e_z:.1e}), axial force {row['axial_force']:.2e} N; plane strain u(b) "
              f"error {plane:.1e}; along the radius max |sigma_zz| {zz:.3e} MPa, FE error of "
              f"sigma_r + sigma_theta {trace_error:.3e} MPa, |sigma_zz - nu (sigma_r + sigma_theta) "
              f"- E eps_0| {relation:.1e} MPa")
        checks("cylinder: u(a), u(b) and eps_zz of the open-ended Lame cylinder to 1e-5",
               max(e_a, e_b, e_z) < 1e-5)
        checks("cylinder: axial force 0 (1e-8 p (b^2 - a^2) pi / 4)",
               abs(row["axial_force"]) < 1e-8 * p * (b * b - a * a) * 0.785)
        checks("cylinder: sigma_zz = nu (sigma_r + sigma_theta) + E eps_0 at every probe point (1e-8 p)",
               relation < 1e-8 * p)
        checks("cylinder: |sigma_zz| <= nu x the FE error of sigma_r + sigma_theta (Lame: 2 A), below 1e-2 p",
               zz <= nu * trace_error + 1e-8 * p and trace_error < 1e-2 * p)
        checks("cylinder: the plane strain run of the mesh is as close (its FE error below 1e-5)",
               plane < 1e-5)

    if "np2" in cases:
        run(ausroll, cylinder, elastic + [GPS], "cylinder_np1")
        run(ausroll, cylinder, elastic + [GPS], "cylinder_np2", mpi=2)
        one, two = history("cylinder_np1"), history("cylinder_np2")
        worst = 0.0
        for column in ("inner_ux", "outer_ux", "stretch_z"):
            size = max(abs(float(r[column])) for r in one) or 1.0
            worst = max(worst, max(abs(float(r1[column]) - float(r2[column])) / size
                                   for r1, r2 in zip(one, two)))
        # the axial force at equilibrium is round-off (1e-7 N): against p times the section
        axial = max(abs(float(r1["axial_force"]) - float(r2["axial_force"])) for r1, r2 in zip(one, two))
        force = p * (b * b - a * a) * 0.785
        print(f"np2: largest relative difference {worst:.1e} (u, stretch_z), axial force "
              f"{axial / force:.1e} of p (b^2 - a^2) pi / 4")
        checks("np2: the history on 2 ranks equals np = 1 (1e-10)",
               len(one) == len(two) and worst < 1e-10 and axial < 1e-10 * force)

    if "resume" in cases:
        steps = elastic[:2] + ["Loading/End time=1", "Loading/Number of steps=4", GPS,
                               "Output/Interval=0",
                               "Checkpoint/Interval=2"]
        run(ausroll, cylinder, steps, "resume_whole")
        shutil.rmtree("resume_resumed", ignore_errors=True)
        first = run(ausroll, cylinder, steps + ["Checkpoint/Abort after step=3"], "resume_resumed")
        second = run(ausroll, cylinder, steps, "resume_resumed", extra=["--resume"])
        whole, resumed = history("resume_whole"), history("resume_resumed")
        same = second.returncode == 0 and len(whole) == len(resumed) and all(
            ra[c] == rb[c] for ra, rb in zip(whole, resumed) for c in ra if c != "wall_seconds")
        print(f"resume: {len(whole)} rows, stretch_z at the end {whole[-1]['stretch_z']}")
        checks("resume: the run stopped after step 3 (exit 99)", first.returncode == 99)
        checks("resume: resumed from step 2, history identical", same)

    return checks.exit_status()


if __name__ == "__main__":
    sys.exit(main())
