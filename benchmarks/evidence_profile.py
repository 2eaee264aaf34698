#!/usr/bin/python3
"""Where a full-evidence line of `relpos batch` spends its time, component by component
(doc/performance.md, "Where a full-evidence line's time goes").

    /usr/bin/python3 benchmarks/evidence_profile.py --cli build/cli/relpos [--lines 5000] [--out FILE.json]

For each regime file of benchmarks/batch_bench.py (sphere, matrix and user: spheres and standard
paraboloids placed as a user's are), `relpos batch --evidence full --threads 1` is sampled by `perf
record` (task clock, DWARF call graphs, so inlined functions count for their callers) and every
component's share is the share of the samples with one of its functions on the stack (inclusive),
among the samples whose stack was unwound to main (perf cannot unwind every sample taken inside GMP;
those are assumed spread as the others are), the process start-up apart.
The CPU time of a line is timed apart, without perf, the best of --repeat runs (and that of minimal
evidence beside it); a component's microseconds are its share of that time.

Callgrind is not used: valgrind runs every floating-point operation rounded to nearest whatever the
rounding mode, so the fast reader's enclosures of decimal text collapse to points and the numbers are
read as doubles: another path, with other answers.
"""

import argparse
import json
import os
import re
import resource
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from batch_bench import write_regime  # noqa: E402

# Component -> the functions (demangled names, up to the argument list) whose samples it counts;
# "minus" components are a parent's share less its children's.
COMPONENTS = [
    ("read", "reading the line (scan, numbers, quadrics)", ["relpos::detail::io::read_batch_line"]),
    ("decide", "deciding (the ladder's stages)", ["relpos::(anonymous namespace)::classify_impl"]),
    ("evidence", "evidence (all of fill_full_evidence)", ["relpos::detail::fill_full_evidence"]),
    ("pencil", "  f, s, λ_s in lowest terms (EvidencePencil)", ["relpos::detail::EvidencePencil::EvidencePencil"]),
    ("forms", "    the integer forms and their scales", ["relpos::detail::EvidencePencil::write_integer_forms"]),
    ("lowest", "    lowest terms (divided_by_powers)", ["relpos::detail::forms::divided_by_powers"]),
    ("roots", "  the roots isolated (exact_root_structure)", ["relpos::exact_root_structure"]),
    ("certificate", "  the certificate", ["relpos::detail::certificate::definite", "relpos::detail::certificate::tangent",
                                          "relpos::detail::certificate::crossing_points"]),
    ("write", "writing the answer (JSON)", ["relpos::detail::io::append_members"]),
    ("digits", "  the rationals' decimal digits", ["relpos::detail::io::(anonymous namespace)::put_decimal"]),
    ("startup", "process start-up (dynamic linking)", ["_dl_start"]),
]


def cpu_seconds(cmd, repeat):
    """Best user + system seconds of the command over `repeat` runs (its output discarded)."""
    best = None
    for _ in range(repeat):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        subprocess.run(cmd, stdout=subprocess.DEVNULL, check=True)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        t = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        best = t if best is None else min(best, t)
    return best


def inclusive_shares(cli, data, tmp):
    """{demangled function name: share of samples with it on the stack} of one full-evidence run."""
    trace = os.path.join(tmp, "perf.data")
    subprocess.run(["perf", "record", "-q", "-e", "task-clock", "-F", "4000", "--call-graph", "dwarf,16384",
                    "-o", trace, cli, "batch", "--evidence", "full", "--threads", "1", data],
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    report = subprocess.run(["perf", "report", "-i", trace, "--children", "--stdio", "-g", "none",
                             "--percent-limit", "0"], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                            text=True, check=True).stdout
    shares = {}
    for line in report.splitlines():
        m = re.match(r"\s*([0-9.]+)%\s+[0-9.]+%\s+\S+\s+\S+\s+\[\.\]\s+(.*)$", line)
        if not m:
            continue
        anon = "(anonymous namespace)"  # the name up to its argument list
        key = m.group(2).replace(anon, "\0").split("(")[0].split(" [clone")[0].strip().replace("\0", anon)
        shares[key] = max(shares.get(key, 0.0), float(m.group(1)) / 100)
    return shares


def component_shares(shares):
    """Each component's share of the samples unwound to main, and the start-up's of all."""
    unwound = shares.get("main", 0.0)
    out = {}
    for tag, _, names in COMPONENTS:
        out[tag] = sum(shares.get(n, 0.0) for n in names) / (1 if tag == "startup" else unwound)
    out["decide"] = max(0.0, out["decide"] - out["evidence"])  # classify_impl holds the evidence
    out = {t: v * (1 - out["startup"]) if t != "startup" else v for t, v in out.items()}
    top = ("read", "decide", "evidence", "write", "startup")
    out["other"] = max(0.0, 1 - sum(out[t] for t in top))
    out["unwound"] = unwound
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cli", default="build/cli/relpos")
    ap.add_argument("--lines", type=int, default=5000)
    ap.add_argument("--repeat", type=int, default=5, help="timed runs per command (the best is kept)")
    ap.add_argument("--out", help="write the figures as JSON to this file")
    args = ap.parse_args()
    load = lambda: " ".join(f"{x:.2f}" for x in os.getloadavg())  # noqa: E731
    result = {"lines": args.lines, "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
              "load_before": load(), "forms": {}}
    with tempfile.TemporaryDirectory() as tmp:
        for form in ("sphere", "matrix", "user"):
            data = os.path.join(tmp, form + ".jsonl")
            write_regime(data, args.lines, form=form)
            batch = lambda evidence: [args.cli, "batch", "--evidence", evidence, "--threads", "1", data]  # noqa
            full = cpu_seconds(batch("full"), args.repeat)
            minimal = cpu_seconds(batch("minimal"), args.repeat)
            parts = component_shares(inclusive_shares(args.cli, data, tmp))
            result["forms"][form] = {"full_us": 1e6 * full / args.lines, "minimal_us": 1e6 * minimal / args.lines,
                                     "shares": parts}
            print(f"{form}: full evidence {1e6 * full / args.lines:.1f} µs a line, minimal "
                  f"{1e6 * minimal / args.lines:.1f} µs (CPU, one thread, best of {args.repeat})")
            for tag, label, _ in COMPONENTS + [("other", "the rest (allocation, the pipeline, ...)", [])]:
                print(f"  {label:48} {100 * parts[tag]:5.1f} %  {1e6 * full / args.lines * parts[tag]:6.2f} µs")
    result["load_after"] = load()
    result["components"] = [[tag, label] for tag, label, _ in COMPONENTS] + [
        ["other", "the rest (allocation, the pipeline, ...)"]]
    if args.out:
        with open(args.out, "w") as f:
            json.dump(result, f, indent=1)


if __name__ == "__main__":
    main()
