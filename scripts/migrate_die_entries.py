#!/usr/bin/env python3
"""Move the shape entries of `Contact/Die N` into their shape subsections (in place).

  scripts/migrate_die_entries.py FILE.prm [FILE.md ...]

Before, each `subsection Die N` held one flat list of shape entries (`Point`, `Normal`,
`Center`, `Radius`, `Points`, `Number of teeth`, ...); now each shape has its own subsection
(`Flat`, `Circle`, `Polyline`, `Arc line`, `Involute gear`, `Ellipse`), e.g.
`Contact/Die 0/Radius` is `Contact/Die 0/Circle/Radius`. This script rewrites every
`subsection Die N` block it finds (also in the prm code blocks of Markdown files): the moved
`set` lines are taken out and written, in their order, into one block per shape subsection at
the place of the first of them. `Points` and `Points file` go to `Arc line` when the block sets
`Shape = arc line`, otherwise to `Polyline` (a warning is printed when the block does not set
the shape). Prints what it changed; files without such entries are left alone.
"""

import re
import sys

MOVED = {
    "Point": "Flat",
    "Normal": "Flat",
    "Center": "Circle",
    "Radius": "Circle",
    "Material inside": "Circle",
    "Points": None,  # Polyline or Arc line
    "Points file": None,
    "Fillet radii": "Arc line",
    "Number of teeth": "Involute gear",
    "Diametral pitch": "Involute gear",
    "Module": "Involute gear",
    "Pressure angle": "Involute gear",
    "Addendum": "Involute gear",
    "Dedendum": "Involute gear",
    "Tooth thickness": "Involute gear",
    "Root fillet radius": "Involute gear",
    "Tip radius": "Involute gear",
    "Tooth axis angle": "Involute gear",
    "Teeth in sector": "Involute gear",
}

SUBSECTION = re.compile(r"^(\s*)subsection\s+(.*?)\s*(#.*)?$")
END = re.compile(r"^\s*end\s*(#.*)?$")
SET = re.compile(r"^(\s*)set\s+(.*?)\s*=\s*(.*)$")


def migrate(lines, name):
    out = []
    i = 0
    changed = 0
    while i < len(lines):
        m = SUBSECTION.match(lines[i])
        if not (m and re.fullmatch(r"Die \d+", m.group(2))):
            out.append(lines[i])
            i += 1
            continue
        # a Die block: find its end (nested subsections counted)
        depth, j = 0, i + 1
        while j < len(lines):
            if SUBSECTION.match(lines[j]):
                depth += 1
            elif END.match(lines[j]):
                if depth == 0:
                    break
                depth -= 1
            j += 1
        block = lines[i + 1:j]
        shape = None
        depth = 0
        for line in block:
            if SUBSECTION.match(line):
                depth += 1
            elif END.match(line):
                depth -= 1
            s = SET.match(line)
            if depth == 0 and s and s.group(2) == "Shape":
                shape = s.group(3).split("#")[0].strip()
        groups, order, kept, first = {}, [], [], None
        depth = 0
        for line in block:
            if SUBSECTION.match(line):
                depth += 1
            elif END.match(line):
                depth -= 1
            s = SET.match(line)
            if depth == 0 and s and s.group(2) in MOVED:
                target = MOVED[s.group(2)]
                if target is None:
                    target = "Arc line" if shape == "arc line" else "Polyline"
                    if shape is None:
                        print(f"{name}: {m.group(2)} sets {s.group(2)} without Shape: "
                              f"moved to {target}, check", file=sys.stderr)
                if target not in groups:
                    groups[target] = []
                    order.append(target)
                groups[target].append(line)
                if first is None:
                    first = len(kept)
                    kept.append(None)
                changed += 1
            else:
                kept.append(line)
        out.append(lines[i])
        for line in kept:
            if line is not None:
                out.append(line)
                continue
            for target in order:
                indent = SET.match(groups[target][0]).group(1)
                out.append(f"{indent}subsection {target}\n")
                for g in groups[target]:
                    out.append("  " + g if g.endswith("\n") else "  " + g + "\n")
                out.append(f"{indent}end\n")
        i = j
    return out, changed


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 1
    for name in sys.argv[1:]:
        with open(name) as f:
            lines = f.readlines()
        out, changed = migrate(lines, name)
        if changed:
            with open(name, "w") as f:
                f.writelines(out)
            print(f"{name}: moved {changed} entries")
    return 0


if __name__ == "__main__":
    sys.exit(main())
