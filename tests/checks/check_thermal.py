#!/usr/bin/env python3
"""Thermal verification checks (the temperature field, Thermal subsection), each against a closed
form with its tolerance and the reason for it:

conduction   a strip held at 120 C at x = 0, insulated elsewhere (scenes/thermal_conduction.prm),
             against the erfc image series at t = 2 s; run with 40 and 20 steps. The error is the
             time discretisation's (measured 2026-12-07: 20/40/80/160/640 steps give 0.688,
             0.344, 0.172, 0.086, 0.0215 K; 20 or 80 cells instead of 40 change it by < 2e-4 K):
             backward Euler is first order, so the error must halve with the step (ratio 1.9 to
             2.1) and stay below 0.4 K (0.4 % of the temperature step) at 40 steps.
adiabatic    the 3D block in homogeneous uniaxial compression (scenes/thermal_block_3d.prm), J2
             with linear hardening, insulated: T = 20 + beta (sigma_0 a + H a^2 / 2) / (rho c) with
             a = (E eps - sigma_0) / (E + H). The trapezoidal plastic work is exact for linear
             hardening once plastic and the heat equation of a homogeneous source is exact, but the
             first plastic step starts below the yield stress: its trapezoid misses
             (sigma_0 - sigma_e) a_1 / 2. The check is run with the steps of the scene chosen
             so that step 1 ends exactly at yield (then every plastic step is exact): 1e-6.
free         the block heated to 120 C (T_ref = 20, alpha = 1.2e-5), free on its symmetry planes:
             corner displacement (theta - 1) (10, 5, 4), reactions zero; small and finite
             strain; 1e-9 (round-off of the Newton tolerance of the scene).
clamped      the same block at 100 C held at x = 10 in x: sigma_xx = -E alpha dT (201.6 MPa, below
             the yield stress 240), reaction F_x on x = 10 equal to E alpha dT 20 mm^2 (small
             strain, 1e-6: Newton tolerance), lateral corner displacement (1 + nu) alpha dT (5, 4).
plane strain the strip heated uniformly to 120 C, held in x at both ends: sigma_xx =
             -E alpha dT / (1 - nu) (eps_zz = 0), reaction on x = 20 per mm thickness; 1e-6.
cylinder     the thick cylinder of prm/thick_cylinder.prm (a = 100, b = 200 mm, plane strain,
             elastic) with its inner surface at 120 C and its outer at 20 C = T_ref: the steady
             logarithmic profile (3 backward-Euler steps of 1e5 s: the slowest mode decays by
             1e-9) and Timoshenko & Goodier's closed-form thermal stresses (Theory of Elasticity,
             3rd ed., sec. 151; sigma_z = nu (sigma_r + sigma_theta) - E alpha T for eps_z = 0)
             along the radial probe within 0.5 % of the largest stress (measured 2026-12-07:
             0.28 %, at the inner surface where the probe extrapolates the quadrature points);
             the heat flow through the quarter, (pi / 2) k dT / ln(b/a), to 1e-6.
coupling     the clamped block with all faces held at T = 20 + 80 t and a negligible heat capacity
             (specific heat 1 instead of 4.6e8: the temperature is uniform at every step): with Coupling/Iterations = 1 the mechanics of step n sees T(t_n-1)
             (reaction E alpha (T(t_n-1) - 20) A), with Iterations = 3 it sees T(t_n) and
             stops after the second heat solve (the temperature no longer changes): 1e-6.
np2          the conduction run on 2 MPI ranks: every history column within 1e-8 (relative to the
             column's largest magnitude) of the serial run (different partition, same algebra;
             AMG-preconditioned CG to 1e-12).
conductance  an elastic block (10 x 5 mm, scenes/block_slide.prm) pressed by a flat die at 200 C
             with h_c = 10 N/(mm s K), its base held at 20 C: the steady 1D state T_top =
             (h_c T_die + (k/L) T_base) / (h_c + k/L), heat from the die h_c (T_die - T_top) 10 mm
             = heat out through the base; 20 backward-Euler steps of 5 s decay the transient by
             1e-17, and the steady linear profile is exact in Q2: 1e-6.
friction     the same block slid under the die (mu = 0.2, v = 0.1 mm/s) in full slip, insulated,
             no conductance: the heat into the block is the partition 0.5 of mu |F_y| v (every
             node slips the die's travel once the sliding is steady); 1e-6.
dilatometry  the 3D block (free on its symmetry planes) with all faces cooled from 250 C to 20 C in 10
             steps (specific heat 1: uniform temperature), carbon 0.8 wt%, Phases on, Coupling/
             Iterations = 3 (the mechanics sees T(t_n)): the martensite fraction is Koistinen-
             Marburger's 1 - exp(-0.011 (Ms - T)) with Andrews' Ms = 539 - 423 C - 30.4 Mn -
             17.7 Ni - 12.1 Cr - 7.5 Mo (AISI 9310: 0.55, 3.25, 1.2, 0.12) below Ms, 0 above; the
             block stays stress-free and its corner moves by (theta - 1) L with theta = (1 + alpha
             (T - 20)) (1 + f dV/V)^(1/3), dV/V = 4.64 - 0.53 C per cent (finite strain; small
             strain: the sum alpha (T - 20) + (1 + f dV/V)^(1/3) - 1), to 1e-8 of 0.01 mm; the
             fraction to 1e-8: the interior temperature is the CG solution of the heat equation (to
             1e-7 K here, and df/dT <= b), the history has 10 digits. The Newton tolerance is 1e-8 N (1e-12 of the internal forces E alpha dT A
             ~ 1e4 N that cancel in the free block: 1e-10 is below their round-off).
adapted      the dilatometry block (finite strain) with the isothermal split (Coupling/Iterations = 1:
             the heat solve of step n writes T(t_n+1) into the points) and the mesh adapted every 2
             steps (Kelly): the re-equilibration after each mesh change is an equilibrium at the
             temperature the points were evaluated at, so it carries no thermal or transformation
             increment: every load step from the second on solves its own (at least one Newton
             solve; before 2026-12-08 the step after an adaptation had none, its increment having
             been solved in the re-equilibration), the re-equilibrations take at most one solve
             each (the convergence test's first iteration at a zero force level: the transferred
             uniform, stress-free state is in equilibrium), and the history equals the run on the
             fixed mesh (a uniform state is exact on every mesh): corner displacements to 1e-8 of
             0.01 mm, martensite fractions to 1e-8.
quenched     (ctest check/thermal_trip) Phases/Initial state = quenched: the dilatometry block at
             0.2 wt% C (Ms 364.7 C) starts at 250 C holding the Koistinen-Marburger fraction f_0 =
             1 - exp(-0.011 (Ms - 250)) = 0.717 in its stress-free reference and cools to 20 C:
             fractions from f_0 on, corner (theta_th ((1 + f dV/V) / (1 + f_0 dV/V))^(1/3) - 1) L
             (finite strain) and no reactions, to the tolerances of dilatometry.
reheat       the dilatometry block cooled to 50 C (T = 250 - 400 t up to t = 0.5) and heated again to 200 C:
             the martensite fraction keeps its largest value, 1 - exp(-b (Ms - 50)), while the block
             heats (irreversible), to 1e-8; the run interrupted at step 7 (during the heating,
             checkpoints every 2 steps) and resumed gives the same history to the last digit (the
             fraction and the carbon content travel in the checkpoint); on 2 MPI ranks every
             column within 1e-8 of the serial run (of the column's largest magnitude, at least
             0.1: the reactions of the free block are round-off, below 1e-5 N).
softening    temperature-dependent moduli and yield stress (Material entries as tables in T): the
             block of clamped (x held at 0 and 10, free laterally), all faces at T = 20 + 500 t
             (specific heat 1 and no plastic heating: uniform), Coupling/Iterations = 3 (the
             mechanics at T(t_n)),
             E = 20: 210000, 300: 190000, 600: 150000; nu = 20: 0.3, 600: 0.35;
             sigma_0 = 20: 240, 600: 120; perfectly plastic, 20 steps to 520 C. Uniaxial stress:
             small strain sigma_xx = -min(E(T) alpha dT, sigma_0(T)) (the secant law: while
             elastic E(T) alpha dT, once yielded the yield stress at T, the thermal strain still
             growing), the lateral corner displacement 5 ((1 + nu(T)) alpha dT) while elastic and
             5 (1.5 alpha dT - (0.5 - nu(T)) sigma_0(T) / E(T)) once plastic (eps_xx = 0 gives
             eps_p,xx = -alpha dT - sigma_xx / E(T), deviatoric flow); finite strain (logarithmic
             elastic strain, Kirchhoff yield): reaction theta^3 A min(E(T) ln theta, sigma_0(T)),
             theta = 1 + alpha dT. Three elastic steps, seventeen plastic; 1e-8 of sigma_0 A and
             of the lateral strain (the history's 10 digits; measured 2026-12-07: 8.6e-10).
bainite      the dilatometry block (carbon 0.8 wt%, Ms 110.9 C) held at 300 C for 120 s and then
             quenched to 20 C (8 steps of 30 s), with the TTT rows 250 C: 20 / 400 s and 350 C: 10 /
             200 s (start / finish; 15 / 300 s at 300 C): during the hold the bainite fraction is
             JMAK's 1 - exp(-k t^n) through (15 s, 1 %) and (300 s, 99 %) (the additivity rule is
             exact for a hold); after the quench the bainite stays and martensite forms from the
             austenite left, (1 - f_B) (1 - exp(-b (Ms - 20))); the corner moves by
             (theta_th (1 + f_M dV_M/V + f_B dV_B/V)^(1/3) - 1) L (finite strain; dV_B/V = 4.64 -
             1.43 C per cent), both to 1e-8 as dilatometry.
trip         (ctest check/thermal_trip) the dilatometry block cooled from 250 C to 20 C in 10 steps
             under a constant uniaxial traction sigma = 100 MPa on x = 10 (below the yield stress
             240 MPa), Phases/TRIP coefficient K = 1e-4 1/MPa, small strain: the stress is
             uniaxial and fixed by the load, so Leblond's TRIP strain integrates in closed form,
             eps_tp,xx = K sigma phi(f), eps_tp,yy = -K sigma phi(f) / 2 with phi(f) = f (1 - ln f)
             of the Koistinen-Marburger fraction f; the corner moves by L (alpha dT + theta_tr - 1
             + sigma/E + K sigma phi(f)) in x and L (alpha dT + theta_tr - 1 - nu sigma/E - K sigma
             phi(f) / 2) in y and z. The step integrates phi exactly (Delta phi from the fractions
             at both ends) and dev(sigma) is the load's at every step, so the only errors are the
             history's 10 digits and the Newton tolerance (1e-8 N on a stiffness E A / L ~ 4e5
             N/mm): 1e-6 of the TRIP strain K sigma = 1e-2 (measured 2026-12-07: see the output).
             The same run without TRIP (K = 0) gives the corner of the elastic closed form (no
             TRIP strain), to the same tolerance. Finite strain: the dead load fixes P, and the
             Kirchhoff stress of the return, tau_xx = sigma lambda_x / theta^3 (the inner model sees
             F / theta), changes with the stretch; the discrete law ln(lambda_x / theta) = tau_xx /
             E + sum over the steps of K (phi_n - phi_n-1) tau_xx,n (lateral: -nu tau / E - half the
             sum; Hencky elasticity, coaxial logarithmic strains add) with the history's
             stretches, to 1e-8 of K sigma (Newton to 1e-12 of the force level).
mixture      (ctest check/thermal_trip) the same block, K = 0, compressed in y (top face -0.4 t mm,
             perfectly plastic austenite sigma_0 = 240 MPa) while it cools through Ms with
             Phases/Martensite yield stress = 20: 1400, 300: 1100: every step is plastic and the
             reaction on y = 5 is A times the linear mixture (1 - f) 240 + f sigma_y,M(T) at the
             step's temperature and fraction (small strain; the multiplicative models see F / theta,
             theta = theta_th theta_tr, and P = theta^2 P_inner: total Lagrangian times theta
             lambda_y, the yield on S; updated Lagrangian lambda_x lambda_z, on the Cauchy stress;
             finite strain theta^3 / lambda_y, on the Kirchhoff stress; the stretches from the
             corner displacement);
             1e-8 of sigma_y,M A (the return map solves the yield condition to 1e-13, the history
             has 10 digits; Newton to 1e-12 of the force level: the default 1e-6 leaves 2e-7 in
             the reaction of the finite-strain models).
carbon_yield (ctest check/thermal_trip) pure martensite at two carbon contents: the block at 20 C
             from the start (faces held at 20 C, Initial state = quenched with Koistinen-Marburger
             coefficient 10 1/K: f_0 = 1 - exp(-10 (Ms - 20)) is 1 in double for C = 0.2 and 0.8,
             the stress-free reference), with
             Phases/Martensite yield stress = 413 + 1720*sqrt(C) (Krauss' fit, doc/theory.md
             section 8) and Martensite hardening modulus = 3000 + 2000*C + T, compressed in y
             (top face -0.1 t mm, 10 steps, small strain). The transformation strain is
             isotropic and stress-free, so the mechanical axial strain is eps_m = u_y/5 (the
             martensite of t = 0 is the reference: no transformation strain), and once yielded the uniaxial
             closed form of linear hardening |sigma| = (sigma_y,M(C) + H_M |eps_m|) / (1 + H_M/E);
             the reaction on y = 5 is A |sigma| in every plastic step, 1e-8 of sigma_y,M A (the
             return map solves the yield condition to 1e-13, the history has 10 digits, Newton
             to 1e-12 of the force level); the two carbon contents yield at their own
             sigma_y,M (different by 47 %).
trip_heat    (ctest check/thermal_trip) the TRIP dissipation and the latent heat in the heat
             source: the 3D block insulated (no thermal conditions: adiabatic, the source is
             homogeneous, so T is uniform) under a constant uniaxial traction sigma = 200 MPa on
             x = 10 (below the yield stress), TRIP coefficient K = 1e-4 1/MPa, Phases/TRIP heating
             = true, specific heat 4.6e6 (rho c = 0.0361 MPa/K: a rise of tens of K, so that the
             history's 10 digits resolve 1e-8 of it). (a) bainite: held at 300 C (above Ms), TTT
             rows 200 C: 15 / 300 s and 800 C: 15 / 300 s (the same times at every temperature:
             the JMAK fraction f_B(t) does not depend on the temperature rise), Bainite latent
             heat 1e8 mm^2/s^2 (0.1 J/g), 8 steps of 15 s: every step's TRIP strain is kappa dev
             sigma with dev sigma fixed by the dead load, so the dissipation of a step is
             K sigma^2 (phi(f_n) - phi(f_n-1)) exactly, and T(t_n) = 300 + (beta K sigma^2
             phi(f_B(t_n)) + rho L_B f_B(t_n)) / (rho c); (b) martensite: started at 20 C below
             Ms (Ms 110.9 C at 0.8 wt% C; Initial state = undercooled austenite): KM's f = 1 - exp(-b (Ms - 20)) forms in the first step,
             then the block is hotter and nothing more forms; Latent heat 1e8 mm^2/s^2: T = 20 +
             (beta K sigma^2 phi(f) + rho L f) / (rho c) from the first step on. Both to 1e-8 of
             the final rise (backward Euler of a homogeneous source is exact; the history's 10
             digits of T ~ 300 C resolve 1e-7 K; the kinetics use the
             committed temperature, which is not the rise's: JMAK is temperature-independent
             here and KM's fraction is the first step's); (c) (a) with TRIP heating = false
             and no latent heat: T stays 300 C (1e-6 K; the TRIP dissipation is not heat, as
             before this option).
stabilisation (ctest check/thermal_trip) the mechanical stabilisation of austenite: the 3D block at
             250 C (above Ms) compressed by a traction growing to 300 MPa at t = 1 (linear
             hardening H = 1000 from 240 MPa: alpha = 0.06 exactly, uniaxial), unloaded at t =
             1.1, then cooled with all faces at 250 - 230 (t - 1) C to 20 C (specific heat 1, the
             mechanics at T(t_n), Taylor-Quinney 0), with Phases/Mechanical stabilisation =
             true, Stabilisation energy 500 J/mol (a larger shift than the default's, to see it),
             eps_0 0.1, S 6.94: the fraction is KM's with the shifted Ms, 1 - exp(-b (Ms(C) -
             G_0/S (sqrt(1 + alpha/eps_0) - 1) - T)), to 1e-8 (the fraction column has 10
             digits); the same run without the option has the unshifted Ms (1e-8), and the
             shift lowers the final fraction.
resume       the conduction run interrupted after step 25 (checkpoints every 10 steps) and resumed
             gives the same history as the uninterrupted run, to the last digit.

Usage: check_thermal.py AUSROLL SOURCE_DIR [CASE ...] (without cases: all but trip and mixture)
"""

