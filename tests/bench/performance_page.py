#!/usr/bin/env python3
"""docs/performance.md from its text (tests/bench/performance/*.md) and
what scripts/bench measured.

  performance_page.py write PAGE MEASURED DATE MACHINE
      Writes PAGE. A section with files in the folder MEASURED (named
      SECTION.PLACEHOLDER, e.g. reload.table) is filled in from them, with
      DATE and MACHINE; any other section is kept from PAGE as it is.
  performance_page.py check PAGE
      Exits 1, naming the section and its first line that differs, unless
      PAGE is what the text gives for some values of its placeholders: the
      page is written, not edited by hand (dated findings go to
      performance-history.md).

A template's {{name}} stands for measured text (a date, the machine, a
Markdown table, or a note); the page is the header and the sections in
SECTIONS' order, a blank line between them.
"""
import os
import re
import sys
import tempfile

TEXT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "performance")
SECTIONS = ["header", "reload", "firstload", "instructions", "startup", "passes", "budget", "video", "interface"]
PLACEHOLDER = re.compile(r"\{\{(\w+)\}\}")


def template(section):
    with open(os.path.join(TEXT, section + ".md")) as f:
        return f.read()


def heading(section):
    return template(section).split("\n", 1)[0]


def split_page(text):
    """The page's sections by name, found by their headings."""
    by_heading = {heading(s): s for s in SECTIONS}
    starts = [m.start() for m in re.finditer(r"(?m)^#+ ", text)]
    found = {}
    for i, start in enumerate(starts):
        last_one = i + 1 == len(starts)
        chunk = text[start:] if last_one else text[start:starts[i + 1] - 1]  # less the blank line between
        title = chunk.split("\n", 1)[0]
        if title in by_heading:
            found[by_heading[title]] = chunk
        elif found:  # a heading of the template's own (none has one today) or a stray one
            last = list(found)[-1]
            found[last] += "\n" + chunk
    return found


def fill(section, values):
    def value(m):
        if m.group(1) not in values:
            sys.exit(f"performance_page: nothing measured for {{{{{m.group(1)}}}}} in {section}.md")
        return values[m.group(1)]
    return PLACEHOLDER.sub(value, template(section))


def matching(placeholder):
    """What a placeholder may stand for on the page: a table is table rows
    only, so a paragraph written under one by hand is caught."""
    if placeholder == "date":
        return r"\d{4}-\d\d-\d\d"
    if placeholder == "machine":
        return r"[^\n]+?"
    if placeholder.endswith("table"):
        return r"\|[^\n]*(?:\n\|[^\n]*)*"
    return ".*?"


def first_difference(section, chunk):
    """The first line of the section's text that the page does not have
    where it should, or None when the page is what the text gives."""
    pieces = []  # the template's lines, and its placeholders
    for i, part in enumerate(PLACEHOLDER.split(template(section))):
        if i % 2:
            pieces.append((matching(part), "{{" + part + "}}"))
        else:
            pieces += [(re.escape(line), line.rstrip("\n")) for line in part.splitlines(keepends=True)]
    if re.fullmatch("".join(piece for piece, _ in pieces), chunk, re.S):
        return None
    pattern = ""
    for piece, shown in pieces:
        pattern += piece
        if not re.match(pattern, chunk, re.S):
            return shown or "(a blank line)"
    return "(text after the section's end)"


def check(page):
    with open(page) as f:
        text = f.read()
    found = split_page(text)
    bad = 0
    if not text.startswith(heading("header") + "\n"):
        print(f"{page}: does not begin with '{heading('header')}'")
        bad = 1
    for section in SECTIONS:
        if section not in found:
            print(f"{page}: no section '{heading(section)}' (tests/bench/performance/{section}.md)")
            bad = 1
            continue
        line = first_difference(section, found[section])
        if line is not None:
            print(f"{page}: '{heading(section)}' is not what tests/bench/performance/{section}.md gives; "
                  f"first line that differs: {line!r}")
            bad = 1
    return bad


def write(page, measured, date, machine):
    kept = {}
    if os.path.exists(page):
        with open(page) as f:
            kept = split_page(f.read())
    names = os.listdir(measured)
    sections = []
    for section in SECTIONS:
        values = {}
        for name in names:
            if name.startswith(section + "."):
                with open(os.path.join(measured, name)) as f:
                    values[name[len(section) + 1:]] = f.read().strip("\n")
        if section == "header" or values:
            sections.append(fill(section, dict(values, date=date, machine=machine)))
        elif section in kept:
            sections.append(kept[section])
        else:
            sys.exit(f"performance_page: {page} has no '{heading(section)}' to keep: measure it (scripts/bench {section})")
    out = tempfile.NamedTemporaryFile("w", dir=os.path.dirname(os.path.abspath(page)), delete=False)
    with out:
        out.write("\n".join(sections))
    os.replace(out.name, page)


def main(argv):
    if len(argv) == 3 and argv[1] == "check":
        return check(argv[2])
    if len(argv) == 6 and argv[1] == "write":
        write(*argv[2:])
        return 0
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
