#!/usr/bin/env python3
"""Inextensible elastica of a clamped cantilever: independent reference for prm/cantilever.prm.

Standard library only (no numpy, no ausroll code). Euler-Bernoulli beam, length L, bending
stiffness EI, clamped at s = 0 (theta = 0), free at s = L, without shear and axial strain.
Unknowns along the arc length s: tangent angle theta, bending moment M = EI theta', internal force
N = (N_x, N_y) that the part (s, L) receives from the part (0, s). Equilibrium of a beam element:

    N' = -f(s),   M' = -(t x N) = -(cos(theta) N_y - sin(theta) N_x),   theta' = M / EI

with the distributed load f per unit (undeformed = deformed) length:
  - dead   : f = (0, -q)                        (uniform vertical load, the elastica of Holden)
  - follower: f = -q n, n = (-sin theta, cos theta) (uniform pressure on the deformed top surface)

The free end gives N(L) = 0, M(L) = 0; the equations are integrated from the tip to the clamp
with classical Runge-Kutta (RK4) and the tip angle theta(L) is found by the secant method such
that theta(0) = 0 (shooting). Tip displacement u = (int cos theta - 1, int sin theta) L.
Dimensionless load k = q L^3 / EI; the linear (small-deflection) tip deflection is k L / 8.

A tip couple M0 gives the circle of radius EI / M0 exactly: M0 = 2 pi EI / L closes the beam into
a full circle (tip back at the clamp, rotation 2 pi); this script prints that case too.

Reissner's beam (--slenderness L/h, --poisson nu) adds the axial strain N_t / EA and the shear
strain N_n / (kappa G A) to the kinematics, r' = (1 + N_t/EA) t + (N_n/kappa GA) n, with
M' = -(r' x N): the beam that a 2D continuum model of the same L/h approaches.

Usage: elastica.py [--k 1,2,5,10,20] [--steps 4000] [--slenderness 10] [--poisson 0.2]
                   [--csv FILE] [--curve K_MAX:N]
"""

import argparse
import math
import sys


def stretch_vector(theta, nx, ny, beam):
    """r' = (1 + N_t / EA) t + (N_n / kGA) n (Reissner); t for the inextensible elastica."""
    c, s = math.cos(theta), math.sin(theta)
    if beam is None:
        return c, s
    ea, kga = beam
    nt = c * nx + s * ny
    nn = -s * nx + c * ny
    a, b = 1.0 + nt / ea, nn / kga
    return a * c - b * s, a * s + b * c


def integrate(theta_tip, k, follower, steps, beam=None):
    """RK4 from s = 1 to s = 0 (L = EI = 1). Returns theta(0), int x', int y' (Simpson).
    beam = (EA L^2 / EI, kGA L^2 / EI) adds axial and shear flexibility (Reissner's beam)."""
    def rhs(state):
        theta, m, nx, ny = state
        c, s = math.cos(theta), math.sin(theta)
        if follower:
            fx, fy = k * s, -k * c  # f = -k n
        else:
            fx, fy = 0.0, -k
        rx, ry = stretch_vector(theta, nx, ny, beam)
        # d/ds; we integrate with ds = -h
        return (m, -(rx * ny - ry * nx), -fx, -fy)

    h = -1.0 / steps
    state = (theta_tip, 0.0, 0.0, 0.0)
    states = [state]
    for _ in range(steps):
        k1 = rhs(state)
        k2 = rhs(tuple(x + 0.5 * h * d for x, d in zip(state, k1)))
        k3 = rhs(tuple(x + 0.5 * h * d for x, d in zip(state, k2)))
        k4 = rhs(tuple(x + h * d for x, d in zip(state, k3)))
        state = tuple(x + h / 6.0 * (a + 2 * b + 2 * c + d)
                      for x, a, b, c, d in zip(state, k1, k2, k3, k4))
        states.append(state)
    states.reverse()  # s = 0, h, ..., 1
    tangents = [stretch_vector(st[0], st[2], st[3], beam) for st in states]

    def simpson(values):
        n = len(values) - 1
        total = values[0] + values[-1]
        total += 4 * sum(values[1:n:2]) + 2 * sum(values[2:n:2])
        return total / (3.0 * n)

    return (state[0], simpson([t[0] for t in tangents]), simpson([t[1] for t in tangents]))


