#!/usr/bin/env python3
"""Tables of benchmarks/parallel/weak_scaling_3d.sh: per-rank costs of the 3D gear scene.

Usage: weak_scaling_3d.py WORK

For every WORK/L<level>_np<n>.log (Output/Verbosity = verbose) and its lines in WORK/runs.txt:
DoFs, Newton solves, assembly calls, linear iterations per solve, the wall seconds of rank 0's
timer sections (assembly, linear solve), the CPU seconds of rank 0 per linear solve (from the
verbose lines), the CPU of the whole run (user + sys of every rank, /usr/bin/time) and the load
average before and after. Derived per-rank costs (microseconds per DoF owned by a rank, DoFs / np):
  solve      = rank-0 CPU per linear solve (AMG set-up + Krylov, or the direct solve)
  solve/it   = the same per Krylov iteration
  other      = (run CPU / np - rank-0 solve CPU) / assemblies: everything outside the linear
               solves (assembly, contact search, set-up, output, MPI waits) per assembly, an upper
               bound of the assembly's CPU (the timer sections are wall times, meaningless for
               np = 2 on a loaded machine)
Prints a Markdown table.
"""

import glob
import os
import re
import sys


def parse_log(path):
    text = open(path).read()
    out = {}
    m = re.search(r"mesh: (\d+) cells, (\d+) DoFs", text)
    out["dofs"] = int(m.group(2)) if m else None
    solves = re.findall(r"linear solve: (\d+) iterations, ([0-9.e+-]+) s wall, ([0-9.e+-]+) s CPU", text)
    out["solves"] = len(solves)
    out["krylov"] = sum(int(s[0]) for s in solves)
    out["solve_cpu"] = sum(float(s[2]) for s in solves)
    out["solve_wall_lines"] = sum(float(s[1]) for s in solves)
    m = re.search(r"Newton: (\d+) solves in (\d+) steps", text)
    out["newton"] = int(m.group(1)) if m else None
    for section in ("assembly", "linear solve", "setup"):
        m = re.search(r"\| " + section + r"\s+\|\s+(\d+) \|\s+([0-9.e+-]+)s", text)
        out[section] = (int(m.group(1)), float(m.group(2))) if m else (0, 0.0)
    m = re.search(r"Total wallclock time elapsed since start\s+\|\s+([0-9.e+-]+)s", text)
    out["wall"] = float(m.group(1)) if m else None
    m = re.search(r"^time: ([0-9.]+) s wall, ([0-9.]+) s CPU", text, re.M)
    out["cpu_all"] = float(m.group(2)) if m else None
    return out


def parse_runs(path):
    runs = {}
    name = None
    for line in open(path):
        m = re.match(r"### (\S+) steps (\d+) load before: ([0-9.]+) ([0-9.]+) ([0-9.]+)", line)
        if m:
            name = m.group(1)
            runs[name] = {"steps": int(m.group(2)), "load_before": float(m.group(3))}
            continue
        m = re.match(r"(\S+) time: user ([0-9.]+) sys ([0-9.]+) wall ([0-9.]+) maxrss_kB (\d+)", line)
        if m and m.group(1) in runs:
            r = runs[m.group(1)]
            r["cpu"] = float(m.group(2)) + float(m.group(3))
            r["time_wall"] = float(m.group(4))
            r["maxrss_MB"] = int(m.group(5)) / 1024.0
            continue
        m = re.match(r"(\S+) exit (\d+) load after: ([0-9.]+)", line)
        if m and m.group(1) in runs:
            runs[m.group(1)]["exit"] = int(m.group(2))
            runs[m.group(1)]["load_after"] = float(m.group(3))
    return runs


def main():
    work = sys.argv[1]
    runs = parse_runs(os.path.join(work, "runs.txt"))
    print("| level (x coarse layers) | DoFs | np | load before / after | Newton solves | assemblies | Krylov it. per solve "
          "| solve CPU s per solve (rank 0) | other CPU s per assembly and rank | run CPU s (all ranks) "
          "| wall s (rank 0 timer) | assembly wall s per call (rank 0 timer) | peak RSS MB (largest process) "
          "| solve µs per DoF of a rank | solve µs per DoF of a rank and Krylov it. | other µs per DoF of a rank and assembly |")
    print("|" + "---:|" * 16)
    for path in sorted(glob.glob(os.path.join(work, "L*_np*.log"))):
        name = os.path.basename(path)[:-4]
        level, np_ = re.match(r"L(\d+(?:x\d+)?)_np(\d+)", name).groups()
        np_ = int(np_)
        log = parse_log(path)
        run = runs.get(name, {})
        if not log["dofs"] or not log["solves"]:
            print(f"| {level} | {log['dofs']} | {np_} | no linear solve logged |" + " |" * 12)
            continue
        if run.get("exit") != 0 or log["cpu_all"] is None:
            # stopped before its end: the linear solves that finished
            per_rank = log["dofs"] / np_
            solve_cpu = log["solve_cpu"] / log["solves"]
            krylov = log["krylov"] / log["solves"]
            print(f"| {level} | {log['dofs']} | {np_} | {run.get('load_before', 0):.1f} / - "
                  f"| stopped after {log['solves']} solves | | {krylov:.1f} | {solve_cpu:.3g} | | | | | "
                  f"| {1e6 * solve_cpu / per_rank:.3g} | {1e6 * solve_cpu / per_rank / max(krylov, 1):.3g} | |")
            continue
        per_rank = log["dofs"] / np_
        calls, asm_wall = log["assembly"]
        solve_cpu = log["solve_cpu"] / log["solves"]
        krylov = log["krylov"] / log["solves"]
        # CPU of a rank outside the linear solves (assembly, contact search, set-up, output, MPI
        # waits), shared out over the assemblies: an upper bound of the assembly's CPU.
        other = (log["cpu_all"] / np_ - log["solve_cpu"]) / max(calls, 1)
        print(f"| {level} | {log['dofs']} | {np_} | {run.get('load_before', 0):.1f} / {run.get('load_after', 0):.1f} "
              f"| {log['newton']} | {calls} | {krylov:.1f} | {solve_cpu:.3g} | {other:.3g} | {log['cpu_all']:.1f} "
              f"| {log['wall']:.3g} | {asm_wall / max(calls, 1):.3g} | {run.get('maxrss_MB', 0):.0f} "
              f"| {1e6 * solve_cpu / per_rank:.3g} | {1e6 * solve_cpu / per_rank / max(krylov, 1):.3g} "
              f"| {1e6 * other / per_rank:.3g} |")

if __name__ == "__main__":
    main()
