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
import fractions
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


def user_placement(rng):
    """One pair of write_user_regime, drawn: the vertex v, a, b, the radius r, the centre's x, y in the
    paraboloid's frame (vertex at the origin, axis z) and its height above the surface in radii, t."""
    v = [rng.uniform(-2, 2) for _ in range(3)]
    a, b = rng.uniform(0.5, 2), rng.uniform(0.5, 2)
    r = rng.uniform(0.02, 0.3) * min(a, b) ** 2
    x, y = rng.uniform(-0.5, 0.5) * a, rng.uniform(-0.5, 0.5) * b
    return v, a, b, r, x, y, rng.uniform(-2.4, 5)


def write_user_regime(path, lines, seed=12):
    """Spheres and standard paraboloids as a user's float code places them (regime::user_pair of
    benchmarks/ordinary/regime_matrices.hpp, written as text): the vertex anywhere in [-2, 2]^3, a, b
    in [0.5, 2], the radius 0.02 to 0.3 min(a, b)^2, the centre within 0.5 a, 0.5 b of the axis at
    -2.4 to 5 radii above the surface, every number printed with %.17g."""
    rng = random.Random(seed)
    f = lambda v: "%.17g" % v
    with open(path, "w") as out:
        for i in range(lines):
            v, a, b, r, x, y, t = user_placement(rng)
            c = [v[0] + x, v[1] + y, v[2] + x * x / (a * a) + y * y / (b * b) + t * r]
            out.write('{"id":%d,"ellipsoid":{"sphere":{"center":[%s,%s,%s],"radius":%s}},'
                      '"paraboloid":{"vertex":[%s,%s,%s],"a":%s,"b":%s}}\n'
                      % (i, f(c[0]), f(c[1]), f(c[2]), f(r), f(v[0]), f(v[1]), f(v[2]), f(a), f(b)))


def write_off_axis(path, lines, seed=21):
    """Paraboloids off the z axis, a line of each kind in turn: a standard paraboloid whose vertex is
    off the axis (write_user_regime's pairs), the same turned by a small integer quaternion
    ("rotation"), and the turned one as a matrix of %.17g numbers (det Q3 = 0 shown by no zero
    entry: the general reader's) with exact "p/q" entries; the sphere near the surface as in write_user_regime."""
    rng = random.Random(seed)
    f = lambda v: "%.17g" % v
    with open(path, "w") as out:
        for i in range(lines):
            v, a, b, r, x, y, t = user_placement(rng)
            u = [x, y, x * x / (a * a) + y * y / (b * b) + t * r]  # in the body's frame
            q = [rng.randint(-3, 3) for _ in range(4)]
            if not any(q) or i % 3 == 0:
                q = [1, 0, 0, 0]
            w, qx, qy, qz = q
            n = w * w + qx * qx + qy * qy + qz * qz
            rot = [[(w * w + qx * qx - qy * qy - qz * qz) / n, 2 * (qx * qy - w * qz) / n, 2 * (qx * qz + w * qy) / n],
                   [2 * (qx * qy + w * qz) / n, (w * w - qx * qx + qy * qy - qz * qz) / n, 2 * (qy * qz - w * qx) / n],
                   [2 * (qx * qz - w * qy) / n, 2 * (qy * qz + w * qx) / n, (w * w - qx * qx - qy * qy + qz * qz) / n]]
            c = [v[k] + sum(rot[k][j] * u[j] for j in range(3)) for k in range(3)]
            sphere = '{"sphere":{"center":[%s,%s,%s],"radius":%s}}' % (f(c[0]), f(c[1]), f(c[2]), f(r))
            if i % 3 != 2:
                rotation = "" if i % 3 == 0 else ',"rotation":[%d,%d,%d,%d]' % tuple(q)
                cup = '{"vertex":[%s,%s,%s],"a":%s,"b":%s%s}' % (f(v[0]), f(v[1]), f(v[2]), f(a), f(b), rotation)
            else:
                # The turned paraboloid's exact matrix, as "p/q" strings (its doubles would not be a
                # paraboloid): Q = R diag(1/a^2, 1/b^2, 0) R^T about v, the linear part along R's third column.
                F = fractions.Fraction
                R = [[F(2 * t) / n if k != l else F(t) / n for l, t in enumerate(row)] for k, row in enumerate(
                    [[w * w + qx * qx - qy * qy - qz * qz, qx * qy - w * qz, qx * qz + w * qy],
                     [qx * qy + w * qz, w * w - qx * qx + qy * qy - qz * qz, qy * qz - w * qx],
                     [qx * qz - w * qy, qy * qz + w * qx, w * w - qx * qx - qy * qy + qz * qz]])]
                d = [1 / F(a) ** 2, 1 / F(b) ** 2, F(0)]
                V = [F(t) for t in v]
                A = [[sum(R[k][j] * d[j] * R[l][j] for j in range(3)) for l in range(3)] for k in range(3)]
                g = [R[k][2] for k in range(3)]
                bl = [-sum(A[k][l] * V[l] for l in range(3)) - g[k] / 2 for k in range(3)]
                c0 = sum(V[k] * A[k][l] * V[l] for k in range(3) for l in range(3)) + sum(g[k] * V[k] for k in range(3))
                m = [A[0] + [bl[0]], A[1] + [bl[1]], A[2] + [bl[2]], bl + [c0]]
                cup = "[" + ",".join("[" + ",".join('"%s"' % m[k][l] for l in range(4)) + "]" for k in range(4)) + "]"
            out.write('{"id":%d,"ellipsoid":%s,"paraboloid":%s}\n' % (i, sphere, cup))


