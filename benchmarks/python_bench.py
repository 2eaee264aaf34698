#!/usr/bin/python3
"""Speed of the Python package (doc/python.md, "Measured"), every figure against a float baseline
timed in the same run:

- `decide_positions` on random float64 pairs (own paraboloid per pair, one shared paraboloid; 1 and 2
  threads) against the minimal float decision written in numpy on the same arrays (the characteristic
  quartic by the Laplace expansion, 27 Disc from the invariants, the sign rule: what a numpy user
  would write, vectorized, no certification);
- one pair at a time (`Ellipsoid(matrix)`, `Paraboloid(matrix)`, `classify`) against the same minimal
  float decision in pure Python on one pair;
- `relpos.distributed.batch` on one file of the paper's regime (benchmarks/batch_bench.py) with 1 and
  2 Dask worker processes against `relpos batch`.

    PYTHONPATH=build/python RELPOS_CLI=build/cli/relpos /usr/bin/python3 benchmarks/python_bench.py \
        [--pairs 20000] [--single 2000] [--rounds 5] [--out FILE.json] [--dask-lines 200000] [--runs 3] \
        [--skip-dask] [--skip-decide]

Each round times every decide path once (best of 3 calls), interleaved; printed and written (--out):
per path the median over rounds of pairs per second and of the per-round ratio to the baseline, with
its range. The answers are checked before timing: relpos's paths agree with each other, and the float
baselines' disagreements with relpos are counted (they are wrong or undecided there).
"""

import argparse
import json
import os
import statistics
import tempfile
import time

import numpy

import relpos

POSITION = {name: k for k, name in enumerate(relpos.POSITION_NAMES)}
PAIRS = ((0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3))
SIGNS = (1, -1, 1, 1, -1, 1)


def random_pairs(n, seed=2024):
    """Small spheres near the cup of z = x^2/a^2 + y^2/b^2 (a, b in [0.5, 2])."""
    rng = numpy.random.default_rng(seed)
    a = rng.uniform(0.5, 2.0, n)
    b = rng.uniform(0.5, 2.0, n)
    x, y = rng.uniform(-1, 1, (2, n))
    z = x * x / (a * a) + y * y / (b * b) + rng.uniform(-0.3, 0.3, n)
    r = rng.uniform(0.01, 0.3, n)
    E = numpy.zeros((n, 4, 4))
    E[:, 0, 0] = E[:, 1, 1] = E[:, 2, 2] = 1
    for k, c in enumerate((x, y, z)):
        E[:, k, 3] = E[:, 3, k] = -c
    E[:, 3, 3] = x * x + y * y + z * z - r * r
    P = numpy.zeros((n, 4, 4))
    P[:, 0, 0] = 1 / (a * a)
    P[:, 1, 1] = 1 / (b * b)
    P[:, 2, 3] = P[:, 3, 2] = -0.5
    return E, P


def quartic(e, p, mul):
    """f(l) = det(l P + E) by the Laplace expansion along rows (0, 1), for entries read as e(i, j),
    p(i, j) (numpy columns or Python floats): the library's formula (math.md §2)."""
    f = [0.0] * 5
    for k, (top, bot) in enumerate(zip(PAIRS, reversed(PAIRS))):
        u = minor(e, p, 0, 1, top)
        v = minor(e, p, 2, 3, bot)
        uv = (mul(u[0], v[0]), mul(u[0], v[1]) + mul(u[1], v[0]), mul(u[0], v[2]) + mul(u[1], v[1]) + mul(u[2], v[0]),
              mul(u[1], v[2]) + mul(u[2], v[1]), mul(u[2], v[2]))
        f = [a + b for a, b in zip(f, uv)] if SIGNS[k] > 0 else [a - b for a, b in zip(f, uv)]
    return f


def minor(e, p, r0, r1, cols):
    c0, c1 = cols
    a0, b0, c, d0 = e(r0, c0), e(r0, c1), e(r1, c0), e(r1, c1)
    a1, b1, c_, d1 = p(r0, c0), p(r0, c1), p(r1, c0), p(r1, c1)
    return (a0 * d0 - b0 * c, a0 * d1 + a1 * d0 - b0 * c_ - b1 * c, a1 * d1 - b1 * c_)


