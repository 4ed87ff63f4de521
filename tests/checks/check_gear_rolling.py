#!/usr/bin/env python3
"""Checks of a (short) gear rolling run (prm/gear_rolling*.prm) against independent references.

Usage: check_gear_rolling.py OUT_DIR --direction S --theta0 DEG --rate DEG --t-roll T
                             [--duration 1] [--pressure-angle 22] [--ratio-tol 0.02]
                             [--force-range LOW HIGH] [--flow-sign +1|-1 --flank-script PATH]

1. Force direction (frictionless die): an involute pair in conjugate contact transmits the force
   along the line of action, which makes the angle alpha with the common tangent of the pitch
   circles. In the frame of the non-rotating workpiece the line of centres is at
   psi = 90 deg + S theta_G(t), theta_G(t) = theta0 + rate * min(max(t - t_roll, 0), duration), so the force of the
   die on the right flank (x > 0) satisfies F_y / F_x = tan(alpha + S theta_G) exactly (rigid
   bodies). Checked at every step with |F| > 10 N/mm within --ratio-tol (the deformed flank
   rotates the contact normal by a few 1e-3 rad; the measured deviation on the scene mesh is
   below 0.01).
2. Force sign and magnitude: F_x < 0 (the die pushes the tooth towards -x) and
   LOW <= |F| <= HIGH at the last step (bounds justified in tests/checks/cmake/gear_rolling.cmake).
3. With --mu (Coulomb die, full slip while rolling): the friction part of the die force on the
   flank, F_t / F_n = mu sign(theta_G - theta_p), F_n and F_t the components along the inward
   normal and along the tangent towards the tip (directions of the line of action). theta_p =
   -S s_p / (2 r_p) is the revolution angle at which the rigid flanks touch at the pitch point
   (the flank point at r_p lies on the line of centres); there the sliding velocity changes
   sign. F_t > 0 drags the flank material towards the tip. Checked at rolling steps away from
   theta_p (more than 1 deg: the stick-slip transition lags by about 0.5 deg) within 0.012
   (measured 0.093 .. 0.105 over whole passes).
With --flank-from the direction checks 1 and 3 start at that revolution angle (thesis start with
a die tip round: the round, not the involute flank, touches the gear flank at first).
4. Optionally the flow direction: the sign of the mean tangential displacement of the flank near
   the pitch point (or --flow-column, e.g. u_t_upper on the addendum), from
   scripts/gear_flank_analysis.py (u_t > 0: towards the tip); with --reference-run the difference
   to a reference run (frictionless: the part of the residual flow that friction causes).
"""

import argparse
import csv
import math
import os
import subprocess
import sys


