#!/usr/bin/python3
"""Speed of the Python package (doc/python.md): decide_positions on random float64 pairs, and
relpos.distributed.batch on 4 JSON Lines files with 1 and with 2 Dask workers.

    PYTHONPATH=build/python RELPOS_CLI=build/cli/relpos /usr/bin/python3 benchmarks/python_bench.py \
        [--pairs 20000] [--lines 5000] [--skip-dask]
"""

import argparse
import json
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
    return E, P, (x, y, z, r, a, b)


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
    ap.add_argument("--lines", type=int, default=5000)
    ap.add_argument("--skip-dask", action="store_true")
    ap.add_argument("--skip-decide", action="store_true")
    ap.add_argument("--decimals", type=int, default=3,
                    help="digits after the point of the JSON numbers of the Dask files (default 3; 0: repr of the doubles)")
    args = ap.parse_args()

    E, P, params = random_pairs(args.pairs)
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
    import distributed

    import relpos.distributed as relpos_distributed

    x, y, z, r, a, b = params
    num = repr if args.decimals == 0 else (lambda v: "%.*f" % (args.decimals, v))
    r = numpy.maximum(r, 10.0**-args.decimals) if args.decimals else r
    with tempfile.TemporaryDirectory() as tmp:
        paths = []
        for f in range(4):
            path = os.path.join(tmp, "part-%d.jsonl" % f)
            with open(path, "w") as out:
                for i in range(f * args.lines, (f + 1) * args.lines):
                    k = i % args.pairs
                    line = {"id": i, "ellipsoid": {"sphere": {"center": [num(x[k]), num(y[k]), num(z[k])],
                                                              "radius": num(r[k])}},
                            "paraboloid": {"vertex": [0, 0, 0], "a": num(a[k]), "b": num(b[k])}}
                    out.write(json.dumps(line) + "\n")
            paths.append(path)
        timings = {}
        for workers in (1, 2):
            with distributed.LocalCluster(n_workers=workers, threads_per_worker=1, processes=False,
                                          dashboard_address=None) as cluster, distributed.Client(cluster) as client:
                t = time.perf_counter()
                relpos_distributed.batch(paths, os.path.join(tmp, "out-%d" % workers), client=client)
                timings[workers] = time.perf_counter() - t
            print("distributed.batch 4 files x %d lines, %d worker(s): %.2f s" % (args.lines, workers, timings[workers]))
        print("speed-up 1 -> 2 workers: %.2fx" % (timings[1] / timings[2]))


if __name__ == "__main__":
    main()
