"""Shared by the scene checks: a list of named assertions, each printed as "ok" or "FAIL", and
the exit status at the end (the checks are run as ctests, which look at the exit status)."""

import subprocess


def ausroll_command(ausroll, prm, settings=()):
    """``ausroll prm --overwrite`` with ``--set ENTRY=VALUE`` for every one of @p settings."""
    command = [ausroll, prm, "--overwrite"]
    for setting in settings:
        command += ["--set", setting]
    return command


def run_scene(ausroll, prm):
    """Run ``ausroll prm --overwrite``, print its output, and return its standard output, or None
    (with the reason printed) if it failed."""
    run = subprocess.run(ausroll_command(ausroll, prm), capture_output=True, text=True)
    print(run.stdout)
    if run.returncode != 0:
        print(run.stderr)
        print(f"FAIL {prm} exited with {run.returncode}")
        return None
    return run.stdout


class Checklist:
    """Collects assertions: ``checks(label, ok)`` prints and records one, ``checks.exit_status()``
    prints the summary and returns 0 if all held, else 1."""

    def __init__(self):
        self.failures = []

    def __call__(self, label, ok):
        print(f"{'ok  ' if ok else 'FAIL'} {label}")
        if not ok:
            self.failures.append(label)

    def exit_status(self):
        print("passed" if not self.failures else f"{len(self.failures)} check(s) failed")
        return 1 if self.failures else 0


class CoulombCone:
    """Per-node Coulomb assertion data of 3D contact_*.csv files (columns status, x, y, z, R_n, R_t1,
    R_t2; status 0 open, 1 stick, 2 slip) for friction coefficient MU:

    * ``closed``: the (x, y, z) of every closed node-step;
    * ``excess``: the largest |R_t| / (mu R_n) - 1 over them (<= 1e-8: inside the cone);
    * ``slip``: the largest |R_t / (mu R_n) - 1| over the slipping ones (0: on the cone)."""

    def __init__(self, contact_files, mu):
        import csv
        import math

        self.closed, self.excess, self.slip = [], -math.inf, 0.0
        for name in contact_files:
            with open(name) as f:
                for r in csv.DictReader(line for line in f if not line.startswith("#")):
                    if int(r["status"]) == 0:
                        continue
                    self.closed.append((float(r["x"]), float(r["y"]), float(r["z"])))
                    r_n = float(r["R_n"])
                    r_t = math.hypot(float(r["R_t1"]), float(r["R_t2"]))
                    if r_n > 0.0:
                        ratio = r_t / (mu * r_n)
                    else:  # the apex of the cone holds only a node without any force
                        ratio = 1.0 if r_n == 0.0 and r_t == 0.0 else math.inf
                    self.excess = max(self.excess, ratio - 1.0)
                    if int(r["status"]) == 2:
                        self.slip = max(self.slip, abs(ratio - 1.0))

    def check(self, checks, tolerance=1e-8):
        """Record in @p checks (a Checklist): some node-steps closed, every one inside the cone
        and every slipping one on it, to @p tolerance."""
        checks(f"{len(self.closed)} closed node-steps, |R_T| <= mu R_n "
               f"(|R_T| / (mu R_n) - 1 = {self.excess:.3g})",
               len(self.closed) > 0 and self.excess <= tolerance)
        checks(f"slipping nodes |R_T| = mu R_n (worst {self.slip:.2g})", self.slip <= tolerance)
