#!/usr/bin/env python3
"""Move the entries of old files into the subsections of their shape, law, motion, strategy or step
control (in place).

  scripts/migrate_die_entries.py FILE.prm [FILE.md ...]

Before, each `subsection Die N` held one flat list of shape entries (`Point`, `Normal`,
`Center`, `Radius`, `Points`, `Number of teeth`, ...); now each shape has its own subsection
(`Flat`, `Circle`, `Polyline`, `Arc line`, `Involute gear`, `Ellipse`), e.g.
`Contact/Die 0/Radius` is `Contact/Die 0/Circle/Radius`. This script rewrites every
`subsection Die N` block it finds (also in the prm code blocks of Markdown files): the moved
`set` lines are taken out and written, in their order, into one block per shape subsection at
the place of the first of them. `Points` and `Points file` go to `Arc line` when the block sets
`Shape = arc line`, otherwise to `Polyline` (a warning is printed when the block does not set
the shape). The friction entries moved into one subsection per law as well:
`Friction coefficient` goes to the subsection of the block's `Friction` (`Coulomb` or
`Coulomb capped by shear`; `Coulomb` when the block does not set another law, the default),
`Friction factor` to `Tresca`, `Coulomb capped by shear` or `Levanov` (`Tresca` when the law
takes no factor). The `Profile` subsection of `Revolved profile` and `Extruded profile` takes any
2D shape: its chain entries moved into the subsection of the shape its `Type` names (`Points`,
`Points file` to `Polyline` or `Arc line`, `Fillet radii` to `Arc line`, `Center`, `Radius`,
`Material inside` to `Circle`, the gear sizes to `Involute gear`; `Type`, `Closed` and
`Extend ends` stay). The motion entries of `Contact/Die N/Motion` moved into one subsection per
motion: `Translation`, `Rotation`, `Pivot` to `Prescribed`; `Workpiece center`, the rolling radii,
`Initial center distance`, `Initial line angle`, `Direction`, `Rolling factor`, `Revolution
angle`, `Slip angle`, `Feed` to `Rolling`; `Axis` to `Rolling` when the block sets `Type =
rolling`, otherwise to `Prescribed` (`Type` stays). The contact strategies and step controls have
subsections of their own as well: `Contact/Ratio tolerance` moved to `Contact/Load increment
ratio`, `Loading/Target Newton iterations`, `Target status changes` and `Minimum step factor` to
`Loading/Adaptive`. Prints what it changed; files without such entries are left alone.
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
    "Friction coefficient": None,  # the law's subsection
    "Friction factor": None,
}

# the entries of the `Profile` subsection of `Revolved profile` / `Extruded profile` that moved
# into the subsection of the 2D shape named by its `Type` (`Closed` and `Extend ends` stay)
PROFILE_MOVED = {entry: target for entry, target in MOVED.items()
                 if entry not in ("Point", "Normal", "Friction coefficient", "Friction factor")}

# the defaults of the gear entries of the old `Profile` that differ from those of `Involute gear`
OLD_PROFILE_GEAR_DEFAULTS = [("Number of teeth", "20"), ("Diametral pitch", "0"),
                             ("Module", "1"), ("Pressure angle", "20")]

# the laws that read each friction entry, and where it goes for another law
FRICTION_TARGETS = {
    "Friction coefficient": (("Coulomb", "Coulomb capped by shear"), "Coulomb"),
    "Friction factor": (("Tresca", "Coulomb capped by shear", "Levanov"), "Tresca"),
}

# the entries of `Contact/Die N/Motion` that moved into the subsection of their motion type
MOTION_MOVED = {
    "Translation": "Prescribed",
    "Rotation": "Prescribed",
    "Pivot": "Prescribed",
    "Axis": None,  # Prescribed or Rolling
    "Workpiece center": "Rolling",
    "Workpiece rolling radius": "Rolling",
    "Die rolling radius": "Rolling",
    "Initial center distance": "Rolling",
    "Initial line angle": "Rolling",
    "Direction": "Rolling",
    "Rolling factor": "Rolling",
    "Revolution angle": "Rolling",
    "Slip angle": "Rolling",
    "Feed": "Rolling",
}

# the entries of `Contact` and `Loading` that moved into the subsection of their contact strategy
# or step control
SECTION_MOVED = {
    "Contact": {"Ratio tolerance": "Load increment ratio"},
    "Loading": {"Target Newton iterations": "Adaptive", "Target status changes": "Adaptive",
                "Minimum step factor": "Adaptive"},
}

SUBSECTION = re.compile(r"^(\s*)subsection\s+(.*?)\s*(#.*)?$")
END = re.compile(r"^\s*end\s*(#.*)?$")
SET = re.compile(r"^(\s*)set\s+(.*?)\s*=\s*(.*)$")


def value(line):
    return SET.match(line).group(3).split("#")[0].strip()


def migrate_blocks(lines, name, is_block, target_of, extra=lambda settings: {}):
    """Move the `set` lines at the top level of every block whose subsection name satisfies
    is_block into the subsection target_of(entry, settings, block) names (None: keep), written,
    in their order, as one block per target at the place of the first moved line; settings are
    the block's top-level entries (name -> value); extra(settings) gives further `set` lines per
    target (entries whose default changed with the move) for a block that moves something."""
    out = []
    i = 0
    changed = 0
    while i < len(lines):
        m = SUBSECTION.match(lines[i])
        if not (m and is_block(m.group(2))):
            out.append(lines[i])
            i += 1
            continue
        # a block: find its end (nested subsections counted)
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
        settings = {}
        depth = 0
        for line in block:
            if SUBSECTION.match(line):
                depth += 1
            elif END.match(line):
                depth -= 1
            elif depth == 0 and SET.match(line):
                settings[SET.match(line).group(2)] = value(line)
        groups, order, kept, first = {}, [], [], None
        depth = 0
        for line in block:
            if SUBSECTION.match(line):
                depth += 1
            elif END.match(line):
                depth -= 1
            s = SET.match(line)
            target = target_of(s.group(2), settings, m.group(2)) if depth == 0 and s else None
            if target is not None:
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
        if order:
            for target, added in extra(settings).items():
                if target not in groups:
                    continue
                indent = SET.match(groups[target][0]).group(1)
                for entry, default in added:
                    groups[target].append(f"{indent}set {entry} = {default}  # the old default\n")
                    changed += 1
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


def migrate(lines, name):
    def die_target(entry, settings, block):
        if entry not in MOVED:
            return None
        if entry in FRICTION_TARGETS:
            laws, other = FRICTION_TARGETS[entry]
            law = settings.get("Friction", "Coulomb")
            return law if law in laws else other
        if MOVED[entry] is not None:
            return MOVED[entry]
        shape = settings.get("Shape")
        target = "Arc line" if shape == "arc line" else "Polyline"
        if shape is None:
            print(f"{name}: {block} sets {entry} without Shape: moved to {target}, check",
                  file=sys.stderr)
        return target

    def profile_target(entry, settings, block):
        if entry not in PROFILE_MOVED:
            return None
        if PROFILE_MOVED[entry] is not None:
            return PROFILE_MOVED[entry]
        return "Arc line" if settings.get("Type", "polyline") == "arc line" else "Polyline"

    out, changed = migrate_blocks(lines, name, lambda b: re.fullmatch(r"Die \d+", b), die_target)
    def profile_defaults(settings):
        # the gear size defaults of `Profile` differ from those of the 2D `Involute gear`
        if settings.get("Type") != "involute gear":
            return {}
        return {"Involute gear": [(entry, default) for entry, default in OLD_PROFILE_GEAR_DEFAULTS
                                  if entry not in settings]}

    out, changed_profiles = migrate_blocks(out, name, lambda b: b == "Profile", profile_target,
                                           profile_defaults)
    def motion_target(entry, settings, block):
        if entry not in MOTION_MOVED:
            return None
        if MOTION_MOVED[entry] is not None:
            return MOTION_MOVED[entry]
        return "Rolling" if settings.get("Type") == "rolling" else "Prescribed"

    out, changed_motions = migrate_blocks(out, name, lambda b: b == "Motion", motion_target)
    changed_sections = 0
    for section, moved in SECTION_MOVED.items():
        out, n = migrate_blocks(out, name, lambda b, section=section: b == section,
                                lambda entry, settings, block, moved=moved: moved.get(entry))
        changed_sections += n
    return out, changed + changed_profiles + changed_motions + changed_sections


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
