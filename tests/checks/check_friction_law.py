#!/usr/bin/env python3
"""Friction law at every node of the contact CSV of one step, and assertions on history.csv.

  check_friction_law.py OUTDIR TIME [--mu MU] [--friction-factor M --yield-stress SIGMA0]
                        [--levanov] [--tol TOL] [--slip-nodes N] [--total-force]
                        [-- CHECK_HISTORY_ARGS ...]

OUTDIR holds history.csv and contact_NNNN.csv; the CSV whose header says `# time = TIME` is
checked. The slip limit of a node is tau_lim = min(MU p_n, M k) with the shear yield stress
k = SIGMA0 / sqrt(3) (Coulomb: --mu only; Tresca: --friction-factor and --yield-stress only;
Coulomb capped by shear: all three); with --levanov it is Levanov's
tau_lim = M k (1 - exp(-1.25 p_n / SIGMA0)). Checks:
  - every slipping node (status 2): |t_t| = tau_lim, relative to max(tau_lim, 1e-12 MPa);
  - every sticking node (status 1): |t_t| <= tau_lim (1 + TOL);
  - with --slip-nodes: exactly N nodes slip;
  - with --both-branches: some slipping nodes are at MU p_n < M k, some at the cap M k;
  - with --total-force: the die force of history.csv at TIME (column die_<name>_force_x)
    equals the sum of the nodal tangential forces |R_t| of the CSV (flat die with a horizontal
    surface, every node's friction in the same direction), relative TOL: the total is the law
    integrated over the contact, no node left out or pushing the other way;
  - the arguments after `--` go to check_history.py with OUTDIR/history.csv (e.g. the release
    at the end: forces and node counts zero).
The CSV holds 10 significant digits, so TOL = 1e-8 is the round-off of the file, not of the run.
Exit 0 if all hold, 1 otherwise, 2 on usage/data errors.
"""

import argparse
import csv
import glob
import math
import os
import subprocess
import sys


def contact_file_at(directory, time):
    """The contact_NNNN.csv of OUTDIR whose header time is TIME (1e-9 relative)."""
    for name in sorted(glob.glob(os.path.join(directory, "contact_*.csv"))):
        with open(name) as f:
            header = f.readline()
        if header.startswith("# time = "):
            t = float(header[len("# time = "):].split(";")[0])
            if abs(t - time) <= 1e-9 * max(1.0, abs(time)):
                return name
    return None


def main():
    argv = sys.argv[1:]
    history_args = argv[argv.index("--") + 1:] if "--" in argv else []
    argv = argv[:argv.index("--")] if "--" in argv else argv
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("outdir")
    p.add_argument("time", type=float)
    p.add_argument("--mu", type=float, default=math.inf)
    p.add_argument("--friction-factor", type=float)
    p.add_argument("--yield-stress", type=float)
    p.add_argument("--levanov", action="store_true",
                   help="Levanov's law m k (1 - exp(-1.25 p_n / sigma_0)) instead of min(mu p_n, m k)")
    p.add_argument("--tol", type=float, default=1e-8)
    p.add_argument("--slip-nodes", type=int)
    p.add_argument("--total-force", action="store_true")
    p.add_argument("--both-branches", action="store_true",
                   help="at least one slipping node on each branch of min(mu p_n, m k)")
    a = p.parse_args(argv)
    shear = math.inf
    if a.friction_factor is not None:
        shear = a.friction_factor * a.yield_stress / math.sqrt(3.0)
    contact = contact_file_at(a.outdir, a.time)
    if contact is None:
        print(f"check_friction_law.py: no contact CSV at time {a.time} in {a.outdir}",
              file=sys.stderr)
        return 2
    if a.levanov:
        print(f"{contact}: tau_lim = {shear:.10g} MPa (1 - exp(-1.25 p_n / {a.yield_stress:g}))")
    else:
        print(f"{contact}: tau_lim = min({a.mu:g} p_n, {shear:.10g} MPa)")
    try:
        with open(contact) as f:
            rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    except OSError as e:
        print(f"check_friction_law.py: cannot read {contact}: {e.strerror}", file=sys.stderr)
        return 2
    if not rows:
        print(f"check_friction_law.py: {contact} has no nodes", file=sys.stderr)
        return 2

    failed = 0
    worst_slip, worst_stick, n_slip, n_stick, sum_rt = 0.0, 0.0, 0, 0, 0.0
    n_coulomb, n_shear = 0, 0
    for r in rows:
        status = int(float(r["status"]))
        p_n, t_t = float(r["p_n"]), float(r["t_t"])
        if a.levanov:
            limit = shear * (1.0 - math.exp(-1.25 * p_n / a.yield_stress))
        else:
            limit = min(a.mu * p_n if math.isfinite(a.mu) else math.inf, shear)
        if status == 2:
            n_slip += 1
            sum_rt += abs(float(r["R_t"]))
            worst_slip = max(worst_slip, abs(abs(t_t) - limit) / max(limit, 1e-12))
            if limit < shear:
                n_coulomb += 1
            else:
                n_shear += 1
        elif status == 1:
            n_stick += 1
            sum_rt += abs(float(r["R_t"]))
            worst_stick = max(worst_stick, (abs(t_t) - limit) / max(limit, 1e-12))
    ok = worst_slip <= a.tol
    failed += not ok
    print(f"{'ok  ' if ok else 'FAIL'} {n_slip} slipping nodes: max | |t_t| - tau_lim | / tau_lim"
          f" = {worst_slip:.3e} (tol {a.tol:g})")
    ok = worst_stick <= a.tol
    failed += not ok
    print(f"{'ok  ' if ok else 'FAIL'} {n_stick} sticking nodes: max (|t_t| - tau_lim) / tau_lim"
          f" = {worst_stick:.3e} (<= tol {a.tol:g})")
    if a.both_branches:
        ok = n_coulomb > 0 and n_shear > 0
        failed += not ok
        print(f"{'ok  ' if ok else 'FAIL'} slipping nodes on the Coulomb branch {n_coulomb}, "
              f"on the shear cap {n_shear} (both > 0)")
    if a.slip_nodes is not None:
        ok = n_slip == a.slip_nodes
        failed += not ok
        print(f"{'ok  ' if ok else 'FAIL'} slipping nodes {n_slip}, expected {a.slip_nodes}")
    history, time = os.path.join(a.outdir, "history.csv"), a.time
    if a.total_force:
        try:
            hrows = list(csv.DictReader(open(history)))
        except OSError as e:
            print(f"check_friction_law.py: cannot read {history}: {e.strerror}", file=sys.stderr)
            return 2
        row = min(hrows, key=lambda h: abs(float(h["time"]) - time))
        column = f"die_{rows[0]['die']}_force_x"
        fx = float(row[column])
        d = abs(abs(fx) - sum_rt) / max(sum_rt, 1e-12)
        ok = d <= a.tol
        failed += not ok
        print(f"{'ok  ' if ok else 'FAIL'} |{column}(t={time:g})| = {abs(fx):.10g}, sum |R_t| = "
              f"{sum_rt:.10g} (rel. diff {d:.2e}, tol {a.tol:g})")
    if history_args:
        here = os.path.dirname(os.path.abspath(__file__))
        rc = subprocess.run([sys.executable, os.path.join(here, "check_history.py"), history]
                            + history_args).returncode
        if rc == 2:
            return 2
        failed += rc != 0
    print("passed" if not failed else f"{failed} check(s) failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