def minimal_from_quartic(f, where):
    """C where 27 Disc(f) = 4 I^3 - J^2 < 0, else E with two sign changes in f's coefficients, else I."""
    e, d, c, b, a = f
    I = 12 * a * e - 3 * b * d + c * c
    J = 72 * a * c * e + 9 * b * c * d - 27 * a * d * d - 27 * e * b * b - 2 * c * c * c
    disc27 = 4 * I * I * I - J * J
    changes = sum((f[i] < 0) != (f[i + 1] < 0) for i in range(4))
    return where(disc27 < 0, POSITION["C"], where(changes >= 2, POSITION["E"], POSITION["I"]))


def numpy_minimal(E, P):
    """The minimal float decision on n pairs at once (E: (n, 4, 4); P: (n, 4, 4) or (4, 4))."""
    if P.ndim == 2:
        P = numpy.broadcast_to(P, E.shape)
    f = quartic(lambda i, j: E[:, i, j], lambda i, j: P[:, i, j], numpy.multiply)
    return minimal_from_quartic(f, numpy.where).astype(numpy.int8)


def python_minimal(e, p):
    """The same decision in pure Python on one pair given as nested lists of floats."""
    f = quartic(lambda i, j: e[i][j], lambda i, j: p[i][j], lambda x, y: x * y)
    return minimal_from_quartic(f, lambda c, x, y: x if c else y)


def best_of(k, f):
    times = []
    for _ in range(k):
        t = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - t)
    return min(times), out


def decide_bench(args):
    """The decide paths against the float baselines, in interleaved rounds; returns the results."""
    E, P = random_pairs(args.pairs)
    shared = P[0]
    exact_own = relpos.decide_positions(E, P, threads=1)
    exact_shared = relpos.decide_positions(E, shared, threads=1)
    for threads in (2,):
        if not (numpy.array_equal(relpos.decide_positions(E, P, threads=threads), exact_own)
                and numpy.array_equal(relpos.decide_positions(E, shared, threads=threads), exact_shared)):
            raise SystemExit("decide_positions: the answers depend on the thread count")
    float_own, float_shared = numpy_minimal(E, P), numpy_minimal(E, shared)
    wrong = int((float_own != exact_own).sum()) + int((float_shared != exact_shared).sum())

    m = args.single
    e_lists, p_lists = E[:m].tolist(), P[:m].tolist()
    single_exact = [relpos.classify(relpos.Ellipsoid(E[i]), relpos.Paraboloid(P[i]), "minimal").position
                    for i in range(m)]
    if [POSITION[x] for x in single_exact] != list(exact_own[:m]):
        raise SystemExit("classify and decide_positions disagree")
    single_wrong = int(sum(python_minimal(e_lists[i], p_lists[i]) != exact_own[i] for i in range(m)))

    def single(evidence):
        def run():
            for i in range(m):
                relpos.classify(relpos.Ellipsoid(E[i]), relpos.Paraboloid(P[i]), evidence)
        return run

    def single_float():
        for i in range(m):
            python_minimal(e_lists[i], p_lists[i])

    # (key, label, pairs per call, baseline key or None, callable)
    paths = [
        ("numpy", "minimal float decision in numpy, own P per pair (baseline)", args.pairs, None,
         lambda: numpy_minimal(E, P)),
        ("numpy_shared", "minimal float decision in numpy, one shared P (baseline)", args.pairs, None,
         lambda: numpy_minimal(E, shared)),
    ]
    for threads in (1, 2):
        paths.append(("own_%d" % threads, "`decide_positions`, own P per pair, threads=%d" % threads, args.pairs,
                      "numpy", lambda t=threads: relpos.decide_positions(E, P, threads=t)))
    for threads in (1, 2):
        paths.append(("shared_%d" % threads, "`decide_positions`, one shared P, threads=%d" % threads, args.pairs,
                      "numpy_shared", lambda t=threads: relpos.decide_positions(E, shared, threads=t)))
    paths += [
        ("python", "minimal float decision in pure Python, one pair per call (baseline)", m, None, single_float),
        ("single_minimal", "`Ellipsoid(E)`, `Paraboloid(P)`, `classify(e, p, \"minimal\")`, one pair per call", m,
         "python", single("minimal")),
        ("single_full", "`Ellipsoid(E)`, `Paraboloid(P)`, `classify(e, p)` (full evidence), one pair per call", m,
         "python", single("full")),
    ]
    seconds = {key: [] for key, *_ in paths}
    for _ in range(args.rounds):
        for key, _, n, _, run in paths:
            seconds[key].append(best_of(3, run)[0] / n)
    results = {"pairs": args.pairs, "single_pairs": m, "rounds": args.rounds, "cores": os.cpu_count(),
               "load_after": round(os.getloadavg()[0], 1), "float_wrong": wrong, "float_wrong_single": single_wrong,
               "positions": {name: int((exact_own == k).sum()) for name, k in POSITION.items()}, "paths": []}
    for key, label, n, base, _ in paths:
        s = seconds[key]
        row = {"key": key, "label": label, "seconds_per_pair": statistics.median(s),
               "pairs_per_second": 1 / statistics.median(s)}
        if base:
            ratios = [a / b for a, b in zip(s, seconds[base])]
            row["vs_baseline"] = [statistics.median(ratios), min(ratios), max(ratios)]
        results["paths"].append(row)
        print("%-100s %12.0f pairs/s %s" % (label, row["pairs_per_second"],
              "" if not base else "%.2fx baseline [%.2f-%.2f]" % tuple(row["vs_baseline"])))
    print("positions (own P):", results["positions"], "; float baselines wrong on %d of %d (arrays), %d of %d (single)"
          % (wrong, 2 * args.pairs, single_wrong, m))
    return results


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--pairs", type=int, default=20000)
    ap.add_argument("--single", type=int, default=2000, help="pairs of the one-pair-per-call paths (default 2000)")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--out", help="write the decide results as JSON (benchmarks/tables.py --python)")
    ap.add_argument("--dask-lines", type=int, default=200000, help="lines of the Dask regime file (default 200000)")
    ap.add_argument("--runs", type=int, default=3, help="Dask runs per worker count; the median is kept (default 3)")
    ap.add_argument("--skip-dask", action="store_true")
    ap.add_argument("--skip-decide", action="store_true")
    args = ap.parse_args()

    if not args.skip_decide:
        results = decide_bench(args)
        if args.out:
            results["date"] = time.strftime("%Y-%m-%d")
            with open(args.out, "w") as f:
                json.dump(results, f, indent=1)
    if args.skip_dask:
        return
    dask_bench(args)


