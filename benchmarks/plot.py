"""Charts for benchmarks/results (doc/performance.md). Usage: plot.py [--edge | --general] RESULTS_DIR

--edge: only the near-tangency chart, from edge.csv (edge_bench).
--general: only the general quadrics' near-tangency chart, from general_edge.csv (general_bench --edge).
"""
import csv
import json
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from provenance import savefig  # noqa: E402


def near_tangency(out, colors):
    """(6) the near-tangent regime (edge_bench, edge.csv): time per delta of the exact methods and of
    the float pipelines, and each float pipeline's error rate against its time."""
    ed = sorted(csv.DictReader(open(f"{out}/edge.csv")), key=lambda r: int(r["k"]))
    ks = [int(r["k"]) for r in ed]
    exact_cols = [("decide", "decide_position", "black"), ("exact", "classify_exact, minimal", "tab:brown"),
                  ("flint", "FLINT reference", "tab:pink"), ("full", "classify, full evidence", "tab:purple")]
    floats = [c[: -len("_error_rate")] for c in ed[0] if c.endswith("_error_rate")]
    fig, axes = plt.subplots(1, 2, figsize=(13, 4.8))
    for name, label, color in exact_cols:
        axes[0].plot(ks, [float(r[name + "_ns"]) / 1000 for r in ed], marker="o", label=label, color=color)
    for m in floats:
        axes[0].plot(ks, [float(r[m + "_ns"]) / 1000 for r in ed], marker="x", ls="--", label=m + " (not exact)",
                     color=colors.get(m))
    axes[0].set_yscale("log")
    axes[0].set_xticks(ks, ["2^-%d" % k for k in ks])
    axes[0].set_xlabel("distance delta of the sphere from an exact tangency")
    axes[0].set_ylabel("per-pair median [us] (log), timed back to back")
    axes[0].set_title(f"Near tangency: time per delta ({ed[0]['n']} spheres each)")
    axes[0].grid(alpha=0.3, which="both")
    axes[0].legend(fontsize=7)
    for m in floats + ["decide"]:
        xs = [float(r[m + "_ns"]) / 1000 for r in ed]
        ys = [float(r[m + "_error_rate"]) if m != "decide" else 0.0 for r in ed]
        axes[1].plot(xs, ys, marker="o", label=m if m != "decide" else "decide_position (exact)",
                     color="black" if m == "decide" else colors.get(m))
        for x, y, k in list(zip(xs, ys, ks))[:: len(ks) - 1]:  # the first and last delta
            axes[1].annotate("2^-%d" % k, (x, y), textcoords="offset points", xytext=(4, 3), fontsize=7)
    axes[1].set_xscale("log")
    axes[1].set_xlabel("per-pair median [us] (log)")
    axes[1].set_ylabel("error rate (wrong or undecided)")
    axes[1].set_title("Near tangency: speed vs accuracy per delta")
    axes[1].grid(alpha=0.3)
    axes[1].legend(fontsize=8)
    fig.tight_layout()
    savefig(fig, f"{out}/near_tangency.png", [f"{out}/edge.csv"])


def general_edge(out):
    """The float decisions' error rates against the nudge 10^-k of a tangency, per type of quadric
    (general_bench --edge, general_edge.csv)."""
    rows = list(csv.DictReader(open(f"{out}/general_edge.csv")))
    types = []
    for r in rows:
        if r["type"] not in types:
            types.append(r["type"])
    colors = dict(zip(types, plt.cm.tab20.colors[::2] + plt.cm.tab20.colors[1::2]))
    fig, axes = plt.subplots(1, 2, figsize=(13, 4.8), sharey=True)
    for ax, col, title in ((axes[0], "pencil_float_wrong", "float decision of the pencil (sign rule in doubles)"),
                           (axes[1], "wwk_wrong", "Wang–Wang–Kim in doubles (separated or not)")):
        for t in types:
            rs = sorted((r for r in rows if r["type"] == t), key=lambda r: int(r["k"]))
            ax.plot([int(r["k"]) for r in rs], [int(r[col]) / int(r["n"]) for r in rs], marker="o", label=t,
                    color=colors[t], ls="-" if t == "ellipsoid" else "--", lw=2.2 if t == "ellipsoid" else 1)
        ax.set_xlabel("k: the tangency nudged by 10^-k")
        ax.set_title(title)
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("error rate (wrong answers)")
    axes[1].legend(fontsize=7)
    fig.tight_layout()
    savefig(fig, f"{out}/general_edge.png", [f"{out}/general_edge.csv"])


