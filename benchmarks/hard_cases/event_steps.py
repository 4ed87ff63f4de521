#!/usr/bin/env python3
"""Where the Newton solves of a run with contact go: steps with and without contact status
changes (doc/studies/hard_cases.md, section 11).

Reads the terminal log of a run with `Output/Verbosity = verbose` and `Loading/Step control =
adaptive` (its "step control: N Newton iterations, C contact status changes" lines) and prints per
log: the steps, their solves (of the accepted attempts) and the median per step; the same for
the "event" steps (C > 0: a node closed or opened or switched between stick and slip) and for the
other steps; and the other steps by how many steps ago the last event was (1, 2, 3, 4 or more).

    python3 benchmarks/hard_cases/event_steps.py RUN.log [RUN2.log ...]

Runs nothing; the runs of section 11 were made with
    build/ausroll prm/hard_punch.prm --set "Geometry/Local refinements=2" \\
        --set Output/Verbosity=verbose --set Output/Interval=0 > RUN.log
"""

import re
import statistics
import sys

STEP_CONTROL = re.compile(r"step control: (\d+) Newton iterations, (\d+) contact status changes")


def read_steps(lines):
    """(solves, status changes) of every accepted step, in order."""
    steps = []
    for line in lines:
        m = STEP_CONTROL.search(line)
        if m:
            steps.append((int(m.group(1)), int(m.group(2))))
    return steps


def summary(steps):
    """Counts, solves and medians of all, event and other steps, and the other steps by the
    number of steps since the last event (4: four or more, also before the first event)."""
    def part(values):
        return {"steps": len(values), "solves": sum(values),
                "median": statistics.median(values) if values else 0}

    since, after = 4, {1: [], 2: [], 3: [], 4: []}
    for solves, changes in steps:
        if changes > 0:
            since = 0
        else:
            since = min(since + 1, 4)
            after[since].append(solves)
    return {"all": part([s for s, _ in steps]),
            "events": part([s for s, c in steps if c > 0]),
            "others": part([s for s, c in steps if c == 0]),
            "since": {k: part(v) for k, v in after.items()}}


def main(paths):
    for path in paths:
        with open(path, encoding="utf-8", errors="replace") as f:
            steps = read_steps(f)
        if not steps:
            print(f"{path}: no 'step control:' lines (needs Output/Verbosity = verbose and "
                  "Loading/Step control = adaptive)")
            return 1
        s = summary(steps)
        print(path)
        for key, label in (("all", "all steps"), ("events", "with status changes"),
                           ("others", "without")):
            p = s[key]
            print(f"  {label:20s} {p['steps']:5d} steps {p['solves']:6d} solves  median {p['median']:g}")
        for k, p in s["since"].items():
            label = f"{k} after an event" if k < 4 else "4 or more after"
            print(f"    {label:18s} {p['steps']:5d} steps {p['solves']:6d} solves  median {p['median']:g}")
    return 0


if __name__ == "__main__":
    if len(sys.argv) < 2:
        print(__doc__)
        sys.exit(1)
    sys.exit(main(sys.argv[1:]))