import csv
import math
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from checklist import Checklist, ausroll_command  # noqa: E402

E, NU, SIGMA0, H = 210000.0, 0.3, 240.0, 1000.0  # the block's material
RHO_C = 7.85e-9 * 4.6e8
ALPHA = 1.2e-5
CARBON = 0.8  # wt%, the phase cases
# Andrews' martensite start (the default of Phases/Martensite start temperature: AISI 9310 with
# 0.55 Mn, 3.25 Ni, 1.2 Cr, 0.12 Mo), degrees C
MS = 539 - 423 * CARBON - 30.4 * 0.55 - 17.7 * 3.25 - 12.1 * 1.2 - 7.5 * 0.12


def faces_held_at(value):
    """--set entries holding all six faces of the 3D block at the temperature expression value."""
    entries = ["Thermal/Number of conditions=6"]
    for face in range(6):
        entries += [f"Thermal/Condition {face}/Boundary id={face}", f"Thermal/Condition {face}/Type=temperature",
                    f"Thermal/Condition {face}/Value={value}"]
    return entries


def martensite(coolest):
    """Koistinen-Marburger fraction after cooling to the temperature coolest (b = 0.011 1/K)."""
    return 1.0 - math.exp(-0.011 * (MS - coolest)) if coolest < MS else 0.0


