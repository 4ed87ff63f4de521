#!/usr/bin/env python3
"""Deformed gear flank against the original involute (scene prm/gear_rolling*.prm).

Usage: gear_flank_analysis.py OUTPUT_DIR [--flank negative|positive] [--plot FILE.png]
                              [--teeth 31] [--diametral-pitch 8.5] [--pressure-angle 22]
                              [--thickness 4.69392] [--axis-angle 90]

Reads every output step listed in OUTPUT_DIR/solution.pvd (the VTU files, written with
`Output/Deformed mesh = true`: current positions x and the nodal fields displacement and
contact_pressure; reference positions X = x - displacement; needs python3-vtk9) and, for the nodes
whose reference position lies on the involute part of the chosen flank, computes per output step

* the normal deviation of the current position from the ORIGINAL involute,
  d = r_b (phi - theta_h(r)) for the positive flank and r_b (-phi - theta_h(r)) for the negative one
  (phi the polar angle about the gear centre measured from the tooth axis, r = |x|). This is exact:
  the normal of an involute at any point is the tangent to the base circle, and the distance of a
  point from the involute along that tangent equals r_b times its angular offset. d > 0: the
  surface lies outside the original tooth (material piled up), d < 0: inside (material removed or
  pressed in);
* the tangential displacement u_t = (x - X) . t of the node along the flank, t the unit tangent at
  the reference point pointing towards the tip (u_t > 0: material moved towards the tip);
* the contact pressure p_n.

With --scale S the current positions are divided by S before they are measured: against the
design involute at another temperature (a gear modelled at the reference temperature T_ref and
cooled uniformly to T: S = 1 + alpha (T - T_ref), the free thermal contraction about the centre;
u_t is taken from the scaled positions too).

Writes OUTPUT_DIR/flank_deviation.csv (step,time,R,roll_angle,d_n,u_t,p_n; R and the roll angle
u = sqrt(R^2/r_b^2 - 1) of the reference point) and, with --plot, a PNG of d_n and u_t against R
for every step. Prints a summary: the final extreme deviations and the mean u_t over the flank near
the pitch point (|R - r_p| < 1 mm) and over the upper flank (R > r_p + 1 mm), whose signs give the
flow direction (thesis: towards the tip on the trailing side, away from it on the approach side).

ISO 1328-1 profile quantities (profile_deviations()): the trace is d_n against the roll length
xi = r_b u = sqrt(R^2 - r_b^2) (the abscissa of a profile diagram; the design profile is the
unmodified involute, so its traces are the lines d_n = const). The profile evaluation range L_alpha
runs from the start of active profile (--sap-radius; default: the lowest involute flank node) to
the start of the tip chamfer (--tip-chamfer-radius; default: the highest involute flank node, at
most the tip radius), shortened at its tip end to --evaluation-fraction of its roll length (default
1: the whole range). Over L_alpha, with the trace linear between the nodes (its values at the ends
of L_alpha interpolated):
  F_alpha    total profile deviation: max d_n - min d_n (the distance between two design profiles
             enclosing the trace);
  f_f_alpha  profile form deviation: the same about the mean profile line, the least-squares line
             a + b xi of the (piecewise linear) trace over L_alpha;
  f_H_alpha  profile slope deviation: b L_alpha, the rise of the mean profile line from the SAP end
             to the tip end (> 0: the flank stands out more towards the tip).
The summary adds them (of the last output step) with the range (L_alpha_R0, L_alpha_R1 radii,
L_alpha its roll length, all mm); OUTPUT_DIR/flank_iso1328.csv has them for every output step.
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import vtu_io  # noqa: E402


def gear_data(args):
    m = 25.4 / args.diametral_pitch
    alpha = math.radians(args.pressure_angle)
    rp = 0.5 * m * args.teeth
    rb = rp * math.cos(alpha)
    sp = args.thickness if args.thickness > 0 else 0.5 * math.pi * m
    inv_alpha = math.tan(alpha) - alpha

    def theta_h(r):
        u = math.sqrt(max(r * r / (rb * rb) - 1.0, 0.0))
        return sp / (2.0 * rp) + inv_alpha - (u - math.atan(u))

    return rp, rb, rp + m, theta_h


def add_gear_options(parser):
    """The gear data and flank selection options shared by the flank scripts."""
    parser.add_argument("--flank", choices=["negative", "positive"], default="negative")
    parser.add_argument("--teeth", type=int, default=31)
    parser.add_argument("--diametral-pitch", type=float, default=8.5)
    parser.add_argument("--pressure-angle", type=float, default=22.0)
    parser.add_argument("--thickness", type=float, default=4.69392)
    parser.add_argument("--axis-angle", type=float, default=90.0)
    parser.add_argument("--min-radius", type=float, default=0.0)
    parser.add_argument("--tolerance", type=float, default=2e-4,
                        help="distance (mm) of a reference node from the involute to count as flank node")
    parser.add_argument("--sap-radius", type=float, default=0.0,
                        help="start of active profile, the SAP end of L_alpha (mm; 0: lowest flank node)")
    parser.add_argument("--tip-chamfer-radius", type=float, default=0.0,
                        help="start of the tip chamfer, the tip end of L_alpha (mm; 0: highest flank node)")
    parser.add_argument("--scale", type=float, default=1.0,
                        help="current positions divided by this factor before they are measured: the "
                             "design profile at another temperature (1 + alpha (T - T_ref) for a gear "
                             "cooled uniformly from the reference temperature T_ref of its geometry)")
    parser.add_argument("--evaluation-fraction", type=float, default=1.0,
                        help="L_alpha as this fraction of the roll length from the SAP to the tip chamfer")


class Flank:
    """The involute flank chosen by the options of add_gear_options."""

    def __init__(self, args):
        self.rp, self.rb, self.rt, self.theta_h = gear_data(args)
        self.axis = math.radians(args.axis_angle)
        self.sign = 1.0 if args.flank == "positive" else -1.0
        self.min_radius = args.min_radius
        self.tolerance = args.tolerance
        self.scale = args.scale

    def measure(self, X, x):
        """(R, roll angle u, d_n, u_t) of a node with reference position X and current position x
        (their first two components, the plane of the gear), or None when X does not lie on the
        involute part of the flank (fillet, lands, radial part)."""
        rb, sign = self.rb, self.sign
        R = math.hypot(X[0], X[1])
        if R < rb * (1.0 + 1e-9) or R > self.rt * (1.0 - 1e-9) or R < self.min_radius:
            return None
        phi_ref = math.remainder(math.atan2(X[1], X[0]) - self.axis, 2.0 * math.pi)
        # VTU coordinates are single precision: 1e-6 relative is about 5e-5 mm
        if abs(sign * phi_ref - self.theta_h(R)) * R > self.tolerance:
            return None
        x = (x[0] / self.scale, x[1] / self.scale)
        r = math.hypot(x[0], x[1])
        phi = math.remainder(math.atan2(x[1], x[0]) - self.axis, 2.0 * math.pi)
        d_n = rb * (sign * phi - self.theta_h(r)) if r > rb else float("nan")
        # tangent towards the tip at the reference point: e_r - u e_theta (positive flank)
        u = math.sqrt(R * R / (rb * rb) - 1.0)
        th = self.axis + sign * self.theta_h(R)
        er = (math.cos(th), math.sin(th))
        et = (-math.sin(th), math.cos(th))
        t = (er[0] - sign * u * et[0], er[1] - sign * u * et[1])
        tn = math.hypot(*t)
        u_t = ((x[0] - X[0]) * t[0] + (x[1] - X[1]) * t[1]) / tn
        return R, u, d_n, u_t


def analyse(args):
    """[(step, time, R, roll angle, d_n, u_t, p_n)] of the flank nodes at every output step."""
    flank = Flank(args)
    results = []
    for step, (time, path) in enumerate(vtu_io.datasets(args.directory)):
        for X, x, p_n in vtu_io.unique_nodes(vtu_io.read_grid(path)):
            m = flank.measure(X, x)
            if m is not None:
                results.append((step, time) + m + (p_n,))
    results.sort()
    return results, flank.rp


def profile_deviations(trace, xi_start, xi_end):
    """ISO 1328-1 profile quantities of TRACE, a list of (xi, d) sorted by the roll length xi and
    linear between its points, over the evaluation range [xi_start, xi_end] (clipped to the
    trace): (F_alpha, f_f_alpha, f_H_alpha) as the module documentation defines them. The mean
    profile line is the least-squares line of the piecewise-linear trace (integrals exact per
    segment), so that unevenly spaced nodes (a mesh refined near the contact) weigh by length."""
    xi0 = max(xi_start, trace[0][0])
    xi1 = min(xi_end, trace[-1][0])
    if not xi1 > xi0:
        raise ValueError(f"evaluation range [{xi_start}, {xi_end}] misses the trace "
                         f"[{trace[0][0]}, {trace[-1][0]}]")

    def at(x):
        for (xa, da), (xb, db) in zip(trace, trace[1:]):
            if xa <= x <= xb:
                return da if xb == xa else da + (db - da) * (x - xa) / (xb - xa)
        return trace[-1][1]

    points = [(xi0, at(xi0))] + [p for p in trace if xi0 < p[0] < xi1] + [(xi1, at(xi1))]
    # least squares of the piecewise-linear d(xi): minimise int (d - a - b xi)^2 dxi; shift the
    # abscissa to the range's start for round-off
    s0 = s1 = s2 = m0 = m1 = 0.0
    for (xa, da), (xb, db) in zip(points, points[1:]):
        h = xb - xa
        ua, ub = xa - xi0, xb - xi0
        s0 += h
        s1 += h * (ua + ub) / 2.0
        s2 += h * (ua * ua + ua * ub + ub * ub) / 3.0
        m0 += h * (da + db) / 2.0
        m1 += h * (ua * (2.0 * da + db) + ub * (da + 2.0 * db)) / 6.0
    b = (s0 * m1 - s1 * m0) / (s0 * s2 - s1 * s1)
    a = (m0 - b * s1) / s0
    d = [p[1] for p in points]
    residual = [p[1] - a - b * (p[0] - xi0) for p in points]
    return max(d) - min(d), max(residual) - min(residual), b * (xi1 - xi0)


def evaluation_range(final, rb, rt, args):
    """(R0, R1) radii of the profile evaluation range L_alpha for the flank nodes FINAL (the
    module documentation: SAP to the tip chamfer start, shortened to --evaluation-fraction)."""
    radii = [r[2] for r in final]
    r0 = args.sap_radius if args.sap_radius > 0 else min(radii)
    r1 = args.tip_chamfer_radius if args.tip_chamfer_radius > 0 else min(max(radii), rt)
    xi0, xi1 = math.sqrt(max(r0 * r0 - rb * rb, 0.0)), math.sqrt(max(r1 * r1 - rb * rb, 0.0))
    xi1 = xi0 + args.evaluation_fraction * (xi1 - xi0)
    return r0, math.hypot(rb, xi1)


def iso1328(results, rb, r0, r1):
    """{step: (time, F_alpha, f_f_alpha, f_H_alpha)} over the radii [r0, r1] for every output
    step of RESULTS (rows of analyse())."""
    xi0, xi1 = math.sqrt(max(r0 * r0 - rb * rb, 0.0)), math.sqrt(max(r1 * r1 - rb * rb, 0.0))
    out = {}
    for step in sorted({r[0] for r in results}):
        rows = [r for r in results if r[0] == step and not math.isnan(r[4])]
        trace = sorted((rb * r[3], r[4]) for r in rows)
        out[step] = (rows[0][1],) + profile_deviations(trace, xi0, xi1)
    return out


def summary(results, rp):
    last = max(r[0] for r in results)
    final = [r for r in results if r[0] == last]
    near = [r[5] for r in final if abs(r[2] - rp) < 1.0]
    upper = [r[5] for r in final if r[2] > rp + 1.0]
    mean = lambda v: sum(v) / len(v) if v else float("nan")
    out = {
        "step": last,
        "nodes": len(final),
        "d_n_min": min(r[4] for r in final),
        "d_n_max": max(r[4] for r in final),
        "u_t_pitch": mean(near),
        "u_t_upper": mean(upper),
        "p_n_max_all_steps": max(r[6] for r in results),
    }
    return out


def iso_summary(values, rb, r0, r1):
    """Summary words of the ISO 1328 quantities VALUES (time, F, f_f, f_H) over radii [r0, r1]."""
    return {"L_alpha_R0": r0, "L_alpha_R1": r1,
            "L_alpha": math.sqrt(r1 * r1 - rb * rb) - math.sqrt(max(r0 * r0 - rb * rb, 0.0)),
            "F_alpha": values[1], "f_f_alpha": values[2], "f_H_alpha": values[3]}


def plot(results, rp, filename, title):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    steps = sorted({r[0] for r in results})
    times = {s: next(r[1] for r in results if r[0] == s) for s in steps}
    fig, axes = plt.subplots(3, 1, figsize=(7.5, 9), sharex=True, constrained_layout=True)
    cmap = plt.get_cmap("viridis")
    # every output step is a curve, coloured by its time (colour bar), not only the first and last
    norm = matplotlib.colors.Normalize(vmin=min(times.values()),
                                       vmax=max(max(times.values()), min(times.values()) + 1e-12))
    for s in steps:
        rows = [r for r in results if r[0] == s]
        c = cmap(norm(times[s]))
        R = [r[2] for r in rows]
        axes[0].plot(R, [1000 * r[4] for r in rows], color=c)
        axes[1].plot(R, [1000 * r[5] for r in rows], color=c)
        axes[2].plot(R, [r[6] for r in rows], color=c)
    for ax in axes:
        ax.axvline(rp, color="gray", ls=":", lw=1)
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("normal deviation d_n (um)")
    axes[1].set_ylabel("tangential displ. u_t (um)\n(> 0: towards the tip)")
    axes[2].set_ylabel("contact pressure p_n (MPa)")
    axes[2].set_xlabel("reference radius R (mm); dotted: pitch circle")
    fig.colorbar(matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap), ax=list(axes),
                 label=f"pseudo-time t of the output ({len(steps)} outputs)")
    axes[0].set_title(title)
    fig.savefig(filename, dpi=110)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("directory")
    p.add_argument("--plot")
    p.add_argument("--title", default="gear flank")
    add_gear_options(p)
    args = p.parse_args()
    results, rp = analyse(args)
    if not results:
        raise SystemExit("gear_flank_analysis.py: no flank nodes found")
    with open(os.path.join(args.directory, "flank_deviation.csv"), "w") as f:
        f.write("step,time,R,roll_angle,d_n,u_t,p_n\n")
        for r in results:
            f.write(",".join(f"{v:.10g}" for v in r) + "\n")
    s = summary(results, rp)
    rb = gear_data(args)[1]
    r0, r1 = evaluation_range([r for r in results if r[0] == s["step"]], rb, gear_data(args)[2], args)
    iso = iso1328(results, rb, r0, r1)
    with open(os.path.join(args.directory, "flank_iso1328.csv"), "w") as f:
        f.write("step,time,L_alpha_R0,L_alpha_R1,F_alpha,f_f_alpha,f_H_alpha\n")
        for step, values in iso.items():
            f.write(",".join(f"{v:.10g}" for v in (step, values[0], r0, r1) + values[1:]) + "\n")
    s.update(iso_summary(iso[s["step"]], rb, r0, r1))
    print(" ".join(f"{k}={v:.6g}" if isinstance(v, float) else f"{k}={v}" for k, v in s.items()))
    if args.plot:
        plot(results, rp, args.plot, args.title)
    return 0


if __name__ == "__main__":
    sys.exit(main())
