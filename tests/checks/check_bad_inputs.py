#!/usr/bin/env python3
"""Run ausroll on every malformed .prm in a directory and check that each fails cleanly.

Each file states what it expects in its first lines:
    # expect: <text that must appear in the error message>
    # exit: <status>            (optional, default 2 = input error)
    # args: <extra arguments>   (optional, e.g. --resume)
A case passes if ausroll exits with that status, prints the expected text on stderr, does not
crash (no signal, no "internal error") and leaves no solution.pvd behind.
"""

import os
import shutil
import subprocess
import sys
import tempfile


def expectations(path):
    expect, status, args = None, 2, []
    with open(path) as f:
        for line in f:
            if line.startswith("# expect:"):
                expect = line.split(":", 1)[1].strip()
            elif line.startswith("# exit:"):
                status = int(line.split(":", 1)[1])
            elif line.startswith("# args:"):
                args = line.split(":", 1)[1].split()
    return expect, status, args


def main():
    if len(sys.argv) != 3:
        print("usage: check_bad_inputs.py AUSROLL DIRECTORY", file=sys.stderr)
        return 2
    ausroll, directory = sys.argv[1], sys.argv[2]
    cases = sorted(f for f in os.listdir(directory) if f.endswith(".prm"))
    failures = 0
    for name in cases:
        path = os.path.join(directory, name)
        expect, status, args = expectations(path)
        if expect is None:
            print(f"{name}: no '# expect:' line")
            failures += 1
            continue
        work = tempfile.mkdtemp(prefix="ausroll_bad_")
        try:
            # files the case refers to (e.g. meshes) are resolved relative to the .prm file
            shutil.copy(path, work)
            run = subprocess.run([ausroll, os.path.join(work, name)] + args, cwd=work,
                                 capture_output=True, text=True, timeout=120)
            leftovers = [os.path.join(r, f) for r, _, fs in os.walk(work) for f in fs
                         if f == "solution.pvd"]
            problems = []
            if run.returncode != status:
                problems.append(f"exit status {run.returncode}, expected {status}")
            if expect not in run.stderr:
                problems.append(f"message lacks '{expect}'")
            if "internal error" in run.stderr or run.returncode < 0:
                problems.append("crashed")
            if leftovers and status == 2:
                problems.append("left " + ", ".join(leftovers))
            if problems:
                failures += 1
                print(f"FAIL {name}: {'; '.join(problems)}\n     stderr: {run.stderr.strip()}")
            else:
                print(f"ok   {name}: {run.stderr.strip().splitlines()[-1] if run.stderr.strip() else ''}")
        finally:
            shutil.rmtree(work)
    print(f"{len(cases) - failures} of {len(cases)} malformed inputs handled correctly")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