args = [a for a in sys.argv[1:] if a not in ("--edge", "--general")]
out = args[0] if args else "benchmarks/results"
if "--general" in sys.argv:
    general_edge(out)
    sys.exit(0)
if "--edge" in sys.argv:  # only the near-tangency chart (edge_bench's edge.csv)
    near_tangency(out, dict(zip(["naive-double", "long-double", "float128", "mpfr-256", "interval", "exact", "flint",
                                 "adaptive"], plt.cm.tab10.colors)))
    sys.exit(0)
rows = list(csv.DictReader(open(f"{out}/results.csv")))
methods = []
for r in rows:
    if r["method"] not in methods:
        methods.append(r["method"])
colors = dict(zip(methods, plt.cm.tab10.colors))

# (1) per-pair median time per method per family ((c) rows pooled: median of the per-eps medians).
fams = ["a", "b", "c", "c-sym"]
labels = {"a": "(a) generic random", "b": "(b) exact tangencies", "c": "(c) near-tangent",
          "c-sym": "(c-sym) near-tangent, symmetric"}
def med(xs):
    xs = sorted(xs)
    return xs[len(xs) // 2] if xs else float("nan")
t = defaultdict(list)
for r in rows:
    t[(r["family"], r["method"])].append(float(r["pair_median_ns"]))
fig, ax = plt.subplots(figsize=(10, 5))
w = 0.8 / len(methods)
for i, m in enumerate(methods):
    ys = [med(t[(f, m)]) for f in fams]
    ax.bar([j + i * w for j in range(len(fams))], ys, w, label=m, color=colors[m])
ax.set_yscale("log")
ax.set_xticks([j + 0.4 - w / 2 for j in range(len(fams))], [labels[f] for f in fams])
ax.set_ylabel("median time per classification [ns] (log)")
ax.set_title("Time per classification (for (c): median over eps levels)")
ax.legend(fontsize=8, ncol=4)
ax.grid(axis="y", which="both", alpha=0.3)
fig.tight_layout()
savefig(fig, f"{out}/time_per_family.png", [f"{out}/results.csv"])

# (2) error rate vs eps, families c and c-sym.
fig, axes = plt.subplots(1, 2, figsize=(12, 4.5), sharey=True)
for ax, fam in zip(axes, ["c", "c-sym"]):
    for m in methods:
        pts = [(float(r["eps"]), float(r["error_rate"])) for r in rows if r["family"] == fam and r["method"] == m]
        pts.sort()
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="o", ms=3, label=m, color=colors[m])
    ax.set_xscale("log")
    ax.invert_xaxis()
    ax.set_xlabel("shift of the sphere centre eps (actually 2^-round(log2(1/eps)))")
    ax.set_title(labels[fam])
    ax.grid(alpha=0.3)
axes[0].set_ylabel("error rate (wrong or undecided)")
axes[0].legend(fontsize=8)
fig.tight_layout()
savefig(fig, f"{out}/error_vs_eps.png", [f"{out}/results.csv"])

# (3) speed-accuracy: pooled over every pair of every family (time weighted by n).
fig, ax = plt.subplots(figsize=(7, 5))
points = []
for m in methods:
    rs = [r for r in rows if r["method"] == m]
    n = sum(int(r["n"]) for r in rs)
    err = sum(float(r["error_rate"]) * int(r["n"]) for r in rs) / n
    tm = sum(float(r["median_ns"]) * int(r["n"]) for r in rs) / n  # family means
    ax.scatter([tm], [err], s=60, color=colors[m], label=m)
    points.append((tm, err, m))
ax.set_xscale("log")
ax.margins(x=0.25, y=0.15)
# Labels that do not overlap: placed one by one (lowest error first), each moved up in steps of
# its height until its estimated box (in points: ~5 pt per character, 9 pt high) meets no box
# placed before, then drawn with a leader line when it moved.
fig.canvas.draw()
to_pt = 72.0 / fig.dpi
placed = []
for tm, err, m in sorted(points, key=lambda p: (p[1], p[0])):
    px, py = ax.transData.transform((tm, err))
    x0, y0 = px * to_pt + 8, py * to_pt
    w, h = 5.0 * len(m) + 2, 10.0
    dy = 4
    while any(x0 < bx + bw and bx < x0 + w and y0 + dy < by + bh and by < y0 + dy + h for bx, by, bw, bh in placed):
        dy += h
    placed.append((x0, y0 + dy, w, h))
    ax.annotate(m, (tm, err), textcoords="offset points", xytext=(8, dy), fontsize=8,
                arrowprops=dict(arrowstyle="-", lw=0.5, color="0.5") if dy > 4 else None)
