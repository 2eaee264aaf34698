#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-3.0-or-later
"""relpos is LGPL-3.0-or-later because every CGAL header it includes offers the LGPL (README.md,
"License"). This check keeps it so: it preprocesses every translation unit of the library, the CLI
and the Python extension with the build's own flags (compile_commands.json, `-M`: every header
reached, transitively), reads the SPDX-License-Identifier line of each CGAL header and fails on a
header that offers no licence a proprietary program may link (GPL-only CGAL packages such as
Nef_polyhedron_3 or Triangulation_2 are "GPL-3.0-or-later OR LicenseRef-Commercial").

    check_cgal_licences.py COMPILE_COMMANDS_JSON SOURCE_DIR

It first checks itself: a translation unit including <CGAL/convex_hull_2.h> (GPL) must be flagged.
"""
import json
import os
import re
import shlex
import subprocess
import sys
import tempfile

# Licences under which code may be linked into a program of any licence (with the LGPL's terms).
PERMISSIVE = {"LGPL-3.0-or-later", "LGPL-3.0-only", "BSL-1.0", "MIT"}
# Translation units that end up in what relpos distributes: library, CLI, Python extension.
PROJECT_DIRS = ("src/", "cli/", "python/src/")


def acceptable(expression):
    """True when one OR-alternative of the SPDX expression consists of permissive licences only."""
    flat = expression.replace("(", " ").replace(")", " ")
    for alternative in re.split(r"\s+OR\s+", flat.strip()):
        parts = [p.strip() for p in re.split(r"\s+AND\s+", alternative)]
        if all(p in PERMISSIVE for p in parts):
            return True
    return False


def spdx(path):
    with open(path, errors="replace") as f:
        for line in f:
            m = re.search(r"SPDX-License-Identifier:\s*(.*\S)", line)
            if m:
                return m.group(1).rstrip("*/ ").strip()
    return None


def headers_reached(argv, cwd):
    """Every header the compiler reads for this command line (preprocessing only)."""
    out, skip = [], False
    for a in argv:
        if skip:
            skip = False
        elif a in ("-o", "-MF", "-MT", "-MQ"):
            skip = True
        elif a not in ("-c", "-MD", "-MMD"):
            out.append(a)
    r = subprocess.run(out + ["-M"], cwd=cwd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("preprocessing failed: %s\n%s" % (" ".join(out), r.stderr))
    deps = r.stdout.replace("\\\n", " ").split(":", 1)[1].split()
    return {os.path.realpath(d) for d in deps}


def offending(headers):
    bad = []
    for h in sorted(headers):
        if "/CGAL/" not in h:
            continue
        lic = spdx(h)
        if lic is None or not acceptable(lic):
            bad.append((h, lic))
    return bad


def self_check(compiler):
    with tempfile.TemporaryDirectory() as tmp:
        tu = os.path.join(tmp, "gpl.cpp")
        with open(tu, "w") as f:
            f.write("#include <CGAL/convex_hull_2.h>\n")
        bad = offending(headers_reached([compiler, "-std=c++17", "-c", tu], tmp))
    if not any(h.endswith("/CGAL/convex_hull_2.h") for h, _ in bad):
        sys.exit("self-check failed: <CGAL/convex_hull_2.h> (GPL) was not flagged")


def main():
    commands, source_dir = sys.argv[1], os.path.realpath(sys.argv[2])
    with open(commands) as f:
        entries = json.load(f)
    units, headers = 0, set()
    compiler = None
    for e in entries:
        path = os.path.realpath(e["file"])
        # A unity build's batch (CMakeLists.txt, "Unity build") includes the library's sources.
        unity = re.search(r"/Unity/unity_[0-9]+_cxx\.cxx$", path)
        if not os.path.relpath(path, source_dir).startswith(PROJECT_DIRS) and not unity:
            continue
        argv = shlex.split(e["command"]) if "command" in e else e["arguments"]
        if os.path.basename(argv[0]) == "ccache":
            argv = argv[1:]
        compiler = compiler or argv[0]
        headers |= headers_reached(argv, e["directory"])
        units += 1
    if units == 0:
        sys.exit("no translation unit of src/, cli/ or python/src/ in %s" % commands)
    self_check(compiler)
    cgal = [h for h in headers if "/CGAL/" in h]
    bad = offending(headers)
    print("%d translation units, %d CGAL headers reached" % (units, len(cgal)))
    for h, lic in bad:
        print("not LGPL: %s (%s)" % (h, lic or "no SPDX-License-Identifier line"))
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
