#!/usr/bin/env python3
"""The floors of relpos hold: every #include in src/, include/, cli/ and python/src points down.

The floors are read from the table of doc/architecture.md ("Floors"), so that the document and this
check cannot drift. Each row names a floor: its number, its name, the folders and public headers it
holds, and the floors it may include. The check fails when

  - a source or header file belongs to no floor (a new folder must be placed in the table first),
  - a quoted #include cannot be resolved to a file of the repository,
  - a file includes a file of another floor that its row does not list (an include running up, or
    across to a sibling on the same floor),
  - a row lists a floor that is not below it,
  - the folders, linked by their actual includes, form a cycle.

Usage: check_architecture.py REPO_ROOT
"""
import re
import sys
from pathlib import Path

SCANNED = ("src", "include", "cli", "python/src")
EXTENSIONS = {".hpp", ".cpp", ".h", ".cc"}
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]', re.M)


def read_floors(doc: Path):
    """Rows of the "Floors" table: (number, name, [paths], [may include])."""
    text = doc.read_text(encoding="utf-8")
    section = re.search(r"^## Floors\n(.*?)(?=^## )", text, re.M | re.S)
    if not section:
        sys.exit(f"{doc}: no '## Floors' section")
    rows = []
    for line in section.group(1).splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) != 5 or not cells[0].isdigit():
            continue
        number, name, paths, _holds, may = cells
        paths = re.findall(r"`([^`]+)`", paths)
        may = [] if may in ("", "—", "-") else [m.strip().strip("`") for m in may.split(",")]
        rows.append((int(number), name.strip("`* "), paths, may))
    if not rows:
        sys.exit(f"{doc}: the Floors table has no rows")
    return rows


def main() -> int:
    root = Path(sys.argv[1]).resolve()
    rows = read_floors(root / "doc" / "architecture.md")
    floor_of = {name: number for number, name, _, _ in rows}
    allowed = {name: set(may) for _, name, _, may in rows}
    owner = []  # (path prefix, row name), longest prefix first
    for _, name, paths, _ in rows:
        for p in paths:
            owner.append((p, name))
    owner.sort(key=lambda x: -len(x[0]))
    errors = []

    for number, name, paths, may in rows:
        for m in may:
            if m not in floor_of:
                errors.append(f"doc/architecture.md: floor {name} may include '{m}', which is no floor")
            elif floor_of[m] >= number:
                errors.append(f"doc/architecture.md: floor {name} (#{number}) lists {m} (#{floor_of[m]}), not below it")
        for p in paths:
            if not (root / p).exists():
                errors.append(f"doc/architecture.md: floor {name} names {p}, which does not exist")

    def row_of(rel: str):
        for prefix, name in owner:
            if rel == prefix or (prefix.endswith("/") and rel.startswith(prefix)):
                return name
        return None

    def resolve(including: Path, target: str):
        for base in (including.parent, root / "include", root / "src"):
            candidate = (base / target).resolve()
            if candidate.is_file():
                return candidate
        # A public header CMake generates (relpos/version.hpp) is its template cmake/NAME.in.
        template = root / "cmake" / (Path(target).name + ".in")
        if target.startswith("relpos/") and template.is_file():
            return template
        return None

    edges = {}
    files = sorted(f for d in SCANNED for f in (root / d).rglob("*") if f.suffix in EXTENSIONS and f.is_file())
    for f in files:
        rel = f.relative_to(root).as_posix()
        here = row_of(rel)
        if here is None:
            errors.append(f"{rel}: belongs to no floor of doc/architecture.md")
            continue
        for kind, target in INCLUDE.findall(f.read_text(encoding="utf-8", errors="replace")):
            if kind == "<" and not target.startswith("relpos/"):
                continue  # the standard library and third-party headers
            found = resolve(f, target)
            if found is None:
                errors.append(f'{rel}: #include "{target}" resolves to no file of the repository')
                continue
            there = row_of(found.relative_to(root).as_posix())
            if there is None:
                errors.append(f"{rel}: includes {target}, which belongs to no floor")
                continue
            if there == here:
                continue
            edges.setdefault(here, set()).add(there)
            if there not in allowed[here]:
                direction = "up" if floor_of[there] > floor_of[here] else (
                    "across" if floor_of[there] == floor_of[here] else "down to an unlisted floor")
                errors.append(f"{rel} ({here}, floor {floor_of[here]}) includes {target} "
                              f"({there}, floor {floor_of[there]}): {direction}")

    # Folder-level cycles in the actual include graph (depth-first search, three colours).
    state = {}

    def visit(node, path):
        state[node] = 1
        for nxt in sorted(edges.get(node, ())):
            if state.get(nxt) == 1:
                errors.append("cycle: " + " -> ".join(path[path.index(nxt):] + [nxt]))
            elif nxt not in state:
                visit(nxt, path + [nxt])
        state[node] = 2

    for node in sorted(edges):
        if node not in state:
            visit(node, [node])

    for e in errors:
        print(e)
    print(f"{len(files)} files, {sum(len(v) for v in edges.values())} floor-to-floor links, {len(errors)} errors")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
