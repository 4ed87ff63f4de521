#!/usr/bin/env python3
"""Fail if a GoogleTest case of the unit-test executable belongs to no per-file ctest.

Usage: check_unit_coverage.py UNIT_TEST_EXECUTABLE SUITE [SUITE ...]

tests/CMakeLists.txt registers one ctest per tests/unit/test_<name>.cc with a --gtest_filter of
the suites it found in that file's TEST/TEST_F/TYPED_TEST/TEST_P lines, and passes all those
suites here. A suite the executable defines in another way (a macro that expands to TEST, a
value-parameterised instantiation Prefix/Suite) would silently run in no ctest: this lists the
executable's cases (--gtest_list_tests) and names every suite that is not covered.
"""

import subprocess
import sys


def main(argv):
    if len(argv) < 3:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    executable, covered = argv[1], set(argv[2:])
    run = subprocess.run([executable, "--gtest_list_tests"], capture_output=True, text=True)
    if run.returncode != 0:
        print(f"{executable} --gtest_list_tests failed:\n{run.stdout}{run.stderr}")
        return 1
    suites = {}
    suite = None
    for line in run.stdout.splitlines():
        if not line.strip() or line.startswith(("Running main", "[")):
            continue
        if not line.startswith(" "):  # "Suite." (and a comment for typed suites)
            suite = line.split()[0].rstrip(".")
            suites[suite] = 0
        elif suite is not None:
            suites[suite] += 1
    missing = sorted(s for s in suites if s not in covered)
    for s in missing:
        print(f"suite {s} ({suites[s]} cases) runs in no unit/<file> ctest: define it with "
              f"TEST/TEST_F/TYPED_TEST/TEST_P(Suite, ...) in tests/unit/test_<file>.cc")
    if not suites:
        print("the executable lists no test cases")
        return 1
    if missing:
        return 1
    print(f"all {sum(suites.values())} cases of {len(suites)} suites run in a unit/<file> ctest")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
