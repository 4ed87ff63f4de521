#!/usr/bin/env python3
"""Write a variant of a .prm file with some entries changed (for studies and checks).

Usage: prm_variant.py BASE.prm OUT.prm "Section/Sub/Entry = value" ...

Each override replaces the value of an existing `set Entry = ...` line inside the given subsection
path, or, if the entry is not set in BASE, adds the line at the end of that subsection (the
subsection is created at the end of the file if it does not exist). Relative file names in BASE
(`include` lines, `Mesh file`, `Points file`) that name a file next to BASE are made absolute, so
that OUT may be written anywhere.
"""

import os
import sys

FILE_ENTRIES = ("Mesh file", "Points file")


def absolute_file_names(lines, base_dir):
    """Make the relative file names of include lines and file entries absolute (relative to
    @p base_dir) when that file exists."""
    out = []
    for line in lines:
        code, hash_, comment = line.partition("#")
        words = code.split(None, 1)
        indent = line[: len(line) - len(line.lstrip())]
        if len(words) == 2 and words[0] == "include":
            name = words[1].strip()
            candidate = os.path.join(base_dir, name)
            if not os.path.isabs(name) and os.path.exists(candidate):
                line = f"{indent}include {os.path.abspath(candidate)}" + (
                    f" {hash_}{comment}" if hash_ else "\n")
        elif len(words) == 2 and words[0] == "set" and "=" in words[1]:
            entry, value = (x.strip() for x in words[1].split("=", 1))
            candidate = os.path.join(base_dir, value)
            if (entry in FILE_ENTRIES and value and not os.path.isabs(value)
                    and os.path.exists(candidate)):
                line = f"{indent}set {entry} = {os.path.abspath(candidate)}" + (
                    f" {hash_}{comment}" if hash_ else "\n")
        out.append(line)
    return out


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
        lines = absolute_file_names(f.readlines(), os.path.dirname(os.path.abspath(sys.argv[1])))
    for text in sys.argv[3:]:
        sections, entry, value = parse_override(text)
        lines = apply(lines, sections, entry, value)
    with open(sys.argv[2], "w") as f:
        f.writelines(lines)
    return 0


if __name__ == "__main__":
    sys.exit(main())
