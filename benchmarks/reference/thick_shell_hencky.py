#!/usr/bin/env python3
"""Pressurised thick cylinder (plane strain) or sphere at finite strain, Hencky elasticity.

Independent 1D reference for the follower pressure of ausroll (standard library only). The
material is the elastic response of `Model/Kinematics = finite strain` (Yield criterion = none):
Kirchhoff stress tau = lambda tr(h) I + 2 mu h with the logarithmic strain h = ln V, Cauchy stress
sigma = tau / J. Radial motion r = phi(R), principal stretches lambda_r = phi', lambda_t = phi / R
(and lambda_z = 1 for the cylinder, a second lambda_t for the sphere).

Equilibrium in the deformed configuration, d sigma_r / dr + m (sigma_r - sigma_t) / r = 0 (m = 1
cylinder, m = 2 sphere), written in R:

    d sigma_r / dR = -m (phi' / phi) (sigma_r - sigma_t),

with sigma_r = S(phi', phi / R) this is a second-order ODE for phi. Boundary conditions: the
internal pressure p acts on the deformed inner surface, sigma_r(A) = -p (this is what a follower
pressure load means), sigma_r(B) = 0. Shooting on phi(A): phi'(A) from sigma_r(A) = -p (Newton),
RK4 to R = B, secant method on sigma_r(B) = 0.

Usage: thick_shell_hencky.py [--shape cylinder|sphere] [--A 100] [--B 200] [--E 1000] [--nu 0.3]
                             [--pmax 150] [--levels 15] [--steps 4000] [--csv FILE]
Writes a CSV with columns pressure,u_inner,u_outer (radial displacements in mm).
"""

import argparse
import math
import sys


def make_material(E, nu, m):
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    mu = E / (2 * (1 + nu))

    def stresses(lr, lt):
        er, et = math.log(lr), math.log(lt)
        tr = er + m * et
        J = lr * lt ** m
        sr = (lam * tr + 2 * mu * er) / J
        st = (lam * tr + 2 * mu * et) / J
        # partial derivatives of sigma_r w.r.t. lambda_r and lambda_t
        dsr_dlr = ((lam + 2 * mu) / lr) / J - sr / lr
        dsr_dlt = (lam * m / lt) / J - m * sr / lt
        return sr, st, dsr_dlr, dsr_dlt

    return stresses


def shoot(phi_a, p, A, B, m, stresses, steps):
    """sigma_r(B) for phi(A) = phi_a, and phi(B)."""
    lt = phi_a / A
    lr = lt  # initial guess for phi'(A)
    for _ in range(100):
        sr, _, d1, _ = stresses(lr, lt)
        step = (sr + p) / d1
        lr -= step
        if lr <= 0:
            lr = 1e-3
        if abs(step) < 1e-15:
            break

    def rhs(R, y):
        phi, dphi = y
        sr, st, d1, d2 = stresses(dphi, phi / R)
        dsr = -m * (dphi / phi) * (sr - st)
        ddphi = (dsr - d2 * (dphi / R - phi / R ** 2)) / d1
        return (dphi, ddphi)

    h = (B - A) / steps
    y = (phi_a, lr)
    R = A
    for _ in range(steps):
        k1 = rhs(R, y)
        k2 = rhs(R + h / 2, tuple(a + h / 2 * b for a, b in zip(y, k1)))
        k3 = rhs(R + h / 2, tuple(a + h / 2 * b for a, b in zip(y, k2)))
        k4 = rhs(R + h, tuple(a + h * b for a, b in zip(y, k3)))
        y = tuple(a + h / 6 * (b + 2 * c + 2 * d + e) for a, b, c, d, e in zip(y, k1, k2, k3, k4))
        R += h
    sr_b = stresses(y[1], y[0] / B)[0]
    return sr_b, y[0]


def solve(p, A, B, m, stresses, steps, guess):
    a = guess
    b = guess * (1 + 1e-4) + 1e-6
    fa = shoot(a, p, A, B, m, stresses, steps)[0]
    fb = shoot(b, p, A, B, m, stresses, steps)[0]
    for _ in range(200):
        if fb == fa:
            break
        c = b - fb * (b - a) / (fb - fa)
        a, fa = b, fb
        b = c
        fb = shoot(b, p, A, B, m, stresses, steps)[0]
        if abs(fb) < 1e-12 * max(1.0, p):
            break
    if abs(fb) > 1e-8 * max(1.0, p):
        raise RuntimeError(f"no convergence at p = {p}")
    return b, shoot(b, p, A, B, m, stresses, steps)[1]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--shape", choices=["cylinder", "sphere"], default="cylinder")
    ap.add_argument("--A", type=float, default=100.0)
    ap.add_argument("--B", type=float, default=200.0)
    ap.add_argument("--E", type=float, default=1000.0)
    ap.add_argument("--nu", type=float, default=0.3)
    ap.add_argument("--pmax", type=float, default=150.0)
    ap.add_argument("--levels", type=int, default=15)
    ap.add_argument("--steps", type=int, default=4000)
    ap.add_argument("--csv")
    args = ap.parse_args()
    m = 1 if args.shape == "cylinder" else 2
    stresses = make_material(args.E, args.nu, m)
    rows = [(0.0, 0.0, 0.0)]
    guess = args.A
    for i in range(1, args.levels + 1):
        p = args.pmax * i / args.levels
        phi_a, phi_b = solve(p, args.A, args.B, m, stresses, args.steps, guess)
        coarse = solve(p, args.A, args.B, m, stresses, args.steps // 2, phi_a)
        guess = phi_a
        rows.append((p, phi_a - args.A, phi_b - args.B))
        print(f"p = {p:8.3f}  u(A) = {phi_a - args.A:.7f}  u(B) = {phi_b - args.B:.7f}  "
              f"(RK4 steps/2 changes u(A) by {abs(coarse[0] - phi_a):.1e})")
    if args.csv:
        with open(args.csv, "w") as f:
            f.write("pressure,u_inner,u_outer\n")
            for p, ua, ub in rows:
                f.write(f"{p:.6g},{ua:.9f},{ub:.9f}\n")
        print(f"wrote {args.csv}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
