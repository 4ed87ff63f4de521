#!/usr/bin/env python3
"""Relative 3D effect on the residual flank deviation: ratios of d_n minima of a 3D gear roll,
the 3D slice and the 2D run on the same section (doc/scenes/gear_rolling_3d.md, "Section level 2").

Usage: ratios.py --2d 2D_OUT/flank_deviation.csv --3d OUT/flank_deviation_3d.csv
                 [--slice SLICE_OUT/flank_deviation_3d.csv] [--tip-radius 49.306] [--margin 0.1]

The CSVs are those of scripts/gear_flank_analysis.py (2D, its last step) and
scripts/gear_flank_3d.py (3D: the layer z = 0 is the mid-face, the largest z the face end; for
the slice every layer is the same plane-strain answer, the z = 0 layer is taken). d_n min is
taken over the flank nodes below the tip corner (R < tip radius - margin): the corner node at the
addendum circle (R = 49.31 mm) is the edge of the tip land, not a flank point, and its d_n jumps
between runs. Prints d_n min (um) with its radius for each profile and the ratios
3D mid-face / 2D, face end / mid-face, face end / 2D, and with --slice: slice / 2D and
3D mid-face / slice.
"""

import argparse
import csv


def profile_2d(path):
    rows = list(csv.DictReader(open(path)))
    last = max(int(r["step"]) for r in rows)
    return [(float(r["R"]), float(r["d_n"])) for r in rows if int(r["step"]) == last]


def layers_3d(path):
    out = {}
    for r in csv.DictReader(open(path)):
        out.setdefault(float(r["Z"]), []).append((float(r["R"]), float(r["d_n"])))
    zs = sorted(out)
    return out[zs[0]], out[zs[-1]], zs


def minimum(profile, r_max):
    R, d = min(((R, d) for R, d in profile if R < r_max), key=lambda p: p[1])
    return 1000 * d, R


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--2d", dest="two", required=True)
    p.add_argument("--3d", dest="three", required=True)
    p.add_argument("--slice")
    p.add_argument("--tip-radius", type=float, default=49.306)
    p.add_argument("--margin", type=float, default=0.1)
    args = p.parse_args()
    r_max = args.tip_radius - args.margin
    d2, R2 = minimum(profile_2d(args.two), r_max)
    mid, end, zs = layers_3d(args.three)
    dm, Rm = minimum(mid, r_max)
    de, Re = minimum(end, r_max)
    print(f"layers={len(zs)} z_end={zs[-1]:.4g} (R < {r_max:.4g} mm)")
    print(f"2D d_n_min={d2:.4f} um at R={R2:.2f}")
    print(f"3D mid-face d_n_min={dm:.4f} um at R={Rm:.2f}")
    print(f"3D face end d_n_min={de:.4f} um at R={Re:.2f}")
    print(f"ratio mid/2D={dm / d2:.4f} end/mid={de / dm:.4f} end/2D={de / d2:.4f}")
    if args.slice:
        ds, Rs = minimum(layers_3d(args.slice)[0], r_max)
        print(f"slice d_n_min={ds:.4f} um at R={Rs:.2f}")
        print(f"ratio slice/2D={ds / d2:.4f} mid/slice={dm / ds:.4f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
