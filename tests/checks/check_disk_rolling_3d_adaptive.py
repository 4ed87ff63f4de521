#!/usr/bin/env python3
"""Adaptivity following the die in 3D (issue 15, item 4).

Usage: check_disk_rolling_3d_adaptive.py AUSROLL SOURCE_DIR

Runs tests/checks/scenes/disk_rolling_3d_round_adaptive_short.prm (contact band 6 mm, maximum
level 1, re-adapted every step, 10 degrees of rolling after the feed) and checks:
  - the mesh was adapted while the die rolled: more cells at the end than at the end of the feed
    (the band is refined ahead of the die; cells the die has left stay refined here, since cells
    are only coarsened beyond twice the sum of the band and their size, 2 (6 + 11.4) = 35 mm,
    more than the 7.6 mm rolled);
  - the refined band is at the die: every output sub-cell (the level field of the last VTU, written per
    point of each deal.II patch) whose
    centre lies within 3 mm (half the band) of a closed contact node of the last contact CSV is at
    the maximum level 1 (exact: levels are integers);
  - sign: force_radial < 0 at every loaded step (the die pushes the disk towards its axis);
  - Coulomb per node (last contact CSV): |R_T| <= mu R_n (1 + 1e-8) at every closed node and
    |R_T| = mu R_n within 1e-8 at every slipping node (the cone is exact at convergence).
The np = 2 twin (check/disk_rolling_3d_round_adaptive_short_np2) compares the histories to 1e-8.
"""

import base64
import csv
import math
import os
import re
import struct
import subprocess
import sys
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklist import Checklist, CoulombCone  # noqa: E402

MU = 0.3
MAX_LEVEL = 1
RADIUS = 3.0


def decode(text, fmt):
    """A deal.II zlib-compressed binary VTU data array: base64 header, then base64 blocks."""
    text = text.strip()
    n = struct.unpack("<I", base64.b64decode(text[:8])[:4])[0]
    hlen = 4 * ((4 * (3 + n) + 2) // 3)
    header = struct.unpack(f"<{3 + n}I", base64.b64decode(text[:hlen])[: 4 * (3 + n)])
    data = base64.b64decode(text[hlen:])
    raw, pos = b"", 0
    for size in header[3:]:
        raw += zlib.decompress(data[pos:pos + size])
        pos += size
    width = struct.calcsize(fmt)
    return list(struct.unpack(f"<{len(raw) // width}{fmt}", raw))


def arrays(path):
    text = open(path).read()
    out = {}
    types = {"Float32": "f", "Float64": "d", "Int32": "i", "Int64": "q", "UInt8": "B"}
    for m in re.finditer(r'<DataArray type="(\w+)"([^>]*)format="binary">([^<]*)</DataArray>', text):
        name = re.search(r'Name="([^"]*)"', m.group(2))
        key = name.group(1) if name else "points"
        out[key] = decode(m.group(3), types[m.group(1)])
    return out


def main():
    ausroll, source = sys.argv[1], sys.argv[2]
    prm = os.path.join(source, "tests", "checks", "scenes", "disk_rolling_3d_round_adaptive_short.prm")
    code = subprocess.call([ausroll, prm, "--overwrite"])  # a rerun replaces the earlier results
    if code != 0:
        print(f"FAIL {prm} exited with {code}")
        return 1
    checks = Checklist()
    rows = list(csv.DictReader(open("out/history.csv")))[1:]
    feed_end = [r for r in rows if abs(float(r["time"]) - 4) < 1e-9][0]
    checks(f"mesh adapted while rolling ({feed_end['cells']} -> {rows[-1]['cells']} cells)",
           int(rows[-1]["cells"]) > int(feed_end["cells"]))
    radial = [float(r["die_roll_force_radial"]) for r in rows]
    checks(f"force_radial < 0 at every step (max {max(radial):.6g} N)", all(f < 0 for f in radial))

    cone = CoulombCone(["out/contact_0001.csv"], MU)
    nodes, worst_cone, worst_slip = cone.closed, cone.excess, cone.slip
    checks(f"{len(nodes)} closed nodes, |R_T| <= mu R_n (|R_T| / (mu R_n) - 1 = {worst_cone:.3g})",
           len(nodes) > 0 and worst_cone <= 1e-8)
    checks(f"slipping nodes |R_T| = mu R_n (worst {worst_slip:.2g})", worst_slip <= 1e-8)

    a = arrays("out/solution_0001.0.vtu")
    pts, conn, offs, level = a["points"], a["connectivity"], a["offsets"], a["level"]
    near, low, start = 0, 0, 0
    for c, end in enumerate(offs):
        ids = conn[start:end]
        start = end
        centre = [sum(pts[3 * i + k] for i in ids) / len(ids) for k in range(3)]
        if min(math.dist(centre, p) for p in nodes) <= RADIUS:
            near += 1
            low += any(round(level[i]) != MAX_LEVEL for i in ids)
    checks(f"{near} output sub-cells within {RADIUS} mm of the contact, {low} below level {MAX_LEVEL}",
           near > 0 and low == 0)
    return checks.exit_status()


if __name__ == "__main__":
    sys.exit(main())
