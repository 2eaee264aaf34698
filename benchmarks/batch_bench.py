#!/usr/bin/python3
"""Lines per second of `relpos batch` against CPython's json.loads on the same file, all measured in
one run (doc/performance.md, "relpos batch lines per second").

    /usr/bin/python3 benchmarks/batch_bench.py --cli build/cli/relpos [--lines 20000] [--repeat 3]

The file is the paper's regime written as a user's float code would: small spheres near the cup of
axis-aligned paraboloids, every number printed with %.17g (decimal text that is not a dyadic, read
exactly by the default `--numbers exact`). Each command runs --repeat times; the best wall time is
kept. The baseline is a separate /usr/bin/python3 process that reads the file and calls json.loads
on every line (interpreter start-up included, as for relpos). The positions of every run must agree
line by line, and the full-evidence certificates are checked with `relpos verify`.
"""

import argparse
import json
import os
import random
import subprocess
import sys
import tempfile
import time


def write_regime(path, lines, seed=12, form="sphere"):
    """form "sphere": sphere and standard paraboloid (6 numbers a line); "matrix": the same bodies
    as two 4x4 matrices of doubles (32 numbers a line, what a float pipeline holds)."""
    rng = random.Random(seed)
    f = lambda v: "%.17g" % v
    with open(path, "w") as out:
        for i in range(lines):
            a, b = rng.uniform(0.8, 2.0), rng.uniform(0.8, 2.0)
            r = rng.uniform(0.01, 0.2)
            x, y = rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3)
            z = x * x / a / a + y * y / b / b + rng.uniform(-0.4, 0.6)
            if form == "sphere":
                out.write(
                    '{"id":%d,"ellipsoid":{"sphere":{"center":[%s,%s,%s],"radius":%s}},'
                    '"paraboloid":{"vertex":[0,0,0],"a":%s,"b":%s}}\n' % (i, f(x), f(y), f(z), f(r), f(a), f(b))
                )
                continue
            e = [[1, 0, 0, -x], [0, 1, 0, -y], [0, 0, 1, -z], [-x, -y, -z, x * x + y * y + z * z - r * r]]
            p = [[1 / a / a, 0, 0, 0], [0, 1 / b / b, 0, 0], [0, 0, 0, -0.5], [0, 0, -0.5, 0]]
            m = lambda q: "[" + ",".join("[" + ",".join(f(v) for v in row) + "]" for row in q) + "]"
            out.write('{"id":%d,"ellipsoid":{"matrix":%s},"paraboloid":{"matrix":%s}}\n' % (i, m(e), m(p)))


def best_time(cmd, repeat, out_path):
    best = None
    for _ in range(repeat):
        with open(out_path, "wb") as out:
            t = time.perf_counter()
            subprocess.run(cmd, stdout=out, check=True)
            dt = time.perf_counter() - t
        best = dt if best is None else min(best, dt)
    return best


def positions(path):
    with open(path) as f:
        return [(d["id"], d["position"]) for d in map(json.loads, f)]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cli", default="build/cli/relpos")
    ap.add_argument("--lines", type=int, default=20000)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--file", help="use this JSON Lines file instead of writing the regime file")
    ap.add_argument("--form", choices=("sphere", "matrix"), default="sphere", help="how the regime file writes the bodies")
    args = ap.parse_args()

    with tempfile.TemporaryDirectory() as tmp:
        data = args.file or os.path.join(tmp, "regime.jsonl")
        if not args.file:
            write_regime(data, args.lines, form=args.form)
        lines = sum(1 for _ in open(data))
        loads = [sys.executable, "-c", "import json,sys\nfor l in open(sys.argv[1]): json.loads(l)", data]
        runs = [
            ("json.loads (CPython, one process)", loads, None),
            ("relpos batch --evidence minimal --threads 1", [args.cli, "batch", "--evidence", "minimal", "--threads", "1", data], "min1"),
            ("relpos batch --evidence minimal (all cores)", [args.cli, "batch", "--evidence", "minimal", data], "min"),
            ("relpos batch --evidence full --threads 1", [args.cli, "batch", "--evidence", "full", "--threads", "1", data], "full1"),
            ("relpos batch --evidence full (all cores)", [args.cli, "batch", "--evidence", "full", data], "full"),
        ]
        results = []
        for name, cmd, tag in runs:
            out = os.path.join(tmp, (tag or "loads") + ".out")
            results.append((name, best_time(cmd, args.repeat, out), tag and out))
        base = results[0][1]
        print(f"{lines} lines, {os.cpu_count()} cores, best of {args.repeat}")
        print(f"{'command':48} {'seconds':>8} {'lines/s':>10} {'vs json.loads':>14}")
        for name, t, _ in results:
            print(f"{name:48} {t:8.3f} {lines / t:10.0f} {base / t:13.2f}x")
        # Every run gives the same positions, in input order; every certificate verifies.
        reference = positions(results[1][2])
        assert len(reference) == lines and [i for i, _ in reference] == list(range(lines)), "ids out of order"
        for name, _, out in results[2:]:
            assert positions(out) == reference, f"{name}: positions differ from the minimal run"
        verify = subprocess.run([args.cli, "verify", data, results[-1][2]], stdout=subprocess.PIPE, text=True)
        print("relpos verify (full evidence):", verify.stdout.strip().splitlines()[-1] if verify.stdout else "")
        if verify.returncode != 0:
            sys.exit("relpos verify failed")
        print("positions: identical in every run (" + ", ".join(
            f"{p} {sum(1 for _, q in reference if q == p)}" for p in ("I", "TI", "C", "TE", "E")) + ")")


if __name__ == "__main__":
    main()
