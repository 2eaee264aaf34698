#!/usr/bin/python3
"""Every citation of doc/math.md names a section that exists.

Comments and docs cite the mathematics as `math.md §N` (or `math.md §N–§M`, `math.md §N and §M`).
This check fails when
  - a cited §N has no heading `## §N. Title` in doc/math.md,
  - a `§N` inside doc/math.md itself points at no section,
  - the headings of doc/math.md are not numbered 1, 2, 3, ... in order,
  - an old-style citation remains: `math.md section N`, `math.md sections N and M`,
    `math.md "Title"`, `math.md, section "Title"`, `section N of math.md`,
  - a bare "section N" names no document (the paper's sections are cited as "the paper's section N"
    or "paper section N").

Usage: check_citations.py SOURCE_DIR. A self-test on synthetic text runs first, so a checker that
stops finding anything fails too.
"""
import os
import re
import sys

HEADING = re.compile(r"^## §(\d+)\. \S", re.M)
# After "math.md": optional comma, spaces and comment leaders (a citation may wrap), then §N, §N–§M, ...
CITE = re.compile(r"math\.md(?:\)|\]\(math\.md\))?,?(?:\s|//+|#+|\*+)*((?:§\d+(?:\s*(?:–|-|,|and)\s*)?)+)")
OLD = [
    re.compile(r"math\.md,?(?:\s|//+|#+|\*+)*sections?\b"),
    re.compile(r"math\.md,?(?:\s|//+|#+|\*+)*(?:section\s+)?\"[A-Z]"),
    re.compile(r"\bsections?\s+\d+(?:\s*(?:,|and|-)\s*\d+)*\s+of\s+(?:doc/)?math\.md"),
]
TEXT = re.compile(r"\.(c|cc|cpp|h|hpp|py|pyi|md|sh|txt|cmake|in|toml|cfg)$|^CMakeLists\.txt$")


def line_of(text, pos):
    return text.count("\n", 0, pos) + 1


BARE = re.compile(r"\bsections? \d+")


# Output text (a C++ string literal such as a rule's sentence) keeps the ASCII form
# `math.md section N`, so reports stay plain ASCII; the section must still exist.
OUTPUT = re.compile(r'"[^"\n]*?math\.md section (\d+)[^"\n]*"')


def problems_in(text, where, sections):
    out = []
    literal = []
    for m in OUTPUT.finditer(text):
        literal.append((m.start(), m.end()))
        if int(m.group(1)) not in sections:
            out.append(f"{where}:{line_of(text, m.start())}: output text cites math.md section {m.group(1)}, "
                       "which does not exist")
    inside = lambda pos: any(a <= pos < b for a, b in literal)
    for m in BARE.finditer(text):
        if inside(m.start()):
            continue
        before = text[max(0, m.start() - 30):m.start()]
        if "paper" not in before.split("\n")[-1] and not re.search(r"math\.md[,\s/#*]*$", before):
            out.append(f"{where}:{line_of(text, m.start())}: bare {m.group(0)!r}: write math.md §N")
    for m in CITE.finditer(text):
        for n in re.findall(r"§(\d+)", m.group(1)):
            if int(n) not in sections:
                out.append(f"{where}:{line_of(text, m.start())}: cites math.md §{n}, which does not exist")
    for pattern in OLD:
        for m in pattern.finditer(text):
            if inside(m.start()):
                continue
            out.append(f"{where}:{line_of(text, m.start())}: old-style citation {m.group(0)!r}: write math.md §N")
    return out


def math_problems(text):
    numbers = [int(n) for n in HEADING.findall(text)]
    out = []
    if numbers != list(range(1, len(numbers) + 1)):
        out.append(f"doc/math.md: section headings are numbered {numbers}, not 1, 2, 3, ...")
    sections = set(numbers)
    for m in re.finditer(r"§(\d+)", text):
        if int(m.group(1)) not in sections:
            out.append(f"doc/math.md:{line_of(text, m.start())}: refers to §{m.group(1)}, which does not exist")
    return sections, out


def self_test():
    sections = {1, 2, 3, 8}
    bad = [
        'return "crossing (math.md section 9, rule 5)";',
        "// (math.md §9)",
        "// math.md §3–§9",
        "// math.md §1, §2 and §12",
        "// (math.md section 8)",
        "// math.md sections 3 and 6",
        "// (I or C by math.md\n// section 8 needs)",
        '// (math.md "Motion")',
        '(doc/math.md, section "Motion")',
        "(section 4 of math.md)",
        "// the gap test (section 8)",
    ]
    good = ['return "crossing (math.md section 8, rule 5)";', "// (math.md §8)", "// math.md §1–§3", "// math.md §3 and §8", "(math.md\n// §2)", "see math.md.",
            "(the paper's section 2)", "The paper (section 2) tracks", "(paper section 2.1)"]
    for text in bad:
        if not problems_in(text, "self-test", sections):
            sys.exit(f"check_citations.py self-test: {text!r} was not flagged")
    for text in good:
        if problems_in(text, "self-test", sections):
            sys.exit(f"check_citations.py self-test: {text!r} was flagged")
    if not math_problems("## §1. A\n## §3. B\n")[1] or not math_problems("## §1. A\nsee §2\n")[1]:
        sys.exit("check_citations.py self-test: a bad doc/math.md was not flagged")


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: check_citations.py SOURCE_DIR")
    root = sys.argv[1]
    self_test()
    with open(os.path.join(root, "doc", "math.md"), encoding="utf-8") as f:
        sections, problems = math_problems(f.read())
    if len(sections) < 13:
        problems.append(f"doc/math.md: only {len(sections)} numbered sections found")
    checked = 0
    for dirpath, dirnames, filenames in os.walk(root):
        # Skip hidden directories and build trees (a build directory holds a CMakeCache.txt).
        dirnames[:] = [
            d for d in dirnames
            if not d.startswith(".") and not os.path.exists(os.path.join(dirpath, d, "CMakeCache.txt"))
        ]
        for name in filenames:
            path = os.path.join(dirpath, name)
            rel = os.path.relpath(path, root)
            if not TEXT.search(name) or rel == os.path.join("doc", "math.md") or rel == os.path.join(
                    "tests", "check_citations.py"):
                continue
            try:
                with open(path, encoding="utf-8") as f:
                    text = f.read()
            except (UnicodeDecodeError, OSError):
                continue
            checked += 1
            problems += problems_in(text, rel, sections)
    for p in problems:
        print(p)
    print(f"{checked} files checked, {len(sections)} sections in doc/math.md, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
