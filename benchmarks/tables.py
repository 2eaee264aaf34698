#!/usr/bin/env python3
"""Print the markdown tables of doc/performance.md from benchmarks/results/{results,flint}.csv.

    /usr/bin/python3 benchmarks/tables.py [RESULTS_DIR]
    /usr/bin/python3 benchmarks/tables.py --edge [RESULTS_DIR]   # "Near tangency", from edge.csv
"""
import csv
import os
import sys

args = sys.argv[1:]
edge = "--edge" in args
args = [a for a in args if a != "--edge"]
out = args[0] if args else os.path.join(os.path.dirname(__file__), "results")

if edge:
    ed = sorted(csv.DictReader(open(os.path.join(out, "edge.csv"))), key=lambda r: int(r["k"]))
    floats = [c[: -len("_error_rate")] for c in ed[0] if c.endswith("_error_rate")]
    us = lambda r, m: float(r[m + "_ns"]) / 1000  # noqa: E731
    print("| δ | decide_position (µs) | classify_exact, minimal (µs) | FLINT reference (µs) | decide / exact "
          "| exact / FLINT | classify, full evidence (µs) | certificate's share of the full evidence time |")
    print("|---|---|---|---|---|---|---|---|")
    for r in ed:
        print(f"| 2^-{r['k']} | {us(r, 'decide'):.1f} | {us(r, 'exact'):.1f} | {us(r, 'flint'):.1f} "
              f"| {us(r, 'decide') / us(r, 'exact'):.2f} | {us(r, 'exact') / us(r, 'flint'):.2f} "
              f"| {us(r, 'full'):.0f} | {100 * float(r['certificate_share']):.0f} % |")
    print()
    print("| δ | " + " | ".join(f"{m}: µs / error rate" for m in floats) + " | decided by (decide_position) |")
    print("|---" * (len(floats) + 2) + "|")
    for r in ed:
        stages = ", ".join(f"{c[len('stage_'):]} {r[c]}" for c in r if c.startswith("stage_") and int(r[c]) > 0)
        print(f"| 2^-{r['k']} | " + " | ".join(f"{us(r, m):.2f} / {float(r[m + '_error_rate']):.2f}" for m in floats)
              + f" | {stages} |")
    sys.exit(0)

rows = list(csv.DictReader(open(os.path.join(out, "results.csv"))))
flint = list(csv.DictReader(open(os.path.join(out, "flint.csv"))))


def get(fam, eps, method):
    for r in rows:
        if r["family"] == fam and r["eps"] == eps and r["method"] == method:
            return r
    raise KeyError((fam, eps, method))


def fget(fam, eps):
    for r in flint:
        if r["family"] == fam and r["eps"] == eps:
            return r
    raise KeyError((fam, eps))


methods = ["naive-double", "long-double", "float128", "mpfr-256", "interval", "exact", "flint", "adaptive"]
print("| family | " + " | ".join(methods) + " |")
print("|---" * (len(methods) + 1) + "|")
for fam in ["a", "b"]:
    cells = []
    for m in methods:
        v = f"{float(get(fam, '', m)['pair_median_ns']):.0f}"
        cells.append(f"**{v}**" if m == "adaptive" else v)
    print(f"| ({fam}) median ns | " + " | ".join(cells) + " |")
    errs = []
    for m in methods:
        r = get(fam, "", m)
        e, d = float(r["error_rate"]), float(r["decided_fraction"])
        errs.append(f"{e:.3f}" + (f" (decided {d:.2f})" if d < 1 else ""))
    print(f"| ({fam}) error rate | " + " | ".join(errs) + " |")
print()
print("| eps | exact-double inputs | naive-double | long-double | float128 | mpfr-256 | interval | adaptive err "
      "| adaptive median ns | exact median ns | flint median ns |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for e in ["1e-2", "1e-4", "1e-6", "1e-8", "1e-10", "1e-12", "1e-14", "1e-16", "1e-18", "1e-20", "1e-24", "1e-30",
          "1e-34", "1e-36", "1e-40"]:
    a = get("c", e, "adaptive")
    errs = []
    for m in ["naive-double", "long-double", "float128", "mpfr-256", "interval"]:
        r = get("c", e, m)
        x = f"{float(r['error_rate']):.3f}"
        if m == "interval":
            x += f" ({float(r['decided_fraction']):.2f})"
        errs.append(x)
    print(f"| {e} | {a['exact_double_inputs']}/{a['n']} | " + " | ".join(errs) +
          f" | {float(a['error_rate']):.3f} | {float(a['pair_median_ns']):.0f}"
          f" | {float(get('c', e, 'exact')['pair_median_ns']):.0f} | {float(get('c', e, 'flint')['pair_median_ns']):.0f} |")
print()
print("| family | exact (µs) | flint (µs) | adaptive (µs) | exact / flint | flint / adaptive |")
print("|---|---|---|---|---|---|")
for name, fam, eps in [("(a) generic random", "a", ""), ("(b) exact tangencies", "b", "")] + \
        [(f"(c) eps = {e}", "c", e) for e in ["1e-2", "1e-8", "1e-16", "1e-40"]] + \
        [(f"(c-sym) eps = {e}", "c-sym", e) for e in ["1e-2", "1e-6", "1e-40"]]:
    r = fget(fam, eps)
    ex, fl, ad = (float(r[k]) / 1000 for k in ("exact_ns", "flint_ns", "adaptive_ns"))
    print(f"| {name} | {ex:.1f} | {fl:.1f} | {ad:.2f} | {ex / fl:.1f} | {fl / ad:.2f} |")
print()
print("c-sym adaptive per-pair medians (ns):",
      {e: get("c-sym", e, "adaptive")["pair_median_ns"] for e in ["1e-2", "1e-4", "1e-6", "1e-16", "1e-40"]})
