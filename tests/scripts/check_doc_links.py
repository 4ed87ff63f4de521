#!/usr/bin/env python3
"""Link and anchor checker for README.md and doc/**/*.md.

Usage: check_doc_links.py [ROOT]   (ROOT: the checkout, default: two folders above this script)

For every Markdown link and image outside code blocks and code spans:
  - an external link (http:, https:, mailto:) is skipped;
  - a relative link must name an existing file or folder (relative to the page);
  - a "#anchor" (alone or after a .md file) must be the slug of a heading of the target page,
    made by GitHub's rules: the heading's text without Markdown markup, lower case, every character
    that is not a letter, digit, space, hyphen or underscore removed, spaces turned into hyphens,
    repeated headings numbered "-1", "-2", ...; explicit <a name="..."> / id="..." anchors count
    too.
Prints one line per broken link (file:line: link: reason) and exits 1 if there is any, 0 otherwise.
The self-test (--self-test) checks the slug rules on headings whose GitHub anchors are known.
"""

import os
import re
import sys
import tempfile
import unicodedata

EXTERNAL = re.compile(r"^[a-zA-Z][a-zA-Z0-9+.-]*:")  # http:, https:, mailto:, ...
FENCE = re.compile(r"^\s*(```|~~~)")
HEADING = re.compile(r"^\s{0,3}(#{1,6})\s+(.*?)\s*#*\s*$")
HTML_ANCHOR = re.compile(r"""<a\s+[^>]*(?:name|id)\s*=\s*["']([^"']+)["']""", re.IGNORECASE)
# [text](target) or ![alt](target); the text may hold one level of brackets (e.g. [`a[0]`](x)).
LINK = re.compile(r"(!?)\[((?:[^\[\]]|\[[^\]]*\])*)\]\(\s*<?([^)\s>]*)>?(?:\s+\"[^\"]*\")?\s*\)")
REFERENCE_DEF = re.compile(r"^\s{0,3}\[([^\]]+)\]:\s*<?(\S+?)>?(\s|$)")


def strip_code_spans(line):
    """The line with the contents of `code spans` blanked (links inside code are not links)."""
    return re.sub(r"(`+)(.+?)\1", lambda m: " " * len(m.group(0)), line)


def heading_text(raw):
    """The rendered text of a heading: links reduced to their text, markup removed."""
    text = re.sub(r"!?\[((?:[^\[\]]|\[[^\]]*\])*)\]\([^)]*\)", r"\1", raw)  # links, images
    text = re.sub(r"<[^>]+>", "", text)  # inline HTML
    text = text.replace("`", "")
    text = re.sub(r"(\*+|(?<!\w)_+|_+(?!\w))", "", text)  # emphasis, not snake_case
    return text


def slug(raw):
    """GitHub's anchor for a heading (before numbering of repeats)."""
    out = []
    for ch in heading_text(raw).strip().lower():
        cat = unicodedata.category(ch)
        if ch in "-_" or cat[0] in "LN" or cat == "Mn":
            out.append(ch)
        elif ch == " ":
            out.append("-")
    return "".join(out)


def markdown_lines(text):
    """(line number, line) of the lines outside fenced code blocks."""
    fenced = None
    for number, line in enumerate(text.splitlines(), 1):
        m = FENCE.match(line)
        if m:
            if fenced is None:
                fenced = m.group(1)
            elif m.group(1) == fenced:
                fenced = None
            continue
        if fenced is None:
            yield number, line


_anchor_cache = {}


def anchors_of(path):
    """The set of anchors a Markdown file offers."""
    if path not in _anchor_cache:
        with open(path, encoding="utf-8") as f:
            text = f.read()
        seen = {}
        anchors = set()
        for _, line in markdown_lines(text):
            for name in HTML_ANCHOR.findall(line):
                anchors.add(name)
            m = HEADING.match(line)
            if not m:
                continue
            base = slug(m.group(2))
            count = seen.get(base, 0)
            seen[base] = count + 1
            anchors.add(base if count == 0 else f"{base}-{count}")
        _anchor_cache[path] = anchors
    return _anchor_cache[path]


def links_of(text):
    """(line number, is_image, target) of every inline link, image and reference definition."""
    for number, line in markdown_lines(text):
        plain = strip_code_spans(line)
        for m in LINK.finditer(plain):
            yield number, m.group(1) == "!", m.group(3)
        m = REFERENCE_DEF.match(plain)
        if m:
            yield number, False, m.group(2)


