#!/usr/bin/env python3
"""An error found on one rank only ends every rank with its message (no rank left waiting).

Usage: check_rank_error.py AUSROLL SOURCE_DIR MPIEXEC

On 2 ranks, a directory named history.csv in the output directory: only rank 0 writes
history.csv, so only rank 0 finds that it cannot (before: rank 1 waited forever in its next
collective call). Expected within 60 s: exit status 2 (MPI_Abort with the input-error status),
the message naming the file, and the note that it was found on rank 0 only.
"""

import os
import shutil
import subprocess
import sys


def main():
    ausroll, source, mpiexec = sys.argv[1], sys.argv[2], sys.argv[3]
    work = os.path.join(os.getcwd(), "work")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(os.path.join(work, "out", "history.csv"))
    prm = os.path.join(source, "tests", "checks", "scenes", "block_slide.prm")
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    try:
        result = subprocess.run([mpiexec, "-np", "2", ausroll, prm], cwd=work, env=env,
                                capture_output=True, text=True, errors="replace", timeout=60)
    except subprocess.TimeoutExpired:
        print("FAIL: the ranks did not end within 60 s")
        return 1
    problems = []
    if result.returncode != 2:
        problems.append(f"exit {result.returncode}, expected 2")
    for text in ("Output/Directory: cannot write 'out/history.csv'",
                 "the error was found on rank 0 only"):
        if text not in result.stderr:
            problems.append(f"message lacks {text!r}")
    if problems:
        print("FAIL: " + "; ".join(problems) + "\n" + result.stderr)
        return 1
    print("ok: exit 2\n" + result.stderr)
    shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
