#!/usr/bin/python3
"""Lines per second of `relpos batch` against CPython's json.loads on the same file, all measured in
one run (doc/performance.md, "relpos batch lines per second").

    /usr/bin/python3 benchmarks/batch_bench.py --cli build/cli/relpos [--lines 20000] [--repeat 3]
        [--threads 2] [--form sphere|matrix|both] [--out FILE.json]

The file is the paper's regime written as a user's float code would: small spheres near the cup of
axis-aligned paraboloids, every number printed with %.17g (decimal text that is not a dyadic, read
exactly by the default `--numbers exact`); by default one file of each form is measured in the same
run. Each round runs every command once, json.loads included, so that each ratio can also be taken
within a round; printed per command: the best wall time, its ratio to the best json.loads time, and
the median and range of the per-round ratios. The baseline is a separate /usr/bin/python3 process
that reads the file and calls json.loads on every line (interpreter start-up included, as for
relpos). relpos runs with one thread and with --threads (2 by default). The positions of every run
must agree line by line, and the full-evidence certificates are checked with `relpos verify`.
"""

import argparse
import json
import os
import random
import statistics
import subprocess
import sys
import tempfile
import time


def write_regime(path, lines, seed=12, form="sphere"):
    """form "sphere": sphere and standard paraboloid (6 numbers a line); "matrix": the same bodies
    as two 4x4 matrices of doubles (32 numbers a line, what a float pipeline holds); "user": a sphere
    and a standard paraboloid placed as a user's are (write_user_regime)."""
    if form == "user":
        return write_user_regime(path, lines, seed)
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


def write_user_regime(path, lines, seed=12):
    """Spheres and standard paraboloids as a user's float code places them (regime::user_pair of
    benchmarks/ordinary/regime_matrices.hpp, written as text): the vertex anywhere in [-2, 2]^3, a, b
    in [0.5, 2], the radius 0.02 to 0.3 min(a, b)^2, the centre within 0.5 a, 0.5 b of the axis at
    -2.4 to 5 radii above the surface, every number printed with %.17g."""
    rng = random.Random(seed)
    f = lambda v: "%.17g" % v
    with open(path, "w") as out:
        for i in range(lines):
            v = [rng.uniform(-2, 2) for _ in range(3)]
            a, b = rng.uniform(0.5, 2), rng.uniform(0.5, 2)
            r = rng.uniform(0.02, 0.3) * min(a, b) ** 2
            x, y = rng.uniform(-0.5, 0.5) * a, rng.uniform(-0.5, 0.5) * b
            c = [v[0] + x, v[1] + y, v[2] + x * x / (a * a) + y * y / (b * b) + rng.uniform(-2.4, 5) * r]
            out.write('{"id":%d,"ellipsoid":{"sphere":{"center":[%s,%s,%s],"radius":%s}},'
                      '"paraboloid":{"vertex":[%s,%s,%s],"a":%s,"b":%s}}\n'
                      % (i, f(c[0]), f(c[1]), f(c[2]), f(r), f(v[0]), f(v[1]), f(v[2]), f(a), f(b)))


def run_time(cmd, out_path):
    with open(out_path, "wb") as out:
        t = time.perf_counter()
        subprocess.run(cmd, stdout=out, check=True)
        return time.perf_counter() - t


def positions(path):
    with open(path) as f:
        return [(d["id"], d["position"]) for d in map(json.loads, f)]


