#!/usr/bin/env python3
"""3D process-chain check (scenes/gear_chain_3d_free.prm): the extruded gear tooth of
prm/gear_ausrolling_chain_3d.prm with the chain's features (Stages with per-stage thermal values,
the temperature field, Phases: Koistinen-Marburger martensite with its volume change, TRIP, the
mixture yield stress; finite strain with the 3D F-bar; the inner arc moving with the body's free
strain in x, y and z, u_z = 0 at mid-face, the face end free) cooled uniformly from 250 C to 20 C
through Ms, in two cases: C = 0.5 wt% (Ms 237.8 C), all austenite at 250 C, and C = 0.1 wt%
(Ms 407.0 C) with Phases/Initial state = quenched, the fraction f0 = f(250 C) = 0.8223 in the
stress-free reference (the core of the carburized gear); the inner-arc entry is written for each
(inner_arc()). Closed form: a free body at a uniform temperature and martensite fraction is
stress-free and stretched uniformly,

    lambda = (1 + alpha (T - T_ref)) ((1 + f dV / 100) / (1 + f0 dV / 100))^(1/3)
             (thermal and transformation stretch; f0 = 0 for the austenite),
    f = 1 - exp(-b (Ms(C) - T)),  Ms(C) = 539 - 423 C - 30.4 Mn - 17.7 Ni - 12.1 Cr - 7.5 Mo,
    dV = 4.64 - 0.53 C                                         (the Phases defaults, AISI 9310),

so at the end (20 C, held for two steps) every node is displaced by (lambda - 1) X (X its reference
position) and the stress vanishes; TRIP (driven by the deviatoric stress) adds nothing.

Checks, each with its tolerance and why:
  fraction    martensite_min and martensite_max of the last row equal f(20 C) within 1e-8 (the
              history prints 10 digits; the fraction is uniform because the carbon and the
              temperature are);
  temperature T_min, T_max of the last row 20 C within 1e-6 K (the conductivity is 5e7 times
              steel's: the nodes inside lag the boundary by less than 1e-6 K once it holds);
  stage       the history's stage column is 0 up to t = 0.1 s and 1 after, and the last row is at
              t = 12.1 s (the end of the cooling stage);
  tip         the history's monitor point at the tooth tip at the face end (0, 49.2, 6) is displaced by
              (lambda - 1) X within 1e-9 mm (the history prints 10 digits of 0.39 mm; the
              stress-free state leaves no strain beyond round-off);
  stretch     the displacement of every node of the last VTU output equals (lambda - 1) X within
              2e-7 mm (the VTU is single precision: positions of 50 mm to 3e-6 mm, so X = x - u
              carries 3e-6 mm, times lambda - 1 = 0.008, plus the 0.4 mm displacement to 2.4e-8 mm;
              measured 3e-8 mm); a missing transformation strain would be off by 0.5 mm, a
              missing z component of the inner-arc condition by 0.05 mm;
  stress      the largest von Mises stress of the last output below 1e-3 MPa (measured 8e-7 MPa;
              the inner arc moved with the thermal strain alone leaves 1200 MPa);
  plastic     no plastic strain anywhere (the path is stress-free at every step);
  np2         the quenched case on 2 MPI ranks: the checks above, and every history column within
              1e-8 of its largest magnitude (another partition, the same algebra), except
              heat_condition_K: with the
              conductivity 5e7 times steel's the heat through a temperature condition is the
              reaction of a nearly singular conduction matrix, round-off times 1e9 (measured
              1.6e-7 of its largest), and wall_seconds; the tip's displacement components are
              measured against the largest of them (tip_ux is 0 up to round-off on the tooth axis).

Usage: check_gear_chain_3d.py AUSROLL SOURCE_DIR
"""

import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts"))
from check_thermal import history, run  # noqa: E402  (one way to run and read a scene)
from checklist import Checklist  # noqa: E402

ALPHA, T_REF, T_END, B = 2.2e-5, 250.0, 20.0, 0.011
TIP = (0.0, 49.2, 6.0)


def martensite_start(C):
    return 539 - 423 * C - 30.4 * 0.55 - 17.7 * 3.25 - 12.1 * 1.2 - 7.5 * 0.12


def stretch(C, T, quenched):
    """(f, lambda) of a free body at the uniform temperature T, cooled monotonically from T_REF, all
    austenite at T_REF or (quenched) with the fraction f0 = f(T_REF) in its stress-free reference."""
    def fraction(T):
        return max(0.0, 1.0 - math.exp(-B * (martensite_start(C) - T)))

    dv = (4.64 - 0.53 * C) / 100.0
    f0 = fraction(T_REF) if quenched else 0.0
    return fraction(T), (1.0 + ALPHA * (T - T_REF)) * ((1.0 + fraction(T) * dv) / (1.0 + f0 * dv)) ** (1.0 / 3.0)