def check_file(path, root):
    """Problems of one Markdown file: list of 'file:line: target: reason'."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    problems = []
    rel = os.path.relpath(path, root)
    for number, is_image, target in links_of(text):
        if not target or EXTERNAL.match(target):
            continue
        where = f"{rel}:{number}: {target}: "
        file_part, _, anchor = target.partition("#")
        if file_part:
            if file_part.startswith("/"):
                problems.append(where + "absolute path (use a path relative to the page)")
                continue
            resolved = os.path.normpath(os.path.join(os.path.dirname(path), file_part))
            if not os.path.exists(resolved):
                kind = "image" if is_image else "file"
                problems.append(where + f"{kind} {os.path.relpath(resolved, root)} does not exist")
                continue
        else:
            resolved = path
        if anchor:
            if not resolved.endswith(".md") or os.path.isdir(resolved):
                continue  # anchors into source files (#L10) or folders are not checked
            if anchor not in anchors_of(resolved):
                problems.append(where + f"no heading with anchor #{anchor} in "
                                f"{os.path.relpath(resolved, root)}")
    return problems


def documentation_files(root):
    """README.md and every .md file below doc/."""
    files = [os.path.join(root, "README.md")]
    for folder, _, names in os.walk(os.path.join(root, "doc")):
        files += [os.path.join(folder, n) for n in sorted(names) if n.endswith(".md")]
    return [f for f in files if os.path.isfile(f)]


def self_test():
    """Slugs of headings whose GitHub anchors are known (taken from rendered pages)."""
    cases = {
        "Converged answers and their error bars (convergence study)":
            "converged-answers-and-their-error-bars-convergence-study",
        "Section level 2: the 3D effect on a finer section":
            "section-level-2-the-3d-effect-on-a-finer-section",
        "Disk rolling (`prm/disk_rolling.prm`)": "disk-rolling-prmdisk_rollingprm",
        "3D disk rolling: round-faced and flat-faced die":
            "3d-disk-rolling-round-faced-and-flat-faced-die",
        "Plastic coarsening level (the DoFs level off)":
            "plastic-coarsening-level-the-dofs-level-off",
        "Contact strategy: nested active set vs load increment ratio":
            "contact-strategy-nested-active-set-vs-load-increment-ratio",
        "Two ranks (issue 14, 6(e))": "two-ranks-issue-14-6e",
        "Units": "units",
        "Elastic–plastic thick cylinder": "elasticplastic-thick-cylinder",
        "**Bold** and [a link](x.md)": "bold-and-a-link",
    }
    failed = [(h, slug(h), s) for h, s in cases.items() if slug(h) != s]
    for h, got, want in failed:
        print(f"FAIL slug({h!r}) = {got!r}, expected {want!r}")
    text = "# A\n## A\n```\n# not a heading\n```\n## A\n"
    path = "/nonexistent-self-test.md"
    _anchor_cache.pop(path, None)
    seen, anchors = {}, set()
    for _, line in markdown_lines(text):
        m = HEADING.match(line)
        if m:
            base = slug(m.group(2))
            anchors.add(base if seen.get(base, 0) == 0 else f"{base}-{seen[base]}")
            seen[base] = seen.get(base, 0) + 1
    if anchors != {"a", "a-1", "a-2"}:
        failed.append(("repeats", anchors, {"a", "a-1", "a-2"}))
        print(f"FAIL repeated headings give {sorted(anchors)}, expected a, a-1, a-2")
    links = list(links_of("see [x](a.md#b) and `[y](c.md)` and ![i](f.png)\n```\n[z](d.md)\n```\n"))
    if links != [(1, False, "a.md#b"), (1, True, "f.png")]:
        failed.append(("links", links, None))
        print(f"FAIL links found: {links}")
    # a small tree: a good link of each kind, a broken anchor, a missing image and file
    with tempfile.TemporaryDirectory() as root:
        os.makedirs(os.path.join(root, "doc", "figures"))
        open(os.path.join(root, "doc", "figures", "a.png"), "w").close()
        with open(os.path.join(root, "doc", "page.md"), "w") as f:
            f.write("# Page\n\n## Results (2026)\n\n[self](#results-2026) [bad](#results)\n"
                    "![ok](figures/a.png) ![missing](figures/b.png)\n")
        with open(os.path.join(root, "README.md"), "w") as f:
            f.write("[page](doc/page.md#page) [gone](doc/gone.md) [web](https://example.org)\n")
        problems = []
        for path in documentation_files(root):
            problems += check_file(path, root)
        expected = ["README.md:1: doc/gone.md: ", "doc/page.md:5: #results: ",
                    "doc/page.md:6: figures/b.png: "]
        if len(problems) != 3 or not all(p.startswith(e) for p, e in zip(sorted(problems),
                                                                             expected)):
            failed.append(("tree", problems, expected))
            print(f"FAIL the small tree gives {problems}")
    print("self-test:", "FAIL" if failed else "ok")
    return 1 if failed else 0


def main(argv):
    if "--self-test" in argv:
        return self_test()
    if len(argv) > 2 or any(a.startswith("-") for a in argv[1:]):
        print(__doc__)
        return 2
    root = os.path.abspath(argv[1] if len(argv) > 1 else
                           os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    if not os.path.isfile(os.path.join(root, "README.md")):
        print(f"check_doc_links.py: no README.md in {root}")
        return 2
    files = documentation_files(root)
    problems = []
    for path in files:
        problems += check_file(path, root)
    for p in problems:
        print(p)
    print(f"{len(files)} files checked, {len(problems)} broken link(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