def main():
    p = argparse.ArgumentParser()
    p.add_argument("out")
    p.add_argument("--direction", type=int, required=True)
    p.add_argument("--theta0", type=float, required=True)
    p.add_argument("--rate", type=float, required=True)
    p.add_argument("--t-roll", type=float, required=True)
    p.add_argument("--duration", type=float, default=1.0)
    p.add_argument("--pressure-angle", type=float, default=22.0)
    p.add_argument("--ratio-tol", type=float, default=0.02)
    p.add_argument("--no-ratio", action="store_true")
    p.add_argument("--force-range", type=float, nargs=2, default=[50.0, 1340.0])
    p.add_argument("--mu", type=float)
    p.add_argument("--mu-tol", type=float, default=0.012)
    p.add_argument("--pitch-thickness", type=float, default=4.69392)
    p.add_argument("--pitch-radius", type=float, default=46.3176471)
    p.add_argument("--flow-sign", type=int, choices=[-1, 1])
    p.add_argument("--flow-column", default="u_t_pitch")
    p.add_argument("--flank-script")
    p.add_argument("--reference-run", nargs=3, metavar=("AUSROLL", "PRM", "OUT_DIR"),
                   help="run this reference scene (e.g. frictionless) and check the flow column "
                        "of OUT minus that of the reference (the part the difference causes)")
    p.add_argument("--flow-min", type=float, default=0.0,
                   help="the flow value times --flow-sign must exceed this (mm)")
    p.add_argument("--flank-from", type=float,
                   help="check directions only from this revolution angle on (deg, S theta_G >= "
                        "S value): before, a rounded die tip touches the flank (not involute on "
                        "involute)")
    a = p.parse_args()
    rows = list(csv.DictReader(open(os.path.join(a.out, "history.csv"))))
    failures = []
    worst = 0.0
    worst_mu = 0.0
    for r in rows:
        t = float(r["time"])
        fx, fy = float(r["die_die_force_x"]), float(r["die_die_force_y"])
        if math.hypot(fx, fy) <= 10.0:
            continue
        theta = a.theta0 + a.rate * min(max(t - a.t_roll, 0.0), a.duration)
        expected = math.tan(math.radians(a.pressure_angle + a.direction * theta))
        if fx >= 0.0:
            failures.append(f"t = {t}: F_x = {fx} is not negative")
        if a.flank_from is not None and a.direction * (theta - a.flank_from) < 0.0:
            continue
        if a.mu is not None and a.t_roll < t < a.t_roll + a.duration:
            theta_p = -a.direction * math.degrees(a.pitch_thickness / (2.0 * a.pitch_radius))
            if abs(theta - theta_p) > 1.0:
                b0 = math.radians(a.pressure_angle + a.direction * theta)
                fn = -(fx * math.cos(b0) + fy * math.sin(b0))
                ft = -fx * math.sin(b0) + fy * math.cos(b0)
                want = a.mu * (1.0 if theta > theta_p else -1.0)
                worst_mu = max(worst_mu, abs(ft / fn - want))
                if abs(ft / fn - want) > a.mu_tol:
                    failures.append(f"t = {t}: F_t/F_n = {ft / fn:.4f}, expected {want}")
        if not a.no_ratio:
            err = abs(fy / fx - expected)
            worst = max(worst, err)
            if err > a.ratio_tol:
                failures.append(f"t = {t}: F_y/F_x = {fy / fx:.5f}, line of action {expected:.5f}")
    last = rows[-1]
    f = math.hypot(float(last["die_die_force_x"]), float(last["die_die_force_y"]))
    if not a.force_range[0] <= f <= a.force_range[1]:
        failures.append(f"|F| = {f:.1f} N/mm at t = {last['time']} outside {a.force_range}")
    print(f"check_gear_rolling: worst |F_y/F_x - tan(alpha + S theta_G)| = {worst:.5f} "
          f"(tol {a.ratio_tol}); final |F| = {f:.1f} N/mm")
    if a.mu is not None:
        print(f"check_gear_rolling: worst |F_t/F_n - mu sign(theta_G - theta_p)| = {worst_mu:.5f} "
              f"(tol {a.mu_tol})")
    if a.flow_sign is not None:
        def flank_value(directory):
            out = subprocess.run([sys.executable, a.flank_script, directory],
                                 capture_output=True, text=True, check=True).stdout
            return float(dict(kv.split("=") for kv in out.split())[a.flow_column])

        u = flank_value(a.out)
        what = a.flow_column
        if a.reference_run:
            ausroll, prm, ref_out = a.reference_run
            subprocess.run([ausroll, prm, "--overwrite"], capture_output=True, check=True)
            u_ref = flank_value(ref_out)
            print(f"check_gear_rolling: {what} = {u:.6g} mm, reference run {u_ref:.6g} mm")
            u -= u_ref
            what += " - reference"
        print(f"check_gear_rolling: {what} = {u:.6g} mm (expected sign {a.flow_sign:+d}, "
              f"magnitude > {a.flow_min} mm)")
        if not u * a.flow_sign > a.flow_min:
            failures.append(f"flow direction: {what} = {u} has the wrong sign or is too small")
    for msg in failures:
        print("FAIL:", msg)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