def phase_block(profile):
    """--set entries of the free 3D block with phases, its faces at the temperature profile(t),
    the temperature uniform at every step (specific heat 1), the mechanics at T(t_n) (Coupling/
    Iterations = 3) and a Newton tolerance of 1e-8 N (see dilatometry)."""
    return ["Boundary conditions/Number of conditions=3", f"Thermal/Thermal expansion={ALPHA}",
            "Thermal/Initial temperature=250", "Thermal/Specific heat=1", "Phases/Enabled=true",
            f"Phases/Carbon content={CARBON}", "Coupling/Iterations=3", "Loading/Number of steps=10",
            "Solver/Absolute residual tolerance=1e-8"] + faces_held_at(profile)


def run(ausroll, prm, settings, directory, extra=(), mpi=0):
    command = ausroll_command(ausroll, prm, list(settings) + [f"Output/Directory={directory}"])
    command += list(extra)
    if mpi:
        command = ["mpirun", "-np", str(mpi)] + command
    # as scripts/setup.sh: OpenMPI as root, two ranks sharing the cores of a parallel ctest
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1", DEAL_II_NUM_THREADS="1")
    result = subprocess.run(command, capture_output=True, text=True, env=env)
    aborts = any(entry.startswith("Checkpoint/Abort after step=") for entry in settings)
    if result.returncode != 0 and "--resume" not in extra and not aborts:
        print(result.stdout[-3000:])
        print(result.stderr[-3000:])
        raise SystemExit(f"FAIL {' '.join(command)} exited with {result.returncode}")
    return result


def history(directory):
    with open(os.path.join(directory, "history.csv")) as f:
        rows = list(csv.DictReader(f))
    return rows


def last(directory):
    return {k: float(v) for k, v in history(directory)[-1].items()}


def temperatures(directory):
    """(x, T) of every output point of the last VTU in DIRECTORY/solution.pvd."""
    import xml.etree.ElementTree as ET
    from vtkmodules.vtkIOXML import vtkXMLPUnstructuredGridReader
    datasets = ET.parse(os.path.join(directory, "solution.pvd")).getroot().findall(".//DataSet")
    reader = vtkXMLPUnstructuredGridReader()
    reader.SetFileName(os.path.join(directory, datasets[-1].get("file")))
    reader.Update()
    grid = reader.GetOutput()
    T = grid.GetPointData().GetArray("temperature")
    return [(grid.GetPoint(i)[0], T.GetValue(i)) for i in range(grid.GetNumberOfPoints())]


def strip_temperature(x, t, length=20.0, kappa=45.0 / RHO_C):
    """20 C strip of LENGTH, x = 0 held at 120 C from t = 0, x = LENGTH insulated: the image
    series of the semi-infinite erfc solution (the n-th pair of images mirrors the insulated and
    the held end; six pairs reach round-off for 2 sqrt(kappa t) <= LENGTH)."""
    d = 2.0 * math.sqrt(kappa * t)
    series = sum((-1) ** n * (math.erfc((2 * n * length + x) / d)
                              + math.erfc((2 * (n + 1) * length - x) / d)) for n in range(6))
    return 20.0 + 100.0 * series


def conduction_error(ausroll, prm, steps, directory, settings=()):
    run(ausroll, prm, [f"Loading/Number of steps={steps}", f"Output/Interval={steps}"] + list(settings),
        directory)
    return max(abs(T - strip_temperature(x, 2.0)) for x, T in temperatures(directory))