ax.set_xlabel("mean time per query over all families [ns] (log)")
ax.set_ylabel("error rate over all pairs (wrong or undecided)")
ax.set_title("Speed vs accuracy (all families pooled)")
ax.grid(alpha=0.3)
fig.tight_layout()
savefig(fig, f"{out}/speed_accuracy.png", [f"{out}/results.csv"])

# (4) the FLINT reference, timed back to back with exact (GMP) and adaptive on each pair (flint.csv).
fl = list(csv.DictReader(open(f"{out}/flint.csv")))
trio = [("exact_ns", "exact"), ("flint_ns", "flint"), ("adaptive_ns", "adaptive")]
fig, axes = plt.subplots(1, 3, figsize=(14, 4.5), gridspec_kw={"width_ratios": [1, 2, 2]})
ab = [r for r in fl if r["family"] in ("a", "b")]
for i, (col, m) in enumerate(trio):
    axes[0].bar([j + i * 0.27 for j in range(len(ab))], [float(r[col]) for r in ab], 0.27, label=m,
                color=colors.get(m))
axes[0].set_xticks([j + 0.27 for j in range(len(ab))], ["(%s)" % r["family"] for r in ab])
for ax, fam in zip(axes[1:], ["c", "c-sym"]):
    rs = sorted((r for r in fl if r["family"] == fam), key=lambda r: -float(r["eps"]))
    for col, m in trio:
        ax.plot([float(r["eps"]) for r in rs], [float(r[col]) for r in rs], marker="o", ms=3, label=m,
                color=colors.get(m))
    ax.set_xscale("log")
    ax.invert_xaxis()
    ax.set_xlabel("eps")
    ax.set_title(labels[fam])
for ax in axes:
    ax.set_yscale("log")
    ax.grid(alpha=0.3, which="both")
axes[0].set_ylabel("per-pair median [ns] (log), timed back to back")
axes[0].set_title("(a), (b)")
axes[0].legend(fontsize=8)
fig.tight_layout()
savefig(fig, f"{out}/flint_reference.png", [f"{out}/flint.csv"])

# (5) which stage of the adaptive method decided: stage columns read by name from stages.csv
# (every column after "n"), so a new Stage needs no change here.
st = list(csv.DictReader(open(f"{out}/stages.csv")))
stage_cols = [c for c in st[0].keys() if c not in ("family", "eps", "n")] if st else []
xs = [r for r in st if r["family"] in ("a", "b")] + [r for r in st if r["family"] in ("c", "c-sym")]
fig, ax = plt.subplots(figsize=(14, 4.5))
bottom = [0.0] * len(xs)
for k, c in enumerate(stage_cols):
    ys = [int(r[c]) / int(r["n"]) for r in xs]
    ax.bar(range(len(xs)), ys, bottom=bottom, label=c, color=plt.cm.tab10.colors[k % 10])
    bottom = [b + y for b, y in zip(bottom, ys)]
ax.set_xticks(range(len(xs)), [r["family"] + (" " + r["eps"] if r["eps"] else "") for r in xs], rotation=90,
              fontsize=7)
ax.set_ylabel("fraction of pairs")
ax.set_title("Deciding stage of the adaptive method")
ax.legend(fontsize=8, ncol=len(stage_cols))
fig.tight_layout()
savefig(fig, f"{out}/stages.png", [f"{out}/stages.csv"])

if os.path.exists(f"{out}/edge.csv"):
    near_tangency(out, colors)

s = json.load(open(f"{out}/summary.json"))
print("adaptive/naive-double on (a): %.2f   adaptive median on (b): %.2f us" %
      (s["adaptive_over_naive_double_family_a"], s["adaptive_median_family_b_us"]))
f = s["flint"]
print("flint: errors %s, self-check failures %d; " % (f["errors"], f["self_check_failures"]) +
      "  ".join("(%s) %.0f ns, exact/flint %.1f, flint/adaptive %.1f" %
                (k, f[k]["flint_ns"], f[k]["exact_over_flint"], f[k]["flint_over_adaptive"])
                for k in ("a", "b", "c", "c-sym")))