def dask_bench(args):
    """relpos.distributed.batch on one regime file (batch_bench.py's generator) with 1 and with 2
    worker processes (one thread each, one library thread per task), against `relpos batch`."""
    import subprocess
    import sys

    import distributed

    import relpos.distributed as relpos_distributed

    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    from batch_bench import write_regime

    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "regime.jsonl")
        write_regime(path, args.dask_lines)
        t = time.perf_counter()
        expected = subprocess.run([relpos._cli.find_cli(), "batch", path, "--threads", "1"], stdout=subprocess.PIPE,
                                  check=True).stdout
        cli_time = time.perf_counter() - t
        print("regime file: %d lines, %.1f MB; relpos batch --threads 1: %.2f s, %.0f MB of answers"
              % (args.dask_lines, os.path.getsize(path) / 1e6, cli_time, len(expected) / 1e6))
        medians = {}
        for workers in (1, 2):
            with distributed.LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                          dashboard_address=None) as cluster, distributed.Client(cluster) as client:
                times = []
                for run in range(args.runs):
                    out = os.path.join(tmp, "out-%d-%d" % (workers, run))
                    t = time.perf_counter()
                    written = relpos_distributed.batch(path, out, client=client, threads=1)
                    times.append(time.perf_counter() - t)
                    with open(written[0], "rb") as f:
                        if f.read() != expected:
                            raise SystemExit("distributed.batch output differs from relpos batch")
                    os.unlink(written[0])
            medians[workers] = statistics.median(times)
            print("distributed.batch, %d worker process(es): median %.2f s of %s; output identical to relpos batch"
                  % (workers, medians[workers], ", ".join("%.2f" % x for x in times)))
        print("speed-up 1 -> 2 workers: %.2fx (load average now %.1f)" % (medians[1] / medians[2], os.getloadavg()[0]))


if __name__ == "__main__":
    main()
