#!/usr/bin/python3
"""Every file or directory of the repository named in README.md, CHANGELOG.md and doc/*.md exists.

Usage: check_doc_paths.py SOURCE_DIR

A path is a markdown link target (relative to the document) or a token that starts with one of the
repository's top-level directories (src/, include/, tests/, ...; relative to the root, or to doc/
for doc/'s own files). Accepted spellings: a file, a directory, a glob (`tests/hostile/*.jsonl`),
alternatives in braces (`examples/scene-container.{jsonl,csv}`), a file stem
(`src/io/fast_quadric` for .hpp and .cpp), and a second extension after a slash
(`benchmarks/flint_reference.hpp/.cpp`). Paths inside build directories (build/, build-*/) are
outputs and not checked.
"""
import glob
import os
import re
import sys

TOP = ("src", "include", "cli", "python", "tests", "benchmarks", "doc", "examples", "scripts", "tools", "fuzz",
       "cmake", ".ci")
TOP_FILES = ("README.md", "CHANGELOG.md", "LICENSE", "CMakeLists.txt")
LINK = re.compile(r"\]\(([^)\s#]+)(?:#[^)]*)?\)")
TOKEN = re.compile(r"(?<![\w./-])((?:%s)/[\w./*{},+-]*)" % "|".join(re.escape(t) for t in TOP))
TOP_FILE = re.compile(r"(?<![\w./-])(%s)(?![\w.-])" % "|".join(re.escape(t) for t in TOP_FILES))


def expand(path):
    """The spellings a path stands for: brace alternatives and a trailing /.ext."""
    m = re.search(r"\{([^{}]*)\}", path)
    if m:
        out = []
        for alt in m.group(1).split(","):
            out += expand(path[:m.start()] + alt + path[m.end():])
        return out
    m = re.match(r"(.*?)(\.\w+)/(\.\w+)$", path)
    if m:
        return [m.group(1) + m.group(2), m.group(1) + m.group(3)]
    return [path]


def exists(root, path):
    path = path.rstrip(".,:;")  # sentence punctuation
    if not path or path.startswith(("build/", "build-")):
        return True
    for p in expand(path):
        full = os.path.join(root, p)
        if any(c in p for c in "*?[") and glob.glob(full):
            continue
        if os.path.exists(full) or glob.glob(glob.escape(full) + ".*"):
            continue
        return False
    return True


def problems_in(root, rel, text):
    out = []
    base = os.path.dirname(rel)
    for m in LINK.finditer(text):
        target = m.group(1)
        if re.match(r"[a-z]+:", target):  # http:, https:, mailto:
            continue
        if not exists(root, os.path.normpath(os.path.join(base, target))):
            out.append(f"{rel}:{text.count(chr(10), 0, m.start()) + 1}: link to {target}, which does not exist")
    for pattern in (TOKEN, TOP_FILE):
        for m in pattern.finditer(text):
            p = m.group(1)
            # A token inside doc/ may be relative to doc/ (e.g. "figures/x.png" is not matched; "doc/x" is).
            if exists(root, p) or (base and exists(root, os.path.join(base, p))):
                continue
            out.append(f"{rel}:{text.count(chr(10), 0, m.start()) + 1}: names {p}, which does not exist")
    return out


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: check_doc_paths.py SOURCE_DIR")
    root = sys.argv[1]
    # Self-test on synthetic text, so a checker that stops finding anything fails too.
    if not problems_in(root, "README.md", "see `src/no_such_file.cpp`") or not problems_in(
            root, "doc/x.md", "[a](no_such.md)") or problems_in(root, "README.md", "[a](doc/math.md), `src/`"):
        sys.exit("check_doc_paths.py self-test failed")
    docs = ["README.md", "CHANGELOG.md"] + sorted(
        os.path.join("doc", n) for n in os.listdir(os.path.join(root, "doc")) if n.endswith(".md"))
    problems = []
    for rel in docs:
        if not os.path.exists(os.path.join(root, rel)):
            continue
        with open(os.path.join(root, rel), encoding="utf-8") as f:
            problems += problems_in(root, rel, f.read())
    for p in problems:
        print(p)
    print(f"{len(docs)} documents checked, {len(problems)} paths missing")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
