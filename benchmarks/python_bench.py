#!/usr/bin/python3
"""Speed of the Python package (doc/python.md): decide_positions on random float64 pairs, and
relpos.distributed.batch on one file of the paper's regime (benchmarks/batch_bench.py) with 1 and with
2 Dask worker processes.

    PYTHONPATH=build/python RELPOS_CLI=build/cli/relpos /usr/bin/python3 benchmarks/python_bench.py \
        [--pairs 20000] [--dask-lines 200000] [--runs 3] [--skip-dask] [--skip-decide]
"""

import argparse
import os
import tempfile
import time

import numpy

import relpos


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


def best_of(k, f):
    times = []
    for _ in range(k):
        t = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - t)
    return min(times), out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--pairs", type=int, default=20000)
    ap.add_argument("--dask-lines", type=int, default=200000, help="lines of the Dask regime file (default 200000)")
    ap.add_argument("--runs", type=int, default=3, help="Dask runs per worker count; the median is kept (default 3)")
    ap.add_argument("--skip-dask", action="store_true")
    ap.add_argument("--skip-decide", action="store_true")
    args = ap.parse_args()

    E, P = random_pairs(args.pairs)
    shared = P[0]
    for label, p in () if args.skip_decide else (("own P per pair", P), ("one shared P", shared)):
        for threads in (1, 2):
            t, codes = best_of(3, lambda: relpos.decide_positions(E, p, threads=threads))
            print("decide_positions %d pairs, %s, threads=%d: %.3f s = %.0f pairs/s"
                  % (args.pairs, label, threads, t, args.pairs / t))
    if not args.skip_decide:
        counts = {n: int((codes == k).sum()) for k, n in enumerate(relpos.POSITION_NAMES)}
        print("positions (shared P):", counts)

    if args.skip_dask:
        return
    dask_bench(args)


def dask_bench(args):
    """relpos.distributed.batch on one regime file (batch_bench.py's generator) with 1 and with 2
    worker processes (one thread each, one library thread per task), against `relpos batch`."""
    import statistics
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