def main():
    ausroll, source = sys.argv[1], sys.argv[2]
    cases = sys.argv[3:] or ["conduction", "adiabatic", "free", "clamped", "plane_strain",
                             "cylinder", "coupling", "dilatometry", "adapted", "reheat", "conductance", "friction",
                             "softening", "bainite", "np2", "resume"]
    scenes = os.path.join(source, "tests", "checks", "scenes")
    strip = os.path.join(scenes, "thermal_conduction.prm")
    block = os.path.join(scenes, "thermal_block_3d.prm")
    checks = Checklist()

    if "conduction" in cases:
        e40 = conduction_error(ausroll, strip, 40, "conduction_40")
        e20 = conduction_error(ausroll, strip, 20, "conduction_20")
        print(f"conduction: max |T - T_erfc| = {e40:.4f} K (40 steps), {e20:.4f} K (20 steps), "
              f"ratio {e20 / e40:.3f}")
        checks("conduction: error below 0.4 K at 40 steps", e40 < 0.4)
        checks("conduction: first order in time (error ratio 1.9 .. 2.1)", 1.9 < e20 / e40 < 2.1)

    if "adiabatic" in cases:
        # eps = 0.004 t; step 1 ends exactly at yield: t_1 = sigma_0 / (0.004 E)
        t1 = SIGMA0 / (0.004 * E)
        steps = 8
        run(ausroll, block, ["Loading/End time=" + repr(steps * t1), f"Loading/Number of steps={steps}"],
            "adiabatic")
        rows = history("adiabatic")
        worst = 0.0
        for row in rows[1:]:
            eps = 0.004 * float(row["time"])
            a = max(0.0, (E * eps - SIGMA0) / (E + H))
            expected = 20.0 + 0.9 * (SIGMA0 * a + 0.5 * H * a * a) / RHO_C
            worst = max(worst, abs(float(row["T_mean"]) - expected) / (expected - 20.0 + 1e-300)
                        if a > 0 else abs(float(row["T_mean"]) - 20.0))
            spread = float(row["T_max"]) - float(row["T_min"])
            worst = max(worst, spread / max(expected - 20.0, 1e-300) if a > 0 else spread)
        final = float(rows[-1]["T_mean"]) - 20.0
        # the reported plastic heating rate integrates to the heat content of the block (200 mm^3)
        heat = sum(float(r["heat_plastic"]) * (float(r["time"]) - float(p["time"]))
                   for p, r in zip(rows, rows[1:]))
        content = RHO_C * final * 200.0
        print(f"adiabatic: temperature rise {final:.6f} K, worst relative deviation {worst:.2e}; "
              f"plastic heat {heat:.6f}, heat content {content:.6f} N mm")
        checks("adiabatic: int heat_plastic dt = rho c dT V to 1e-6", abs(heat - content) < 1e-6 * content)
        checks("adiabatic: dT = beta W_p / (rho c) to 1e-6, homogeneous", worst < 1e-6 and final > 0.3)

    free_settings = ["Boundary conditions/Number of conditions=3", "Thermal/Initial temperature=120",
                     f"Thermal/Thermal expansion={ALPHA}", "Loading/Number of steps=1"]
    if "free" in cases:
        for kinematics in ["small strain", "finite strain"]:
            directory = "free_" + kinematics.replace(" ", "_")
            run(ausroll, block, free_settings + [f"Model/Kinematics={kinematics}"], directory)
            row = last(directory)
            stretch = ALPHA * 100.0
            deviation = max(abs(row["corner_ux"] - stretch * 10), abs(row["corner_uy"] - stretch * 5),
                            abs(row["corner_uz"] - stretch * 4)) / (stretch * 10)
            reactions = max(abs(row[f"reaction_{b}_{c}"]) for b in (1, 3) for c in "xyz")
            print(f"free ({kinematics}): corner displacement deviation {deviation:.2e}, "
                  f"largest reaction {reactions:.2e} N")
            checks(f"free ({kinematics}): expands by (theta - 1) L to 1e-9", deviation < 1e-9)
            checks(f"free ({kinematics}): stress-free (reactions below 1e-9 E alpha dT A)",
                   reactions < 1e-9 * E * ALPHA * 100 * 20)

    if "clamped" in cases:
        run(ausroll, block, free_settings[2:] + ["Thermal/Initial temperature=100",
                                                 "Boundary conditions/Condition 3/Boundary id=1",
                                                 "Boundary conditions/Condition 3/Components=x",
                                                 "Boundary conditions/Condition 3/Value=0"], "clamped")
        row = last("clamped")
        sigma = -E * ALPHA * 80.0
        force = row["reaction_1_x"]
        lateral = (1 + NU) * ALPHA * 80.0
        print(f"clamped: reaction on x = 10: {force:.6f} N, expected magnitude {abs(sigma) * 20:.6f} N; "
              f"corner u_y {row['corner_uy']:.6e}, expected {lateral * 5:.6e}")
        checks("clamped: |F_x| = E alpha dT A to 1e-6", abs(abs(force) - abs(sigma) * 20) < 1e-6 * abs(sigma) * 20)
        checks("clamped: lateral expansion (1 + nu) alpha dT to 1e-6",
               abs(row["corner_uy"] - lateral * 5) < 1e-6 * lateral * 5
               and abs(row["corner_uz"] - lateral * 4) < 1e-6 * lateral * 4)

    if "softening" in cases:
        tables = {"Young's modulus": [(20, 210000.0), (300, 190000.0), (600, 150000.0)],
                  "Poisson's ratio": [(20, 0.3), (600, 0.35)], "Yield stress": [(20, 240.0), (600, 120.0)]}

        def at(name, t):
            rows = tables[name]
            for (t0, v0), (t1, v1) in zip(rows, rows[1:]):
                if t <= t1:
                    return v0 + (v1 - v0) * (t - t0) / (t1 - t0)
            return rows[-1][1]

        settings = [f"Thermal/Thermal expansion={ALPHA}", "Thermal/Specific heat=1", "Coupling/Iterations=3",
                    "Loading/Number of steps=20", "Material/Hardening modulus=0",
                    "Thermal/Taylor-Quinney coefficient=0",
                    "Boundary conditions/Condition 3/Boundary id=1",
                    "Boundary conditions/Condition 3/Components=x",
                    "Boundary conditions/Condition 3/Value=0"] + faces_held_at("20+500*t")
        settings += [f"Material/{name}=" + ", ".join(f"{t}: {v}" for t, v in rows) for name, rows in tables.items()]
        for kinematics in ["small strain", "finite strain"]:
            directory = "softening_" + kinematics.replace(" ", "_")
            run(ausroll, block, settings + [f"Model/Kinematics={kinematics}"], directory)
            worst, elastic, plastic = 0.0, 0, 0
            for row in history(directory)[1:]:
                t = float(row["T_mean"])
                e, nu, s0 = at("Young's modulus", t), at("Poisson's ratio", t), at("Yield stress", t)
                strain = ALPHA * (t - 20.0)
                if kinematics == "small strain":
                    yielded = e * strain > s0
                    stress = s0 if yielded else e * strain
                    force = stress * 20.0
                    uy = 5.0 * ((1.5 * strain - (0.5 - nu) * s0 / e) if yielded else (1 + nu) * strain)
                    worst = max(worst, abs(float(row["corner_uy"]) - uy) / (5.0 * strain))
                else:
                    theta = 1.0 + strain
                    yielded = e * math.log(theta) > s0
                    force = theta ** 3 * 20.0 * min(e * math.log(theta), s0)
                elastic, plastic = elastic + (not yielded), plastic + yielded
                worst = max(worst, abs(abs(float(row["reaction_1_x"])) - force) / (240.0 * 20.0))
            print(f"softening ({kinematics}): {elastic} elastic and {plastic} plastic steps up to "
                  f"{t:.1f} C, worst relative deviation {worst:.2e}")
            checks(f"softening ({kinematics}): reaction (and lateral strain) at E(T), nu(T), sigma_0(T) to 1e-8",
                   worst < 1e-8 and elastic >= 3 and plastic >= 15)

    if "plane_strain" in cases:
        run(ausroll, strip, ["Thermal/Initial temperature=120", f"Thermal/Thermal expansion={ALPHA}",
                             "Thermal/Number of conditions=0", "Loading/Number of steps=1",
                             "Boundary conditions/Number of conditions=3",
                             "Boundary conditions/Condition 0/Type=displacement",
                             "Boundary conditions/Condition 0/Components=x",
                             "Boundary conditions/Condition 0/Value=0",
                             "Boundary conditions/Condition 1/Boundary id=1",
                             "Boundary conditions/Condition 1/Type=displacement",
                             "Boundary conditions/Condition 1/Components=x",
                             "Boundary conditions/Condition 1/Value=0",
                             "Boundary conditions/Condition 2/Boundary id=2",
                             "Boundary conditions/Condition 2/Type=displacement",
                             "Boundary conditions/Condition 2/Components=y",
                             "Boundary conditions/Condition 2/Value=0",
                             "Postprocess/Reaction boundaries=1"], "plane_strain")
        row = last("plane_strain")
        expected = 200000.0 * ALPHA * 100.0 / (1 - NU) * 1.0  # |sigma_xx| times the 1 mm height
        print(f"plane strain: reaction on x = 20: {row['reaction_1_x']:.6f} N/mm, expected magnitude "
              f"{expected:.6f}")
        checks("plane strain: |F_x| = E alpha dT / (1 - nu) h to 1e-6",
               abs(abs(row["reaction_1_x"]) - expected) < 1e-6 * expected)

    if "cylinder" in cases:
        run(ausroll, os.path.join(source, "prm", "thick_cylinder.prm"), [
            "Boundary conditions/Condition 0/Value=0", "Material/Yield criterion=none",
            "Thermal/Enabled=true", f"Thermal/Thermal expansion={ALPHA}", "Thermal/Number of conditions=2",
            "Thermal/Condition 0/Boundary id=0", "Thermal/Condition 0/Type=temperature",
            "Thermal/Condition 0/Value=120", "Thermal/Condition 1/Boundary id=1",
            "Thermal/Condition 1/Type=temperature", "Thermal/Condition 1/Value=20", "Loading/End time=3e5",
            "Loading/Number of steps=3", "Output/Interval=3", "Output/Verbosity=quiet"], "cylinder")
        a, b, dT, e = 100.0, 200.0, 100.0, 210000.0
        log_ba = math.log(b / a)
        scale = ALPHA * e * dT / (2 * (1 - NU) * log_ba)
        ratio = a * a / (b * b - a * a)
        with open(os.path.join("cylinder", "probe_radial_0001.csv")) as f:
            probe = list(csv.DictReader(f))
        largest, error = 0.0, 0.0
        for row in probe:
            r = float(row["x"])
            s_r = scale * (-math.log(b / r) - ratio * (1 - b * b / (r * r)) * log_ba)
            s_t = scale * (1 - math.log(b / r) - ratio * (1 + b * b / (r * r)) * log_ba)
            s_z = NU * (s_r + s_t) - ALPHA * e * dT * math.log(b / r) / log_ba
            largest = max(largest, abs(s_r), abs(s_t), abs(s_z))
            error = max(error, abs(float(row["stress_xx"]) - s_r), abs(float(row["stress_yy"]) - s_t),
                        abs(float(row["stress_zz"]) - s_z))
        heat = last("cylinder")["heat_condition_0"]
        exact_heat = math.pi / 2 * 45.0 * dT / log_ba
        print(f"cylinder: largest stress deviation {error:.4f} MPa of {largest:.2f} MPa "
              f"({error / largest:.2e}); heat flow {heat:.4f}, exact {exact_heat:.4f} N mm/s")
        checks("cylinder: Timoshenko thermal stresses within 0.5 %", error < 0.005 * largest)
        checks("cylinder: steady heat flow (pi/2) k dT / ln(b/a) to 1e-6",
               abs(heat - exact_heat) < 1e-6 * exact_heat)

    if "coupling" in cases:
        ramp = [f"Thermal/Thermal expansion={ALPHA}", "Thermal/Specific heat=1",
                "Boundary conditions/Number of conditions=4", "Boundary conditions/Condition 3/Boundary id=1",
                "Boundary conditions/Condition 3/Components=x",
                "Boundary conditions/Condition 3/Value=0"] + faces_held_at("20 + 80 * t")
        for iterations, lag in ((1, 1), (3, 0)):
            directory = f"coupling_{iterations}"
            result = run(ausroll, block, ramp + [f"Coupling/Iterations={iterations}",
                                                 "Output/Verbosity=verbose"], directory)
            rows = history(directory)
            worst = 0.0
            for n in range(1, len(rows)):
                t_seen = float(rows[n - lag]["time"])
                expected = -E * ALPHA * 80.0 * t_seen * 20.0
                worst = max(worst, abs(float(rows[n]["reaction_1_x"]) - expected) / (E * ALPHA * 80.0 * 20.0))
            solves = result.stdout.count("coupling: heat solve")
            print(f"coupling (Iterations = {iterations}): largest deviation {worst:.2e} of E alpha 80 K A; "
                  f"{solves} repeated-split heat solves logged")
            checks(f"coupling (Iterations = {iterations}): mechanics at T(t_n-{lag}) to 1e-6", worst < 1e-6)
            if iterations > 1:
                checks("coupling: two heat solves per step (the second changes nothing)", solves == 2 * (len(rows) - 1))

    if "dilatometry" in cases:
        dv = (4.64 - 0.53 * CARBON) / 100.0
        cool = phase_block("250 - 230 * t")
        for kinematics in ["small strain", "finite strain"]:
            directory = "dilatometry_" + kinematics.replace(" ", "_")
            run(ausroll, block, cool + [f"Model/Kinematics={kinematics}"], directory)
            rows = history(directory)
            worst, worst_f, f_end = 0.0, 0.0, 0.0
            for row in rows[1:]:
                T = 250.0 - 230.0 * float(row["time"])
                f = martensite(T)
                theta_tr = (1.0 + f * dv) ** (1.0 / 3.0)
                if kinematics == "finite strain":
                    stretch = (1.0 + ALPHA * (T - 20.0)) * theta_tr - 1.0
                else:
                    stretch = ALPHA * (T - 20.0) + theta_tr - 1.0
                for c, length in (("x", 10.0), ("y", 5.0), ("z", 4.0)):
                    worst = max(worst, abs(float(row[f"corner_u{c}"]) - stretch * length) / 0.01)
                for column in ("martensite_min", "martensite_max", "martensite_mean"):
                    worst_f = max(worst_f, abs(float(row[column]) - f))
                f_end = f
            reactions = max(abs(float(rows[-1][f"reaction_{b}_{c}"])) for b in (1, 3) for c in "xyz")
            print(f"dilatometry ({kinematics}): Ms {MS:.2f} C, final martensite {f_end:.6f}, worst corner "
                  f"deviation {worst:.2e} of 0.01 mm, worst fraction deviation {worst_f:.2e}, "
                  f"largest reaction {reactions:.2e} N")
            checks(f"dilatometry ({kinematics}): corner (theta_th theta_tr - 1) L to 1e-8 of 0.01 mm",
                   worst < 1e-8 and f_end > 0.5)
            checks(f"dilatometry ({kinematics}): Koistinen-Marburger fraction to 1e-8", worst_f < 1e-8)
            checks(f"dilatometry ({kinematics}): stress-free (reactions below 1e-6 N)", reactions < 1e-6)

    if "adapted" in cases:
        split = phase_block("250 - 230 * t") + ["Model/Kinematics=finite strain", "Coupling/Iterations=1"]
        adapt = ["Adaptivity/Indicators=Kelly", "Adaptivity/Interval=2", "Adaptivity/Maximum level=2"]
        run(ausroll, block, split, "adapted_fixed")
        result = run(ausroll, block, split + adapt, "adapted")
        fixed, rows = history("adapted_fixed"), history("adapted")
        adaptations = sum(1 for a, b in zip(rows, rows[1:]) if a["dofs"] != b["dofs"])
        step_solves = sum(int(row["newton_iterations"]) for row in rows)
        all_solves = int(re.search(r"assemblies: \d+: \d+ at the start of a solve \([^)]*\), (\d+) after a "
                                   r"linear solve", result.stdout).group(1))
        lazy = [int(row["step"]) for row in rows[2:] if int(row["newton_iterations"]) == 0]
        worst, worst_f = 0.0, 0.0
        for a, b in zip(fixed, rows):
            for c in "xyz":
                worst = max(worst, abs(float(a[f"corner_u{c}"]) - float(b[f"corner_u{c}"])) / 0.01)
            worst_f = max(worst_f, abs(float(a["martensite_mean"]) - float(b["martensite_mean"])))
        print(f"adapted: {adaptations} mesh changes ({rows[0]['dofs']} -> {rows[-1]['dofs']} DoFs), "
              f"{step_solves} solves in the steps, {all_solves - step_solves} in the re-equilibrations, "
              f"steps without a solve: {lazy}; against the fixed mesh: corner {worst:.2e} of 0.01 mm, "
              f"fraction {worst_f:.2e}")
        checks("adapted: the mesh changes at least twice", adaptations >= 2)
        checks("adapted: every step from the second on solves its own thermal increment", not lazy)
        checks("adapted: at most one solve per re-equilibration", all_solves - step_solves <= adaptations)
        checks("adapted: history of the fixed mesh (corner to 1e-8 of 0.01 mm, fraction to 1e-8)",
               len(rows) == len(fixed) and worst < 1e-8 and worst_f < 1e-8)

    if "quenched" in cases:
        # Phases/Initial state = quenched: a low-carbon block (Ms(0.2) = 364.7 C) starts at 250 C
        # with the Koistinen-Marburger fraction f_0 of that temperature, stress-free, and cools to
        # 20 C: the transformation strain counts from f_0
        carbon = 0.2
        ms = 539 - 423 * carbon - 30.4 * 0.55 - 17.7 * 3.25 - 12.1 * 1.2 - 7.5 * 0.12
        dv = (4.64 - 0.53 * carbon) / 100.0
        f_0 = 1.0 - math.exp(-0.011 * (ms - 250.0))
        settings = phase_block("250 - 230 * t") + [f"Phases/Carbon content={carbon}",
                                                   "Phases/Initial state=quenched",
                                                   "Model/Kinematics=finite strain"]
        run(ausroll, block, settings, "quenched")
        rows = history("quenched")
        worst, worst_f = 0.0, 0.0
        for row in rows:
            T = 250.0 - 230.0 * float(row["time"])
            f = 1.0 - math.exp(-0.011 * (ms - T))
            stretch = (1.0 + ALPHA * (T - 20.0)) * ((1.0 + f * dv) / (1.0 + f_0 * dv)) ** (1.0 / 3.0) - 1.0
            for column in ("martensite_min", "martensite_max", "martensite_mean"):
                worst_f = max(worst_f, abs(float(row[column]) - f))
            if row is rows[0]:
                continue  # the initial row: not evaluated yet (the reference temperature's state)
            for c, length in (("x", 10.0), ("y", 5.0), ("z", 4.0)):
                worst = max(worst, abs(float(row[f"corner_u{c}"]) - stretch * length) / 0.01)
        reactions = max(abs(float(rows[-1][f"reaction_{b}_{c}"])) for b in (1, 3) for c in "xyz")
        print(f"quenched: Ms {ms:.2f} C, f_0 {f_0:.6f}, final martensite {float(rows[-1]['martensite_mean']):.6f}, "
              f"worst corner deviation {worst:.2e} of 0.01 mm, worst fraction deviation {worst_f:.2e}, "
              f"largest reaction {reactions:.2e} N")
        checks("quenched: initial fraction f_0 = KM(Ms - 250 C) and every step's KM fraction to 1e-8", worst_f < 1e-8)
        checks("quenched: corner (theta_th ((1 + f dV) / (1 + f_0 dV))^(1/3) - 1) L to 1e-8 of 0.01 mm", worst < 1e-8)
        checks("quenched: stress-free (reactions below 1e-6 N)", reactions < 1e-6)

    if "bainite" in cases:
        n = math.log(math.log(0.01) / math.log(0.99)) / math.log(300.0 / 15.0)
        k = -math.log(0.99) / 15.0 ** n
        dv_m, dv_b = (4.64 - 0.53 * CARBON) / 100.0, (4.64 - 1.43 * CARBON) / 100.0
        run(ausroll, block, phase_block("t <= 120 ? 300 : 20") + [
            "Thermal/Initial temperature=300", "Loading/End time=240", "Loading/Number of steps=8",
            "Model/Kinematics=finite strain", "Phases/Bainite start times=250: 20, 350: 10",
            "Phases/Bainite finish times=250: 400, 350: 200"], "bainite")
        worst, worst_f = 0.0, 0.0
        for row in history("bainite")[1:]:
            t = float(row["time"])
            f_b = 1.0 - math.exp(-k * min(t, 120.0) ** n)
            T = 300.0 if t <= 120.0 else 20.0
            f_m = (1.0 - f_b) * martensite(T)
            stretch = (1.0 + ALPHA * (T - 20.0)) * (1.0 + f_m * dv_m + f_b * dv_b) ** (1.0 / 3.0) - 1.0
            for c, length in (("x", 10.0), ("y", 5.0), ("z", 4.0)):
                worst = max(worst, abs(float(row[f"corner_u{c}"]) - stretch * length) / 0.01)
            worst_f = max(worst_f, abs(float(row["bainite_mean"]) - f_b), abs(float(row["martensite_mean"]) - f_m))
        print(f"bainite: at the quench {f_b:.6f} bainite, at 20 C {f_m:.6f} martensite; worst corner deviation "
              f"{worst:.2e} of 0.01 mm, worst fraction deviation {worst_f:.2e}")
        checks("bainite: JMAK fraction in the hold, martensite from the austenite left, to 1e-8",
               worst_f < 1e-8 and 0.2 < f_b < 0.9 and f_m > 0.1)
        checks("bainite: corner (theta_th theta_tr - 1) L to 1e-8 of 0.01 mm", worst < 1e-8)

    if "reheat" in cases:
        cycle = phase_block("t <= 0.5 ? 250 - 400 * t : 50 + 300 * (t - 0.5)") + [
            "Model/Kinematics=finite strain", "Checkpoint/Interval=2"]
        run(ausroll, block, cycle, "reheat_whole")
        rows = history("reheat_whole")
        coolest, worst_f = 250.0, 0.0
        for row in rows[1:]:
            t = float(row["time"])
            coolest = min(coolest, 250.0 - 400.0 * t if t <= 0.5 else 50.0 + 300.0 * (t - 0.5))
            worst_f = max(worst_f, abs(float(row["martensite_mean"]) - martensite(coolest)))
        print(f"reheat: fraction at the end {float(rows[-1]['martensite_mean']):.6f} (at 50 C "
              f"{martensite(50.0):.6f}), worst deviation {worst_f:.2e}")
        checks("reheat: the fraction keeps its largest value while heating (1e-8)", worst_f < 1e-8)
        shutil.rmtree("reheat_resumed", ignore_errors=True)
        first = run(ausroll, block, cycle + ["Checkpoint/Abort after step=7"], "reheat_resumed")
        checks("reheat: the first run stopped as asked (exit 99)", first.returncode == 99)
        second = run(ausroll, block, cycle, "reheat_resumed", extra=["--resume"])
        b = history("reheat_resumed")
        checks("reheat: resumed during the heating, history identical",
               second.returncode == 0 and len(rows) == len(b)
               and all(ra[c] == rb[c] for ra, rb in zip(rows, b) for c in ra if c != "wall_seconds"))
        run(ausroll, block, cycle, "reheat_np2", mpi=2)
        c = history("reheat_np2")
        worst = 0.0
        for column in rows[0].keys():
            if column == "wall_seconds":
                continue
            # the reactions of the free block are round-off (below 1e-5 N): a floor of 0.1
            scale = max(max(abs(float(r[column])) for r in rows), 0.1)
            for ra, rc in zip(rows, c):
                worst = max(worst, abs(float(ra[column]) - float(rc[column])) / scale)
        print(f"reheat: np = 2 against np = 1, largest relative difference {worst:.2e}")
        checks("reheat: np = 2 equals np = 1 to 1e-8", len(rows) == len(c) and worst < 1e-8)

    if "trip" in cases:
        sigma, K = 100.0, 1e-4
        dv = (4.64 - 0.53 * CARBON) / 100.0
        load = phase_block("250 - 230 * t") + [
            "Boundary conditions/Number of conditions=4", "Boundary conditions/Condition 3/Boundary id=1",
            "Boundary conditions/Condition 3/Type=traction", f"Boundary conditions/Condition 3/Value={sigma}; 0; 0"]
        for k in (K, 0.0):
            directory = f"trip_{k:g}"
            run(ausroll, block, load + [f"Phases/TRIP coefficient={k}"], directory)
            worst, phi_end = 0.0, 0.0
            for row in history(directory)[1:]:
                T = 250.0 - 230.0 * float(row["time"])
                f = martensite(T)
                phi = f * (1.0 - math.log(f)) if f > 0.0 else 0.0
                free = ALPHA * (T - 20.0) + (1.0 + f * dv) ** (1.0 / 3.0) - 1.0
                axial = free + sigma / E + k * sigma * phi
                lateral = free - NU * sigma / E - 0.5 * k * sigma * phi
                for c, length, strain in (("x", 10.0, axial), ("y", 5.0, lateral), ("z", 4.0, lateral)):
                    worst = max(worst, abs(float(row[f"corner_u{c}"]) - strain * length) / (length * K * sigma))
                phi_end = phi
            print(f"trip (K = {k:g} 1/MPa): final phi(f) {phi_end:.6f}, TRIP strain {k * sigma * phi_end:.6e}, "
                  f"worst corner deviation {worst:.2e} of L K sigma")
            checks(f"trip (K = {k:g}): corner strain thermal + transformation + elastic + K sigma phi(f) to 1e-6",
                   worst < 1e-6 and phi_end > 0.5)

        # finite strain: the dead load gives the Kirchhoff stress of the inner model, tau_xx =
        # sigma lambda_x / theta^3 (P = theta^2 tau F_inner^-T), which changes with the stretch: the
        # discrete law, ln(lambda / theta) = tau / E + sum_m K (phi_m - phi_m-1) tau_m (axial; lateral
        # -nu tau / E - half the sum), checked with the stretches of the history
        directory = "trip_finite_strain"
        run(ausroll, block, load + [f"Phases/TRIP coefficient={K}", "Model/Kinematics=finite strain",
                                    "Solver/Residual tolerance=1e-12"], directory)
        worst, trip_sum, phi_old = 0.0, 0.0, 0.0
        for row in history(directory)[1:]:
            T = 250.0 - 230.0 * float(row["time"])
            f = martensite(T)
            phi = f * (1.0 - math.log(f)) if f > 0.0 else 0.0
            theta = (1.0 + ALPHA * (T - 20.0)) * (1.0 + f * dv) ** (1.0 / 3.0)
            lx, ly, lz = (1.0 + float(row[f"corner_u{c}"]) / length for c, length in (("x", 10.0), ("y", 5.0), ("z", 4.0)))
            tau = sigma * lx / theta ** 3
            trip_sum += K * (phi - phi_old) * tau
            phi_old = phi
            worst = max(worst, abs(math.log(lx / theta) - tau / E - trip_sum) / (K * sigma),
                        abs(math.log(ly / theta) + NU * tau / E + 0.5 * trip_sum) / (K * sigma),
                        abs(math.log(lz / theta) + NU * tau / E + 0.5 * trip_sum) / (K * sigma))
        print(f"trip (finite strain): TRIP log strain {trip_sum:.6e}, worst deviation {worst:.2e} of K sigma")
        checks("trip (finite strain): ln(lambda / theta) = tau / E + sum K dphi tau (Kirchhoff) to 1e-8", worst < 1e-8)

    if "mixture" in cases:
        rows_m = [(20.0, 1400.0), (300.0, 1100.0)]

        def sigma_m(T):
            (t0, v0), (t1, v1) = rows_m
            return v0 + (v1 - v0) * (min(max(T, t0), t1) - t0) / (t1 - t0)

        settings = phase_block("250 - 230 * t") + [
            "Material/Hardening modulus=0", "Thermal/Taylor-Quinney coefficient=0",
            "Boundary conditions/Number of conditions=4", "Boundary conditions/Condition 3/Boundary id=3",
            "Boundary conditions/Condition 3/Components=y", "Boundary conditions/Condition 3/Value=-0.4*t",
            "Phases/Martensite yield stress=" + ", ".join(f"{t:g}: {v:g}" for t, v in rows_m),
            "Solver/Residual tolerance=1e-12"]
        # P_yy on y = 5 per yield stress of the return map's measure, with the stretches of the
        # corner and the isotropic stretch theta = theta_th theta_tr the inner model sees removed
        # (F / theta, P = theta^2 P_inner): small strain 1; total Lagrangian (S) theta lambda_y;
        # updated Lagrangian (Cauchy) lambda_x lambda_z; finite strain (Kirchhoff) theta^3 / lambda_y
        factors = {"small strain": lambda lx, ly, lz, th: 1.0,
                   "total Lagrangian": lambda lx, ly, lz, th: th * ly,
                   "updated Lagrangian": lambda lx, ly, lz, th: lx * lz,
                   "finite strain": lambda lx, ly, lz, th: th ** 3 / ly}
        dv = (4.64 - 0.53 * CARBON) / 100.0
        for kinematics, factor in factors.items():
            directory = "mixture_" + kinematics.replace(" ", "_")
            run(ausroll, block, settings + [f"Model/Kinematics={kinematics}"], directory)
            worst, f_end = 0.0, 0.0
            for row in history(directory)[1:]:
                T = 250.0 - 230.0 * float(row["time"])
                f = martensite(T)
                stretch = [1.0 + float(row[f"corner_u{c}"]) / length for c, length in (("x", 10.0), ("y", 5.0), ("z", 4.0))]
                theta = (1.0 + ALPHA * (T - 20.0)) * (1.0 + f * dv) ** (1.0 / 3.0)
                expected = ((1.0 - f) * SIGMA0 + f * sigma_m(T)) * 40.0 * factor(*stretch, theta)
                worst = max(worst, abs(abs(float(row["reaction_3_y"])) - expected) / (1400.0 * 40.0))
                f_end = f
            print(f"mixture ({kinematics}): final martensite {f_end:.6f}, reaction {float(row['reaction_3_y']):.4f} N, "
                  f"worst deviation {worst:.2e} of sigma_y,M A")
            checks(f"mixture ({kinematics}): reaction = A ((1 - f) sigma_0 + f sigma_y,M(T)) (stretches) in every "
                   "plastic step to 1e-8", worst < 1e-8 and f_end > 0.5)

    if "carbon_yield" in cases:
        yield_m = "413 + 1720*sqrt(C)"
        hardening_m = "3000 + 2000*C + T"
        for carbon in (0.2, 0.8):
            sigma_m = 413.0 + 1720.0 * math.sqrt(carbon)
            h_m = 3000.0 + 2000.0 * carbon + 20.0
            theta_tr = 1.0  # quenched: the martensite of t = 0 is the stress-free reference
            settings = [f"Thermal/Thermal expansion={ALPHA}", "Thermal/Initial temperature=20",
                        "Thermal/Specific heat=1", "Phases/Enabled=true", f"Phases/Carbon content={carbon}",
                        "Phases/Koistinen-Marburger coefficient=10", "Phases/Initial state=quenched",
                        "Loading/Number of steps=10",
                        "Material/Hardening modulus=0", "Thermal/Taylor-Quinney coefficient=0",
                        "Boundary conditions/Condition 3/Value=-0.1*t",
                        f"Phases/Martensite yield stress={yield_m}",
                        f"Phases/Martensite hardening modulus={hardening_m}",
                        "Solver/Residual tolerance=1e-12"] + faces_held_at("20")
            directory = f"carbon_yield_{carbon:g}"
            run(ausroll, block, settings, directory)
            worst, plastic, fractions = 0.0, 0, []
            for row in history(directory)[1:]:
                eps_m = abs(float(row["corner_uy"]) / 5.0 - (theta_tr - 1.0))
                fractions.append(float(row["martensite_min"]))
                if E * eps_m <= sigma_m:
                    continue
                plastic += 1
                expected = (sigma_m + h_m * eps_m) / (1.0 + h_m / E) * 40.0
                worst = max(worst, abs(abs(float(row["reaction_3_y"])) - expected) / (sigma_m * 40.0))
            print(f"carbon_yield (C = {carbon}): sigma_y,M {sigma_m:.4f} MPa, H_M {h_m:.1f} MPa, {plastic} plastic "
                  f"steps, worst reaction deviation {worst:.2e} of sigma_y,M A, martensite {min(fractions):.17g}")
            checks(f"carbon_yield (C = {carbon}): pure martensite from the start (quenched)", min(fractions) == 1.0)
            checks(f"carbon_yield (C = {carbon}): reaction = A (sigma_y,M(C) + H_M |eps_m|) / (1 + H_M/E) to 1e-8",
                   worst < 1e-8 and plastic >= 4)

    if "trip_heat" in cases:
        sigma, K, beta = 200.0, 1e-4, 0.9
        rho, c, latent = 7.85e-9, 4.6e6, 1e8
        rho_c = rho * c
        n = math.log(math.log(0.01) / math.log(0.99)) / math.log(300.0 / 15.0)
        k = -math.log(0.99) / 15.0 ** n

        def phi(z):
            return z * (1.0 - math.log(z)) if z > 0.0 else 0.0

        base = ["Boundary conditions/Number of conditions=4", "Boundary conditions/Condition 3/Boundary id=1",
                "Boundary conditions/Condition 3/Type=traction", f"Boundary conditions/Condition 3/Value={sigma}; 0; 0",
                "Thermal/Thermal expansion=0", f"Thermal/Specific heat={c}", "Phases/Enabled=true",
                f"Phases/Carbon content={CARBON}", f"Phases/TRIP coefficient={K}", "Solver/Absolute residual tolerance=1e-8"]
        bainite = base + ["Thermal/Initial temperature=300", "Loading/End time=120", "Loading/Number of steps=8",
                          "Phases/Bainite start times=200: 15, 800: 15", "Phases/Bainite finish times=200: 300, 800: 300"]
        run(ausroll, block, bainite + ["Phases/TRIP heating=true", f"Phases/Bainite latent heat={latent}"],
            "trip_heat_bainite")
        worst_T, worst, rise = 0.0, 0.0, 0.0
        for row in history("trip_heat_bainite")[1:]:
            f_b = 1.0 - math.exp(-k * float(row["time"]) ** n)
            rise = (beta * K * sigma ** 2 * phi(f_b) + rho * latent * f_b) / rho_c
            worst_T = max(worst_T, abs(float(row["T_mean"]) - 300.0 - rise))
            worst = max(worst, abs(float(row["bainite_mean"]) - f_b))
        worst = max(worst, worst_T / rise)  # of the final (largest) rise: the column has 10 digits
        print(f"trip_heat (bainite): final f_B {f_b:.6f}, rise {rise:.6f} K (TRIP {beta * K * sigma ** 2 * phi(f_b) / rho_c:.4f} "
              f"K, latent {rho * latent * f_b / rho_c:.4f} K), worst relative deviation {worst:.2e}")
        checks("trip_heat (bainite): T = T0 + (beta K sigma^2 phi(f_B) + rho L_B f_B) / (rho c) to 1e-8",
               worst < 1e-8 and f_b > 0.4)

        run(ausroll, block, base + ["Thermal/Initial temperature=20", "Phases/Initial state=undercooled austenite",
                                    "Loading/Number of steps=4",
                                    "Phases/TRIP heating=true", f"Phases/Latent heat={latent}"], "trip_heat_martensite")
        f_m = martensite(20.0)
        rise = (beta * K * sigma ** 2 * phi(f_m) + rho * latent * f_m) / rho_c
        worst = 0.0
        for row in history("trip_heat_martensite")[1:]:
            worst = max(worst, abs(float(row["T_mean"]) - 20.0 - rise) / rise, abs(float(row["martensite_mean"]) - f_m))
        print(f"trip_heat (martensite): f_M {f_m:.6f}, rise {rise:.6f} K, worst relative deviation {worst:.2e}")
        checks("trip_heat (martensite): T = T0 + (beta K sigma^2 phi(f_M) + rho L f_M) / (rho c) to 1e-8", worst < 1e-8)

        run(ausroll, block, bainite, "trip_heat_off")
        unchanged = all(abs(float(row["T_mean"]) - 300.0) < 1e-6 for row in history("trip_heat_off"))
        print(f"trip_heat (off): T_mean stays 300 C: {unchanged}")
        checks("trip_heat (off): without TRIP heating and latent heat the block stays at 300 C (1e-6 K)", unchanged)

    if "stabilisation" in cases:
        g0, eps0, slope, b = 500.0, 0.1, 6.94, 0.011
        alpha = (300.0 - SIGMA0) / H
        shift = g0 / slope * (math.sqrt(1.0 + alpha / eps0) - 1.0)
        settings = ["Boundary conditions/Number of conditions=4", "Boundary conditions/Condition 3/Boundary id=3",
                    "Boundary conditions/Condition 3/Type=traction",
                    "Boundary conditions/Condition 3/Value=0; t < 1.05 ? -300 * min(t, 1) : 0; 0",
                    f"Thermal/Thermal expansion={ALPHA}", "Thermal/Initial temperature=250", "Thermal/Specific heat=1",
                    "Thermal/Taylor-Quinney coefficient=0", "Coupling/Iterations=3", "Phases/Enabled=true",
                    f"Phases/Carbon content={CARBON}", "Loading/End time=2", "Loading/Number of steps=20",
                    "Solver/Absolute residual tolerance=1e-8"] + faces_held_at("t <= 1 ? 250 : 250 - 230 * (t - 1)")
        finals = {}
        for on in (True, False):
            directory = "stabilisation_" + ("on" if on else "off")
            extra = ["Phases/Mechanical stabilisation=true", f"Phases/Stabilisation energy={g0}",
                     f"Phases/Stabilisation strain={eps0}", f"Phases/Driving force slope={slope}"] if on else []
            run(ausroll, block, settings + extra, directory)
            ms = MS - (shift if on else 0.0)
            worst, worst_alpha = 0.0, 0.0
            for row in history(directory)[1:]:
                t = float(row["time"])
                T = 250.0 if t <= 1.0 + 1e-12 else 250.0 - 230.0 * (t - 1.0)
                f = 1.0 - math.exp(-b * (ms - T)) if T < ms else 0.0
                worst = max(worst, abs(float(row["martensite_mean"]) - f), abs(float(row["martensite_max"]) - f))
                finals[on] = f
            print(f"stabilisation ({'on' if on else 'off'}): alpha {alpha:.4f}, Ms {ms:.4f} C (shift "
                  f"{MS - ms:.4f} K), final fraction {finals[on]:.6f}, worst deviation {worst:.2e}")
            checks(f"stabilisation ({'on' if on else 'off'}): KM fraction with Ms - G_0/S (sqrt(1 + alpha/eps_0) - 1) "
                   "to 1e-8", worst < 1e-8 and finals[on] > 0.5)
        checks("stabilisation: the pre-strain lowers the final fraction", finals[True] < finals[False] - 0.01)

    slide = os.path.join(scenes, "block_slide.prm")
    thermal_on = ["Thermal/Enabled=true", "Thermal/Thermal expansion=0", "Thermal/Initial temperature=20",
                  "Output/Overwrite=true"]
    if "conductance" in cases:
        run(ausroll, slide, thermal_on + [
            "Contact/Die 0/Motion/Prescribed/Translation=0; -0.011*min(t,1)", "Loading/End time=100",
            "Loading/Number of steps=20", "Thermal/Contact conductance=10", "Thermal/Die temperatures=200",
            "Thermal/Number of conditions=1", "Thermal/Condition 0/Boundary id=2",
            "Thermal/Condition 0/Type=temperature", "Thermal/Condition 0/Value=20"], "conductance")
        row = last("conductance")
        k_over_L = 45.0 / 5.0
        top = (10.0 * 200.0 + k_over_L * 20.0) / (10.0 + k_over_L)
        heat = 10.0 * (200.0 - top) * 10.0
        print(f"conductance: T_max {row['T_max']:.6f} (expected {top:.6f}), die heat {row['heat_die_0']:.4f} "
              f"(expected {heat:.4f}), base {row['heat_condition_0']:.4f} N mm/s")
        checks("conductance: steady contact temperature to 1e-6 of the range",
               abs(row["T_max"] - top) < 1e-6 * 180.0)
        checks("conductance: die heat h_c (T_die - T) A to 1e-6", abs(row["heat_die_0"] - heat) < 1e-6 * heat)
        checks("conductance: the base takes it out (balance to 1e-6)",
               abs(row["heat_die_0"] + row["heat_condition_0"]) < 1e-6 * heat)

    if "friction" in cases:
        run(ausroll, slide, thermal_on + [
            "Contact/Die 0/Motion/Prescribed/Translation=0.1*max(t-1,0); -0.011*min(t,1)", "Loading/End time=4",
            "Loading/Number of steps=16"], "friction")
        row = last("friction")
        fy = [row[c] for c in row if c.endswith("force_y")][0]
        expected = 0.5 * 0.2 * abs(fy) * 0.1
        print(f"friction: heat into the block {row['heat_die_0']:.6f} N mm/s, 0.5 mu |F_y| v = {expected:.6f}")
        checks("friction: heat = partition mu p v to 1e-6", abs(row["heat_die_0"] - expected) < 1e-6 * expected)

    if "np2" in cases:
        run(ausroll, strip, [], "serial")
        run(ausroll, strip, [], "parallel", mpi=2)
        a, b = history("serial"), history("parallel")
        checks("np2: same number of rows", len(a) == len(b))
        worst = 0.0
        for column in a[0].keys():
            if column in ("wall_seconds",):
                continue
            scale = max(abs(float(r[column])) for r in a) or 1.0
            for ra, rb in zip(a, b):
                worst = max(worst, abs(float(ra[column]) - float(rb[column])) / scale)
        print(f"np2: largest relative difference {worst:.2e}")
        checks("np2: np = 2 equals np = 1 to 1e-8", worst < 1e-8)

    if "resume" in cases:
        base = ["Checkpoint/Interval=10"]
        run(ausroll, strip, base, "whole")
        shutil.rmtree("resumed", ignore_errors=True)
        first = run(ausroll, strip, base + ["Checkpoint/Abort after step=25"], "resumed")
        checks("resume: the first run stopped as asked (exit 99)", first.returncode == 99)
        second = run(ausroll, strip, base, "resumed", extra=["--resume"])
        checks("resume: the resumed run finished", second.returncode == 0)
        a, b = history("whole"), history("resumed")
        same = len(a) == len(b) and all(
            ra[c] == rb[c] for ra, rb in zip(a, b) for c in ra if c != "wall_seconds")
        checks("resume: history identical to the uninterrupted run", same)

    return checks.exit_status()


if __name__ == "__main__":
    sys.exit(main())
