#!/usr/bin/env python3
"""Damaged checkpoints, an edited history.csv and resumes with changed entries end with a clear
message naming the file or entry (exit 2), never a crash, a p4est abort or a NaN later.

Usage: check_damaged_restarts.py AUSROLL SOURCE_DIR

The block-slide scene (tests/checks/scenes/block_slide.prm) with a checkpoint every 2 steps is
stopped after step 5 (Checkpoint/Abort after step): its checkpoint holds step 4. Every case copies
that output directory, damages one thing, resumes, and expects the exit status and a message
fragment. Last, an undamaged copy resumes and finishes (exit 0): the checks do not refuse a good
checkpoint.
"""

import os
import shutil
import subprocess
import sys


def run(ausroll, prm, cwd, *args):
    return subprocess.run([ausroll, prm] + list(args), cwd=cwd, capture_output=True, text=True,
                          errors="replace", timeout=300)


def truncate(path, size):
    with open(path, "r+b") as f:
        f.truncate(size)


def flip_bit(path):
    with open(path, "r+b") as f:
        data = bytearray(f.read())
        data[len(data) // 2] ^= 0x10
        f.seek(0)
        f.write(data)


def replace_in(path, old, new, count=1):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    assert old in text, f"{old!r} not in {path}"
    with open(path, "w", encoding="utf-8") as f:
        f.write(text.replace(old, new, count))


def main():
    ausroll, source = sys.argv[1], sys.argv[2]
    here = os.getcwd()
    base = os.path.join(here, "base")
    shutil.rmtree(base, ignore_errors=True)
    os.makedirs(base)
    prm = os.path.join(here, "scene.prm")
    with open(prm, "w", encoding="utf-8") as f:
        f.write(f"include {source}/tests/checks/scenes/block_slide.prm\n"
                "subsection Checkpoint\n  set Interval = 2\nend\n")
    first = run(ausroll, prm, base, "--set", "Checkpoint/Abort after step=5")
    if first.returncode != 99:
        print(f"the interrupted run ended with {first.returncode}:\n{first.stderr}")
        return 1
    files = sorted(os.listdir(os.path.join(base, "out", "checkpoint")))
    print("checkpoint files:", ", ".join(files))
    data = [f for f in files if f.endswith("_fixed.data")][0]

    def damaged(name):
        return f"checkpoint file '{os.path.join('out', 'checkpoint', name)}' is damaged"

    # (name, damage(out directory), extra arguments, exit status, message fragment)
    cases = [
        ("emptied p4est file", lambda o: truncate(f"{o}/checkpoint/mesh", 0), [], 2,
         damaged("mesh") + ": 0 bytes"),
        ("emptied data file", lambda o: truncate(f"{o}/checkpoint/{data}", 0), [], 2,
         damaged(data) + ": 0 bytes"),
        ("truncated data file",
         lambda o: truncate(f"{o}/checkpoint/{data}",
                            os.path.getsize(f"{o}/checkpoint/{data}") // 2), [], 2,
         damaged(data)),
        ("bit flip in the data file", lambda o: flip_bit(f"{o}/checkpoint/{data}"), [], 2,
         damaged(data) + ": its checksum (FNV-1a) differs"),
        ("bit flip in the p4est file", lambda o: flip_bit(f"{o}/checkpoint/mesh"), [], 2,
         damaged("mesh") + ": its checksum (FNV-1a) differs"),
        ("missing data file", lambda o: os.remove(f"{o}/checkpoint/{data}"), [], 2,
         f"checkpoint file 'out/checkpoint/{data}': no such file"),
        ("edited metadata", lambda o: replace_in(f"{o}/checkpoint/metadata.txt", "value step 1 4",
                                                 "value step 1 3"), [], 2,
         damaged("metadata.txt") + ": its checksum differs from its contents"),
        ("emptied metadata", lambda o: truncate(f"{o}/checkpoint/metadata.txt", 0), [], 2,
         damaged("metadata.txt") + ": incomplete"),
        ("history.csv row edited", lambda o: replace_in(f"{o}/history.csv", "\n2,", "\nabc,"), [],
         2, "--resume: 'out/history.csv' line 4 does not start with a step number"),
        ("history.csv header edited", lambda o: replace_in(f"{o}/history.csv", "step,time,",
                                                           "step,t,"), [], 2,
         "--resume: the columns of 'out/history.csv' differ from those this run writes"),
        ("changed Candidate boundaries", lambda o: None,
         ["--set", "Contact/Die 0/Candidate boundaries=1, 3"], 2,
         "Contact/Die 0/Candidate boundaries (checkpoint: '3', now: '1, 3')"),
        ("added monitor point", lambda o: None, ["--set", "Postprocess/Monitor points=tip: 10, 5"],
         2, "Postprocess/Monitor points (checkpoint: '', now: 'tip: 10, 5') (it changes the "
            "columns of history.csv)"),
        ("undamaged", lambda o: None, [], 0, ""),
    ]
    failures = 0
    for name, damage, args, status, expect in cases:
        work = os.path.join(here, "case")
        shutil.rmtree(work, ignore_errors=True)
        shutil.copytree(base, work, symlinks=True)
        damage(os.path.join(work, "out"))
        result = run(ausroll, prm, work, "--resume", *args)
        problems = []
        if result.returncode != status:
            problems.append(f"exit {result.returncode}, expected {status}")
        if expect not in result.stderr:
            problems.append(f"message lacks {expect!r}")
        if "internal error" in result.stderr or result.returncode < 0:
            problems.append("crashed")
        line = next((l for l in result.stderr.splitlines() if "error" in l), "")
        if problems:
            failures += 1
            print(f"FAIL {name}: {'; '.join(problems)}\n     stderr: {result.stderr.strip()}")
        else:
            print(f"ok   {name}: exit {result.returncode} {line[:300]}")
    shutil.rmtree(os.path.join(here, "case"), ignore_errors=True)
    print(f"{len(cases) - failures} of {len(cases)} restart cases handled correctly")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
