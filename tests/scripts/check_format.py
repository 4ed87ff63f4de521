#!/usr/bin/env python3
"""Fail on C++ files that clang-format (with the repository's .clang-format) would change.

Usage: check_format.py [SOURCE_DIR]      (default: the repository this script lives in)

Checks every *.h and *.cc under include/, source/, tests/ and benchmarks/ with
`clang-format --dry-run -Werror` and prints the files (and clang-format's first complaints) that
are not formatted. Mend them with `clang-format -i FILE`; protect an ASCII diagram in a comment
with `// clang-format off` ... `// clang-format on`.
The clang-format executable is $CLANG_FORMAT, else clang-format on PATH (scripts/setup.sh
installs it). Without one the check fails with a message saying so: it never passes unchecked.
"""

import os
import shutil
import subprocess
import sys

FOLDERS = ("include", "source", "tests", "benchmarks")
SUFFIXES = (".h", ".cc")


def cpp_files(root):
    for folder in FOLDERS:
        for dirpath, dirnames, filenames in os.walk(os.path.join(root, folder)):
            dirnames.sort()
            for name in sorted(filenames):
                if name.endswith(SUFFIXES):
                    yield os.path.join(dirpath, name)


def main(argv):
    root = argv[1] if len(argv) > 1 else os.path.dirname(os.path.dirname(
        os.path.dirname(os.path.abspath(__file__))))
    clang_format = os.environ.get("CLANG_FORMAT") or shutil.which("clang-format")
    if not clang_format or not shutil.which(clang_format):
        print("check_format.py: clang-format not found (install the Debian package clang-format, "
              "e.g. by scripts/setup.sh, or set CLANG_FORMAT); the formatting was NOT checked",
              file=sys.stderr)
        return 1
    if not os.path.isfile(os.path.join(root, ".clang-format")):
        print(f"check_format.py: {root} has no .clang-format", file=sys.stderr)
        return 2
    version = subprocess.run([clang_format, "--version"], capture_output=True,
                             text=True).stdout.strip()
    files = list(cpp_files(root))
    bad = []
    # one clang-format process per batch of files; a failing batch is rechecked file by file
    for start in range(0, len(files), 50):
        batch = files[start:start + 50]
        run = subprocess.run([clang_format, "--dry-run", "-Werror", "--style=file"] + batch,
                             cwd=root, capture_output=True, text=True)
        if run.returncode == 0:
            continue
        for path in batch:
            one = subprocess.run([clang_format, "--dry-run", "-Werror", "--style=file", path],
                                 cwd=root, capture_output=True, text=True)
            if one.returncode != 0:
                bad.append((path, one.stderr))
    for path, message in bad:
        rel = os.path.relpath(path, root)
        print(f"not formatted: {rel}   (mend: clang-format -i {rel})")
        print("    " + "\n    ".join(message.strip().splitlines()[:6]))
    if bad:
        print(f"{len(bad)} of {len(files)} C++ files are not formatted ({version})")
        return 1
    print(f"all {len(files)} C++ files formatted ({version})")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