def solve(k, follower, steps, guess=None, beam=None):
    """Tip angle theta(L) with theta(0) = 0; returns (theta_tip, u_x / L, u_y / L)."""
    if k == 0.0:
        return 0.0, 0.0, 0.0
    a = guess if guess is not None else -k / 6.0  # linear theory: theta_tip = -k / 6
    b = a * 1.01
    fa = integrate(a, k, follower, steps, beam)[0]
    fb = integrate(b, k, follower, steps, beam)[0]
    for _ in range(100):
        if fb == fa:
            break
        c = b - fb * (b - a) / (fb - fa)
        a, fa = b, fb
        b = c
        fb = integrate(b, k, follower, steps, beam)[0]
        if abs(fb) < 1e-13:
            break
    if abs(fb) > 1e-9:
        raise RuntimeError(f"shooting did not converge for k = {k} (residual {fb})")
    _, ic, is_ = integrate(b, k, follower, steps, beam)
    return b, ic - 1.0, is_


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--k", default="1,2,5,10,20", help="load parameters q L^3 / EI")
    parser.add_argument("--steps", type=int, default=4000, help="RK4 steps along the beam")
    parser.add_argument("--slenderness", type=float, default=10.0,
                        help="L / h of the rectangular section for the Reissner beam")
    parser.add_argument("--poisson", type=float, default=0.2, help="nu for the shear modulus")
    parser.add_argument("--csv", help="write a curve k, tip displacements / L")
    parser.add_argument("--curve", default="20:200", help="K_MAX:N for --csv (N + 1 points)")
    args = parser.parse_args()

    # Reissner beam: EA L^2/EI = 12 (L/h)^2, kGA L^2/EI = 12 kappa (L/h)^2 / (2 (1 + nu)), with
    # Cowper's shear coefficient of a rectangle kappa = 10 (1 + nu) / (12 + 11 nu).
    nu, lh = args.poisson, args.slenderness
    kappa = 10 * (1 + nu) / (12 + 11 * nu)
    beam = (12 * lh ** 2, 12 * kappa * lh ** 2 / (2 * (1 + nu)))

    print("Clamped cantilever, uniform load q per length, k = q L^3 / EI; tip displacement / L")
    print(f"elastica: inextensible, no shear; Reissner: axial and shear flexibility for L/h = "
          f"{lh:g}, nu = {nu:g}, kappa = {kappa:.4f} (RK4, {args.steps} steps)")
    print("| k | dead -u_y/L elastica | dead -u_y/L Reissner | dead -u_x/L elastica | "
          "dead -u_x/L Reissner | dead -theta_tip | follower -u_y/L elastica | "
          "follower -u_y/L Reissner | follower -u_x/L elastica | linear k/8 | RK4 error |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for k in [float(v) for v in args.k.split(",")]:
        dead = solve(k, False, args.steps)
        dead_half = solve(k, False, args.steps // 2, dead[0])
        dead_r = solve(k, False, args.steps, dead[0], beam)
        fol = solve(k, True, args.steps)
        fol_r = solve(k, True, args.steps, fol[0], beam)
        print(f"| {k:g} | {-dead[2]:.6f} | {-dead_r[2]:.6f} | {-dead[1]:.6f} | {-dead_r[1]:.6f} | "
              f"{-dead[0]:.6f} | {-fol[2]:.6f} | {-fol_r[2]:.6f} | {-fol[1]:.6f} | {k / 8:.4f} | "
              f"{abs(dead[2] - dead_half[2]):.1e} |")

    # tip couple: circle of radius R = EI / M0
    print("\nTip couple M0 = lambda 2 pi EI / L (exact circle, R = L / (2 pi lambda)):")
    print("| lambda | u_x / L | u_y / L | rotation (deg) |")
    print("|---:|---:|---:|---:|")
    for lam in (0.25, 0.5, 0.75, 1.0):
        phi = 2 * math.pi * lam
        r = 1.0 / phi
        print(f"| {lam:g} | {r * math.sin(phi) - 1:.6f} | {r * (1 - math.cos(phi)):.6f} | "
              f"{math.degrees(phi):.1f} |")

    if args.csv:
        k_max, n = args.curve.split(":")
        k_max, n = float(k_max), int(n)
        guesses = [None] * 4
        with open(args.csv, "w") as out:
            out.write("k,dead_ux,dead_uy,dead_reissner_ux,dead_reissner_uy,follower_ux,"
                      "follower_uy,follower_reissner_ux,follower_reissner_uy\n")
            for i in range(n + 1):
                k = k_max * i / n
                results = [solve(k, False, args.steps, guesses[0]),
                           solve(k, False, args.steps, guesses[1], beam),
                           solve(k, True, args.steps, guesses[2]),
                           solve(k, True, args.steps, guesses[3], beam)]
                if k > 0:
                    guesses = [r[0] for r in results]
                out.write(f"{k:.6g}," + ",".join(f"{r[1]:.9f},{r[2]:.9f}" for r in results)
                          + "\n")
        print(f"\nwrote {args.csv}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
