"""Charts for benchmarks/results (doc/performance.md). Usage: plot.py RESULTS_DIR"""
import csv
import json
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = sys.argv[1] if len(sys.argv) > 1 else "benchmarks/results"
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
fig.savefig(f"{out}/time_per_family.png", dpi=110)

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
fig.savefig(f"{out}/error_vs_eps.png", dpi=110)

# (3) speed-accuracy: pooled over every pair of every family (time weighted by n).
fig, ax = plt.subplots(figsize=(7, 5))
for m in methods:
    rs = [r for r in rows if r["method"] == m]
    n = sum(int(r["n"]) for r in rs)
    err = sum(float(r["error_rate"]) * int(r["n"]) for r in rs) / n
    tm = sum(float(r["median_ns"]) * int(r["n"]) for r in rs) / n  # family means
    ax.scatter([tm], [err], s=60, color=colors[m], label=m)
    ax.annotate(m, (tm, err), textcoords="offset points", xytext=(5, 5), fontsize=8)
ax.set_xscale("log")
ax.set_xlabel("mean time per query over all families [ns] (log)")
ax.set_ylabel("error rate over all pairs (wrong or undecided)")
ax.set_title("Speed vs accuracy (all families pooled)")
ax.grid(alpha=0.3)
fig.tight_layout()
fig.savefig(f"{out}/speed_accuracy.png", dpi=110)

s = json.load(open(f"{out}/summary.json"))
print("adaptive/naive-double on (a): %.2f   adaptive median on (b): %.2f us" %
      (s["adaptive_over_naive_double_family_a"], s["adaptive_median_family_b_us"]))
