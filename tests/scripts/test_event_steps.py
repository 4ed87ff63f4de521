#!/usr/bin/env python3
"""Unit test of benchmarks/hard_cases/event_steps.py on a synthetic log (no simulation): the
split into steps with and without contact status changes and the count of steps since the last
event must equal the values worked out by hand below. Exit 0 if all pass."""

import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "benchmarks", "hard_cases"))
sys.path.insert(0, os.path.join(HERE, "..", "checks"))
import event_steps as es  # noqa: E402
from checklist import Checklist  # noqa: E402  (tests/checks/checklist.py)

check = Checklist()


# (solves, status changes) per step; other lines of a verbose log in between are ignored
steps = [(2, 0), (9, 1), (5, 0), (4, 0), (3, 0), (3, 0), (3, 0), (11, 2), (4, 0)]
lines = []
for n, c in steps:
    lines.append(f"step  1  t = 0.1  ( 10.0%)  Newton {n:2d}  cutbacks 0")
    lines.append("    Newton summary: ignored line with 7 Newton iterations, 3 contact status changes?")
    lines.append(f"  step control: {n} Newton iterations, {c} contact status changes, 0 cutbacks: "
                 "next dt = 0.01")
# the summary line above must not match: it has no "step control:"
read = es.read_steps(lines)
check(f"read_steps reads the step-control lines only: {read}", read == steps)

s = es.summary(read)
check(f"all: 9 steps, 44 solves, median 4: {s['all']}",
      (s["all"]["steps"], s["all"]["solves"], s["all"]["median"]) == (9, 44, 4))
check(f"events: 2 steps, 20 solves, median 10: {s['events']}",
      (s["events"]["steps"], s["events"]["solves"], s["events"]["median"]) == (2, 20, 10))
check(f"others: 7 steps, 24 solves, median 3: {s['others']}",
      (s["others"]["steps"], s["others"]["solves"], s["others"]["median"]) == (7, 24, 3))
# since the last event: step 1 (before any event) counts as 4 or more; after the event of
# step 2: 5 (1), 4 (2), 3 (3), 3 and 3 (4 or more); after step 8: 4 (1)
check(f"1 after an event: 5 and 4: {s['since'][1]}",
      s["since"][1]["solves"] == 9 and s["since"][1]["steps"] == 2)
check(f"2 after an event: 4: {s['since'][2]}", s["since"][2]["solves"] == 4)
check(f"3 after an event: 3: {s['since'][3]}", s["since"][3]["solves"] == 3)
check(f"4 or more: 2, 3, 3: {s['since'][4]}",
      (s["since"][4]["steps"], s["since"][4]["solves"]) == (3, 8))

sys.exit(check.exit_status())