def write_scaled(path, lines, kind="quadric", shift=0, seed=36):
    """Random ordinary pairs as matrices of decimals with 12 significant digits: an ellipsoid (semi-axes
    in [0.2, 2], a random rotation, the centre in [-2, 2]^3) against another ("quadric") or against an
    axis-aligned paraboloid ("paraboloid"), the ellipsoid's exponents moved by +shift and the second
    body's by -shift (shift 300: the pair scaled by 10^300 and 10^-300, the same mantissas)."""
    rng = random.Random(seed)

    def rotation():
        q = [rng.gauss(0, 1) for _ in range(4)]
        n = sum(t * t for t in q) ** 0.5
        w, x, y, z = [t / n for t in q]
        return [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]

    def ellipsoid():
        R, ax = rotation(), [rng.uniform(0.2, 2) for _ in range(3)]
        c = [rng.uniform(-2, 2) for _ in range(3)]
        A = [[sum(R[i][k] * R[j][k] / ax[k] ** 2 for k in range(3)) for j in range(3)] for i in range(3)]
        b = [-sum(A[i][j] * c[j] for j in range(3)) for i in range(3)]
        c0 = sum(c[i] * A[i][j] * c[j] for i in range(3) for j in range(3)) - 1
        return [A[0] + [b[0]], A[1] + [b[1]], A[2] + [b[2]], b + [c0]]

    def paraboloid():
        a, b = rng.uniform(0.3, 2), rng.uniform(0.3, 2)
        v = [rng.uniform(-2, 2) for _ in range(3)]
        ia, ib = 1 / a / a, 1 / b / b
        return [[ia, 0, 0, -ia * v[0]], [0, ib, 0, -ib * v[1]], [0, 0, 0, -0.5],
                [-ia * v[0], -ib * v[1], -0.5, ia * v[0] ** 2 + ib * v[1] ** 2 + v[2]]]

    def text(m, k):
        def number(v):
            if v == 0:
                return "0"
            mantissa, e = ("%.11e" % v).split("e")
            return "%se%d" % (mantissa, int(e) + k)
        return "[" + ",".join("[" + ",".join(number(m[min(i, j)][max(i, j)]) for j in range(4)) + "]"
                              for i in range(4)) + "]"

    with open(path, "w") as out:
        for i in range(lines):
            e = ellipsoid()
            q = ellipsoid() if kind == "quadric" else paraboloid()
            out.write('{"id":%d,"ellipsoid":%s,"%s":%s}\n' % (i, text(e, shift), kind, text(q, -shift)))


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