def measure(cli, data, repeat, threads):
    """Times json.loads and the relpos commands on one file, interleaved round by round; checks the
    positions and the certificates. Returns the form's entry of the JSON output."""
    lines = sum(1 for _ in open(data))
    loads = [sys.executable, "-c", "import json,sys\nfor l in open(sys.argv[1]): json.loads(l)", data]
    batch = lambda evidence, t: [cli, "batch", "--evidence", evidence, "--threads", str(t), data]  # noqa: E731
    runs = [
        ("loads", "json.loads (CPython, one process)", loads),
        ("minimal1", "relpos batch --evidence minimal --threads 1", batch("minimal", 1)),
        ("minimal", f"relpos batch --evidence minimal --threads {threads}", batch("minimal", threads)),
        ("full1", "relpos batch --evidence full --threads 1", batch("full", 1)),
        ("full", f"relpos batch --evidence full --threads {threads}", batch("full", threads)),
    ]
    outs = {tag: data + "." + tag + ".out" for tag, _, _ in runs}
    times = {tag: [] for tag, _, _ in runs}
    for _ in range(repeat):  # one round runs every command once: ratios are taken within a round
        for tag, _, cmd in runs:
            times[tag].append(run_time(cmd, outs[tag]))
    # Every run gives the same positions, in input order; every certificate verifies.
    reference = positions(outs["minimal1"])
    assert len(reference) == lines and [i for i, _ in reference] == list(range(lines)), "ids out of order"
    for tag, name, _ in runs[2:]:
        assert positions(outs[tag]) == reference, f"{name}: positions differ from the minimal run"
    verify = subprocess.run([cli, "verify", data, outs["full"]], stdout=subprocess.PIPE, text=True)
    verified = verify.stdout.strip().splitlines()[-1] if verify.stdout else ""
    if verify.returncode != 0:
        sys.exit("relpos verify failed: " + verified)
    commands = []
    for tag, name, _ in runs:
        ratio = sorted(a / b for a, b in zip(times["loads"], times[tag]))
        commands.append({
            "tag": tag, "command": name, "best_s": min(times[tag]),
            "ratio_best": min(times["loads"]) / min(times[tag]),
            "ratio_median": statistics.median(ratio), "ratio_lo": ratio[0], "ratio_hi": ratio[-1],
        })
    mix = {p: sum(1 for _, q in reference if q == p) for p in ("I", "TI", "C", "TE", "E")}
    return {"lines": lines, "commands": commands, "positions": mix, "verify": verified}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cli", default="build/cli/relpos")
    ap.add_argument("--lines", type=int, default=20000)
    ap.add_argument("--repeat", type=int, default=3, help="rounds; each runs every command once")
    ap.add_argument("--threads", type=int, default=2, help="threads of the multi-threaded runs")
    ap.add_argument("--file", help="use this JSON Lines file instead of writing the regime files")
    ap.add_argument("--form", choices=("sphere", "matrix", "both", "user", "all"), default="both",
                    help="how the regime file writes the bodies (both: sphere and matrix, in one run; user: "
                    "spheres and paraboloids placed as a user's are; all: the three)")
    ap.add_argument("--out", help="write the figures as JSON to this file")
    args = ap.parse_args()

    load = lambda: " ".join(f"{x:.2f}" for x in os.getloadavg())  # noqa: E731
    result = {"threads": args.threads, "cores": os.cpu_count(), "rounds": args.repeat, "load_before": load(),
              "forms": {}}
    with tempfile.TemporaryDirectory() as tmp:
        forms = ["file"] if args.file else {"both": ["sphere", "matrix"], "all": ["sphere", "matrix", "user"]}.get(
            args.form, [args.form])
        for form in forms:
            data = args.file or os.path.join(tmp, form + ".jsonl")
            if not args.file:
                write_regime(data, args.lines, form=form)
            r = measure(args.cli, data, args.repeat, args.threads)
            result["forms"][form] = r
            print(f"{form} file: {r['lines']} lines, {os.cpu_count()} cores, {args.repeat} rounds; "
                  "ratio = json.loads time / command time (best of the rounds; median of the per-round ratios [range])")
            print(f"{'command':48} {'best s':>8} {'lines/s':>10} {'vs json.loads':>14} {'per round':>20}")
            for c in r["commands"]:
                per_round = f"{c['ratio_median']:.2f} [{c['ratio_lo']:.2f}-{c['ratio_hi']:.2f}]"
                print(f"{c['command']:48} {c['best_s']:8.3f} {r['lines'] / c['best_s']:10.0f} "
                      f"{c['ratio_best']:13.2f}x {per_round:>20}")
            print("relpos verify (full evidence):", r["verify"])
            print("positions: identical in every run (" + ", ".join(f"{p} {n}" for p, n in r["positions"].items()) + ")")
    result["load_after"] = load()
    if args.out:
        with open(args.out, "w") as f:
            json.dump(result, f, indent=1)


if __name__ == "__main__":
    main()
