#!/usr/bin/env python3
"""Write a variant of a .prm file with some entries changed (for studies and checks).

Usage: prm_variant.py BASE.prm OUT.prm "Section/Sub/Entry = value" ...

Each override replaces the value of an existing `set Entry = ...` line inside the given subsection
path, or, if the entry is not set in BASE, adds the line at the end of that subsection (the
subsection is created at the end of the file if it does not exist). Relative file names in BASE
(`Mesh file`, `Points file`) are not rewritten: write OUT next to BASE or use absolute paths.
"""

import sys


def parse_override(text):
    if "=" not in text:
        raise SystemExit(f"prm_variant.py: override '{text}' lacks '='")
    path, value = text.split("=", 1)
    parts = [p.strip() for p in path.strip().split("/")]
    return parts[:-1], parts[-1], value.strip()


def apply(lines, sections, entry, value):
    stack, done = [], False
    insert_at = None
    for i, line in enumerate(lines):
        code = line.split("#", 1)[0].strip()
        words = code.split(None, 1)
        if not words:
            continue
        if words[0] == "subsection":
            stack.append(words[1].strip() if len(words) > 1 else "")
        elif words[0] == "end":
            if stack == sections and insert_at is None:
                insert_at = i
            if stack:
                stack.pop()
        elif words[0] == "set" and stack == sections:
            name = code[3:].split("=", 1)[0].strip()
            if name == entry:
                indent = line[: len(line) - len(line.lstrip())]
                lines[i] = f"{indent}set {entry} = {value}\n"
                done = True
    if done:
        return lines
    if insert_at is not None or not sections:
        indent = "  " * len(sections)
        new = f"{indent}set {entry} = {value}\n"
        if sections:
            lines.insert(insert_at, new)
        else:
            lines.insert(0, new)
        return lines
    block = []
    for depth, name in enumerate(sections):
        block.append("  " * depth + f"subsection {name}\n")
    block.append("  " * len(sections) + f"set {entry} = {value}\n")
    for depth in reversed(range(len(sections))):
        block.append("  " * depth + "end\n")
    return lines + ["\n"] + block


def main():
    if len(sys.argv) < 3:
        print(__doc__, file=sys.stderr)
        return 1
    with open(sys.argv[1]) as f:
        lines = f.readlines()
    for text in sys.argv[3:]:
        sections, entry, value = parse_override(text)
        lines = apply(lines, sections, entry, value)
    with open(sys.argv[2], "w") as f:
        f.writelines(lines)
    return 0


if __name__ == "__main__":
    sys.exit(main())