def inner_arc(C, quenched):
    """The entry that moves the inner arc with the body's free strain at the temperature of the
    step's start T_s(t) = T(t - 1) (the scene's text, written for any carbon content and initial
    state)."""
    Ts = "max(20, 250 - 23 * max(t - 1.1, 0))"
    dv = f"(4.64 - 0.53 * {C}) / 100"
    ms = f"(539 - 423 * {C} - 30.4 * 0.55 - 17.7 * 3.25 - 12.1 * 1.2 - 7.5 * 0.12)"
    f = f"max(0, 1 - exp(-0.011 * ({ms} - {Ts})))"
    f0 = f"max(0, 1 - exp(-0.011 * ({ms} - 250)))" if quenched else "0"
    lam = f"((1 + 2.2e-5 * ({Ts} - 250)) * ((1 + {f} * {dv}) / (1 + {f0} * {dv}))^(1 / 3) - 1)"
    return f"Boundary conditions/Condition 0/Value={lam} * x; {lam} * y; {lam} * z"


def check_case(checks, ausroll, prm, directory, C, quenched, mpi=0):
    """Run the scene with carbon C (and the quenched initial state) and check it against the
    closed form; the rows of its history."""
    import vtu_io  # noqa: E402  (VTK is needed only here)

    state = "quenched" if quenched else "austenite"
    label = f"C = {C}, {state}" + (f", np = {mpi}" if mpi else "")
    run(ausroll, prm, [f"Phases/Carbon content={C}", f"Phases/Initial state={state}",
                       inner_arc(C, quenched)], directory, mpi=mpi)
    f, lam = stretch(C, T_END, quenched)
    rows = history(directory)
    last = rows[-1]
    print(f"{label}: closed form at {T_END} C: Ms {martensite_start(C):.3f} C, f {f:.10f}, "
          f"lambda {lam:.10f}; history: t {last['time']}, martensite {last['martensite_min']} .. "
          f"{last['martensite_max']}, T {last['T_min']} .. {last['T_max']}")
    checks(f"{label}: martensite fraction f(20 C) within 1e-8",
           all(abs(float(last[k]) - f) < 1e-8 for k in ("martensite_min", "martensite_max")))
    checks(f"{label}: temperature 20 C within 1e-6 K",
           all(abs(float(last[k]) - T_END) < 1e-6 for k in ("T_min", "T_max")))
    checks(f"{label}: stage column 0 up to t = 0.1 s, 1 after; last row at t = 12.1 s",
           all(int(r["stage"]) == (0 if float(r["time"]) <= 0.1 + 1e-12 else 1) for r in rows)
           and abs(float(last["time"]) - 12.1) < 1e-12)
    moved = [float(last[f"tip_u{c}"]) for c in "xyz"]
    print(f"tip displacement {moved}, closed form {[(lam - 1.0) * X for X in TIP]}")
    checks(f"{label}: tooth tip at the face end displaced by (lambda - 1) X within 1e-9 mm",
           all(abs(u - (lam - 1.0) * X) < 1e-9 for u, X in zip(moved, TIP)))

    grid = vtu_io.read_grid(vtu_io.datasets(directory)[-1][1])
    worst = max(max(abs(x[d] - X[d] - (lam - 1.0) * X[d]) for d in range(3))
                for X, x, _ in vtu_io.unique_nodes(grid))
    mises = max(abs(float(v)) for v in vtu_io.point_array(grid, "von_mises_stress"))
    plastic = max(abs(float(v)) for v in vtu_io.point_array(grid, "equivalent_plastic_strain"))
    print(f"largest |u - (lambda - 1) X| {worst:.3e} mm, von Mises {mises:.3e} MPa, "
          f"plastic strain {plastic:.3e}")
    checks(f"{label}: every node displaced by (lambda - 1) X within 2e-7 mm", worst < 2e-7)
    checks(f"{label}: stress-free, von Mises below 1e-3 MPa", mises < 1e-3)
    checks(f"{label}: no plastic strain", plastic == 0.0)
    return rows


def main():
    ausroll, source = sys.argv[1], sys.argv[2]
    prm = os.path.join(source, "tests", "checks", "scenes", "gear_chain_3d_free.prm")
    checks = Checklist()
    check_case(checks, ausroll, prm, "austenite", 0.5, False)
    rows = check_case(checks, ausroll, prm, "quenched", 0.1, True)
    rows_np2 = check_case(checks, ausroll, prm, "quenched_np2", 0.1, True, mpi=2)
    compared = [c for c in rows[0] if not c.startswith("heat_condition_") and c != "wall_seconds"]
    scale = {c: max(max(abs(float(r[c])) for r in rows + rows_np2), 1e-300) for c in compared}
    tip_scale = max(scale[f"tip_u{c}"] for c in "xyz")
    scale.update({f"tip_u{c}": tip_scale for c in "xyz"})
    worst = max((abs(float(a[c]) - float(b[c])) / scale[c], c) for a, b in zip(rows, rows_np2)
                for c in compared) if len(rows) == len(rows_np2) else (math.inf, "rows")
    print(f"np = 2 against np = 1: {len(compared)} columns, largest relative difference {worst[0]:.2e} ({worst[1]})")
    checks("np = 2 history equals np = 1 within 1e-8", worst[0] < 1e-8)
    return checks.exit_status()


if __name__ == "__main__":
    sys.exit(main())
