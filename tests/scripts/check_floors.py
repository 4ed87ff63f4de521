#!/usr/bin/env python3
"""Fail on an upward include between areas (the floor order of DEVELOPERS.md, "Layout").

Usage: check_floors.py [SOURCE_DIR]      (default: the repository this script lives in)
       check_floors.py --self-test       (the rules on a small synthetic tree)

Every C++ file under include/ausroll/<area>/ and source/<area>/ belongs to <area> (sub-folders
such as contact/surfaces/ belong to their area). A file may include <ausroll/<other>/...> only if
<other> is its own area or a lower floor:

    core -> geometry -> material -> contact -> mechanics | thermal -> solver -> adaptivity -> io -> scene

mechanics and thermal are peers on the same floor: each may include core, geometry, material and
contact, neither includes the other, and solver and everything above may include both.
source/main.cc (argument parsing and dispatch) stands above every area. A folder that is not in
the order fails too: a new area needs its floor here and in DEVELOPERS.md.
Prints every offending include as file:line and exits 1; exits 0 when the tree keeps the order.
"""

import os
import re
import sys
import tempfile

# Floor of each area; equal floors are peers that must not include each other.
FLOORS = {
    "core": 0,
    "geometry": 1,
    "material": 2,
    "contact": 3,
    "mechanics": 4,
    "thermal": 4,
    "solver": 5,
    "adaptivity": 6,
    "io": 7,
    "scene": 8,
}
TOP_FILES = {os.path.join("source", "main.cc")}
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]ausroll/([A-Za-z0-9_]+)/')
SUFFIXES = (".h", ".cc", ".hh", ".cpp", ".hpp")


def allowed(area, other):
    """Whether a file of `area` may include a header of `other`."""
    return other == area or FLOORS[other] < FLOORS[area]


def check(root):
    """Return the list of problems (strings 'file:line: ...') of the tree at `root`."""
    problems = []
    for top in ("include/ausroll", "source"):
        base = os.path.join(root, top)
        for dirpath, dirnames, filenames in os.walk(base):
            dirnames.sort()
            for name in sorted(filenames):
                if not name.endswith(SUFFIXES):
                    continue
                path = os.path.join(dirpath, name)
                rel = os.path.relpath(path, root)
                parts = os.path.relpath(path, base).split(os.sep)
                if rel in TOP_FILES:
                    continue
                if len(parts) < 2:
                    problems.append(f"{rel}: not inside an area folder of {top}/")
                    continue
                area = parts[0]
                if area not in FLOORS:
                    problems.append(f"{rel}: area '{area}' has no floor (add it to FLOORS in "
                                    f"tests/scripts/check_floors.py and to DEVELOPERS.md)")
                    continue
                with open(path, encoding="utf-8", errors="replace") as f:
                    for number, line in enumerate(f, 1):
                        m = INCLUDE.match(line)
                        if not m:
                            continue
                        other = m.group(1)
                        if other not in FLOORS:
                            problems.append(f"{rel}:{number}: includes unknown area '{other}': "
                                            f"{line.strip()}")
                        elif not allowed(area, other):
                            kind = "a peer" if FLOORS[other] == FLOORS[area] else "a higher floor"
                            problems.append(f"{rel}:{number}: {area} includes {other} ({kind}): "
                                            f"{line.strip()}")
    return problems


def self_test():
    """The rules on a synthetic tree: each upward or peer include found, lawful ones accepted."""
    files = {
        "include/ausroll/core/a.h": "#include <deal.II/base/point.h>\n",
        "include/ausroll/contact/surfaces/s.h": "#include <ausroll/geometry/g.h>\n",
        "include/ausroll/thermal/t.h": "#include <ausroll/contact/c.h>\n"
                                       "#include <ausroll/mechanics/m.h>\n",
        "source/mechanics/m.cc": "#include <ausroll/mechanics/m.h>\n\n"
                                 "  #  include <ausroll/solver/x.h>\n",
        "source/solver/x.cc": "#include <ausroll/thermal/t.h>\n#include <ausroll/mechanics/m.h>\n",
        "source/main.cc": "#include <ausroll/scene/scene.h>\n",
        "source/metallurgy/p.cc": "#include <ausroll/core/a.h>\n",
    }
    expected = [
        "include/ausroll/thermal/t.h:2: thermal includes mechanics (a peer)",
        "source/mechanics/m.cc:3: mechanics includes solver (a higher floor)",
        "source/metallurgy/p.cc: area 'metallurgy' has no floor",
    ]
    with tempfile.TemporaryDirectory() as root:
        for rel, text in files.items():
            os.makedirs(os.path.dirname(os.path.join(root, rel)), exist_ok=True)
            with open(os.path.join(root, rel), "w") as f:
                f.write(text)
        problems = check(root)
    ok = len(problems) == len(expected) and all(
        p.startswith(e) for p, e in zip(sorted(problems), sorted(expected)))
    if not ok:
        print("check_floors.py self-test FAILED\n expected:\n  " + "\n  ".join(expected)
              + "\n found:\n  " + "\n  ".join(problems))
        return 1
    print(f"check_floors.py self-test: {len(expected)} violations found as expected")
    return 0


def main(argv):
    if argv[1:] == ["--self-test"]:
        return self_test()
    if len(argv) > 2:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    root = argv[1] if len(argv) == 2 else os.path.dirname(os.path.dirname(
        os.path.dirname(os.path.abspath(__file__))))
    if not os.path.isdir(os.path.join(root, "include", "ausroll")):
        print(f"check_floors.py: {root} has no include/ausroll/", file=sys.stderr)
        return 2
    problems = check(root)
    for p in problems:
        print(p)
    if problems:
        print(f"{len(problems)} include(s) break the floor order "
              f"(core -> geometry -> material -> contact -> mechanics | thermal -> solver -> "
              f"adaptivity -> io -> scene; DEVELOPERS.md, Layout)")
        return 1
    print("floor order kept: no upward include between areas")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
