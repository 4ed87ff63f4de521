#!/usr/bin/env python3
"""Run ausroll on every malformed .prm in a directory and check that each fails cleanly.

Each file states what it expects in its first lines:
    # expect: <text that must appear in the error message>
    # exit: <status>            (optional, default 2 = input error)
    # args: <extra arguments>   (optional, e.g. --resume; shell-quoted: --set "A/B=c d"; the
                                 two characters \\n inside quotes become a line break)
    # with: <files>             (optional: files next to the case it needs, e.g. an include
                                 that is not itself a case: name them *.inc)
    # mkdir: <directories>      (optional: directories to create in the working directory)
    # mkfifo: <paths>           (optional: named pipes to create there, e.g. a .prm that would
                                 block a reader forever)
    # symlink: <link> <target>  (optional: a symbolic link to create there; a link to itself is
                                 a loop)
    # file: <path>              (optional: what to pass as FILE.prm instead of the case itself;
                                 an option such as --print-parameters=json is passed as it is)
A case passes if ausroll exits with that status, prints the expected text on stderr, does not
crash (no signal, no "internal error"), keeps its message under 4000 characters, stays below 8 GB of memory and 120 s, and (for an input
error) leaves no solution.pvd and no output directory behind.

Usage: check_bad_inputs.py AUSROLL DIRECTORY [--shard K/N]
With --shard K/N (1 <= K <= N) only every N-th case of the sorted list is run, starting with the
K-th: the N shards together run every case once (ctest runs them as check/bad_input/shard_K_of_N,
side by side under ctest -j).
"""

import os
import resource
import shlex
import shutil
import subprocess
import sys
import tempfile


def expectations(path):
    e = {"expect": None, "exit": 2, "args": [], "with": [], "mkdir": [], "mkfifo": [],
         "symlink": [], "file": None}
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            line = line.lstrip("\ufeff")
            for key in e:
                if line.startswith(f"# {key}:"):
                    value = line.split(":", 1)[1].strip()
                    if key == "args":
                        e[key] = [a.replace("\\n", "\n") for a in shlex.split(value)]
                    elif key in ("with", "mkdir", "mkfifo", "symlink"):
                        e[key] = shlex.split(value)
                    elif key == "exit":
                        e[key] = int(value)
                    else:
                        e[key] = value
    return e


def limit_memory():
    resource.setrlimit(resource.RLIMIT_AS, (8 << 30, 8 << 30))


def main():
    args = sys.argv[1:]
    shard, n_shards = 1, 1
    if len(args) == 4 and args[2] == "--shard":
        try:
            shard, n_shards = (int(v) for v in args[3].split("/"))
        except ValueError:
            shard = 0
        args = args[:2]
    if len(args) != 2 or not 1 <= shard <= n_shards:
        print("usage: check_bad_inputs.py AUSROLL DIRECTORY [--shard K/N]", file=sys.stderr)
        return 2
    ausroll, directory = args
    cases = sorted(f for f in os.listdir(directory) if f.endswith(".prm"))[shard - 1::n_shards]
    if not cases:
        print(f"no .prm cases in {directory} (shard {shard}/{n_shards})")
        return 1
    failures = 0
    for name in cases:
        path = os.path.join(directory, name)
        e = expectations(path)
        expect, status, args = e["expect"], e["exit"], e["args"]
        if expect is None:
            print(f"{name}: no '# expect:' line")
            failures += 1
            continue
        work = tempfile.mkdtemp(prefix="ausroll_bad_")
        try:
            # files the case refers to (e.g. meshes) are resolved relative to the .prm file
            shutil.copy(path, work)
            for other in e["with"]:
                shutil.copy(os.path.join(directory, other), work)
            for d in e["mkdir"]:
                os.makedirs(os.path.join(work, d), exist_ok=True)
            for f in e["mkfifo"]:
                os.mkfifo(os.path.join(work, f))
            if e["symlink"]:
                os.symlink(e["symlink"][1], os.path.join(work, e["symlink"][0]))
            target = os.path.join(work, e["file"] if e["file"] else name)
            if e["file"] and e["file"].startswith("-"):  # an option instead of a file
                target = e["file"]
            before = set(os.listdir(work))
            try:
                run = subprocess.run([ausroll, target] + args, cwd=work, capture_output=True,
                                     text=True, errors="replace", timeout=120,
                                     preexec_fn=limit_memory)
            except subprocess.TimeoutExpired:
                failures += 1
                print(f"FAIL {name}: no answer within 120 s")
                continue
            created = sorted(set(os.listdir(work)) - before)
            leftovers = [os.path.join(r, f) for r, _, fs in os.walk(work) for f in fs
                         if f == "solution.pvd"]
            problems = []
            if run.returncode != status:
                problems.append(f"exit status {run.returncode}, expected {status}")
            if expect not in run.stderr:
                problems.append(f"message lacks '{expect}'")
            if len(run.stderr) > 4000:
                problems.append(f"message of {len(run.stderr)} characters (at most 4000)")
            if "ausroll: internal error" in run.stderr or run.returncode < 0:
                problems.append("crashed")
            if leftovers and status == 2:
                problems.append("left " + ", ".join(leftovers))
            if created and status in (1, 2):
                problems.append("created " + ", ".join(created))
            if problems:
                failures += 1
                print(f"FAIL {name}: {'; '.join(problems)}\n     stderr: {run.stderr.strip()}")
            else:
                lines = run.stderr.strip().splitlines()
                shown = next((l for l in lines if "error" in l), lines[-1] if lines else "")
                print(f"ok   {name}: {shown[:300]}")
        finally:
            shutil.rmtree(work)
    print(f"{len(cases) - failures} of {len(cases)} malformed inputs handled correctly")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
