#!/usr/bin/env python3
"""`relpos classify --margin`, `relpos batch --margin` and `relpos verify` on margins (doc/cli.md,
doc/certificates.md "Margins"), with Python's exact fractions and nothing of relpos.

Spheres whose s* = (distance from the centre to the paraboloid) / r is known in closed form:
  - z = x^2 + y^2, centre (x0 + t u, y0 + t v, z0 - t) with (u, v, -1) = (2 x0, 2 y0, -1) the outward
    normal at the surface point (x0, y0, z0): for t > 0 the distance is t |n|, so s*^2 = t^2 |n|^2 / r^2
    (rational s* when |n| is rational, e.g. at (1, 1, 2), |n| = 3);
  - on the axis, centre (0, 0, h): s*^2 = (h - 1/4) / r^2 for h >= 1/2 (the circle), h^2 / r^2 below.
Every answer's enclosure must hold s* (exactly, through squares), its approximation agree to 1e-9 and
its polynomial vanish at s*; `relpos verify` must accept them all, and reject forged ones line by line.

Usage: check_margin.py PATH/TO/relpos
"""
import json
import os
import subprocess
import sys
import tempfile
from fractions import Fraction as F

relpos = sys.argv[1]
failures = []


def check(what, ok, detail=""):
    if not ok:
        failures.append("%s %s" % (what, detail))


def run(args, stdin=None):
    return subprocess.run([relpos] + args, input=stdin, stdout=subprocess.PIPE, stderr=subprocess.PIPE)


def s2_of(centre, r):
    """s*^2 of a sphere against z = x^2 + y^2 for the constructions above."""
    x, y, z = centre
    if x == 0 and y == 0:
        return (z - F(1, 4)) / (r * r) if z >= F(1, 2) else z * z / (r * r)
    raise ValueError


cases = []  # (centre, r, s*^2)
for (x0, y0), t, r in [((1, 1), F(1, 3), F(1, 2)), ((1, 0), F(1, 2), F(1, 3)), ((F(1, 2), F(-3, 2)), F(2), F(5, 7)),
                       ((0, 2), F(1, 7), F(3)), ((F(-1, 3), F(1, 4)), F(3, 5), F(1, 9))]:
    z0 = x0 * x0 + y0 * y0
    n = (2 * x0, 2 * y0, -1)
    centre = (x0 + t * n[0], y0 + t * n[1], z0 + t * n[2])
    cases.append((centre, r, t * t * sum(c * c for c in n) / (r * r)))
for h, r in [(F(1), F(1)), (F(1), F(1, 2)), (F(3), F(2)), (F(1, 4), F(1, 8)), (F(1, 3), F(1, 2)), (F(-1), F(3, 2))]:
    cases.append(((F(0), F(0), h), r, s2_of((0, 0, h), r)))


def text(q):
    return str(q.numerator) if q.denominator == 1 else "%d/%d" % (q.numerator, q.denominator)


lines = []
for i, (c, r, _) in enumerate(cases):
    lines.append(json.dumps({"id": i, "ellipsoid": {"sphere": {"center": [text(x) for x in c], "radius": text(r)}},
                             "paraboloid": {"vertex": [0, 0, 0], "a": 1, "b": 1}}))
work = tempfile.mkdtemp()
inp = os.path.join(work, "in.jsonl")
with open(inp, "w") as f:
    f.write("\n".join(lines) + "\n")

out = run(["batch", inp, "--margin"])
check("batch --margin exits 0", out.returncode == 0, out.stderr)
answers = [json.loads(line) for line in out.stdout.decode().splitlines()]
check("one answer per line", len(answers) == len(cases))
plain = [json.loads(line) for line in run(["batch", inp]).stdout.decode().splitlines()]


def poly_value(coefficients, x):
    return sum(F(int(c)) * x ** k for k, c in enumerate(coefficients))


for (c, r, s2), a, p in zip(cases, answers, plain):
    m = a.get("margin")
    check("line %s has a margin" % a["id"], m is not None)
    if m is None:
        continue
    check("line %s: the other members as without --margin" % a["id"], {k: v for k, v in a.items() if k != "margin"} == p)
    check("line %s: margin is the last member" % a["id"], list(a)[-1] == "margin")
    lo, hi = F(m["lo"]), F(m["hi"])
    check("line %s: 0 < lo <= hi" % a["id"], 0 < lo <= hi, m)
    check("line %s: lo^2 <= s*^2 <= hi^2" % a["id"], lo * lo <= s2 <= hi * hi, (m, s2))
    s = float(s2) ** 0.5
    check("line %s: approx within 1e-9" % a["id"], abs(m["approx"] - s) <= 1e-9 * s, (m["approx"], s))
    check("line %s: width 2^-40" % a["id"], (hi - lo) * 2 ** 40 <= lo, m)
    if lo == hi:
        check("line %s: rational s* = lo" % a["id"], lo * lo == s2 and poly_value(m["polynomial"], lo) == 0, m)
        check("line %s: one certificate, at" % a["id"], "at" in m and "below" not in m and "above" not in m, m)
    else:
        # The polynomial changes sign on [lo, hi], and divides den t^2 - num (s*^2 = num / den).
        check("line %s: sign change" % a["id"], poly_value(m["polynomial"], lo) * poly_value(m["polynomial"], hi) < 0, m)
        check("line %s: below and above" % a["id"], "below" in m and "above" in m and "at" not in m, m)
        check("line %s: the minimal polynomial of sqrt(s*^2)" % a["id"],
              [int(x) for x in m["polynomial"]] == [-s2.numerator, 0, s2.denominator], (m["polynomial"], s2))

answers_file = os.path.join(work, "answers.jsonl")
with open(answers_file, "wb") as f:
    f.write(out.stdout)
v = run(["verify", inp, answers_file])
check("verify accepts every margin", v.returncode == 0 and v.stdout.decode().strip().endswith(
    "verified %d, failed 0, skipped 0" % len(cases)), v.stdout)

# Forged margins: each line changed in one way, each must fail (and only those lines).
forged = []
bad_lines = set()
for k, a in enumerate(answers):
    m = dict(a["margin"])
    lo, hi = F(m["lo"]), F(m["hi"])
    kind = k % 6
    if lo == hi:
        m["lo"] = m["hi"] = text(lo + F(1, 1000))  # the rational value moved
        m["approx"] = float(lo + F(1, 1000))
    elif kind == 0:
        m["lo"], m["hi"] = text(hi + (hi - lo)), text(hi + 2 * (hi - lo))  # enclosure moved above s*
    elif kind == 1:
        m["polynomial"] = [m["polynomial"][0]] + ["1"] + m["polynomial"][2:]  # polynomial changed
    elif kind == 2:
        m["below"], m["above"] = m["above"], m["below"]  # certificates swapped
    elif kind == 3:
        m["approx"] = float(hi) * (1 + 1e-9)  # approximation outside
    elif kind == 4:
        m["below"] = {"lambda": text(-F(m["below"]["lambda"]))}  # multiplier tampered
    else:
        m["lo"], m["hi"] = text(lo - 2 * (hi - lo)), text(lo - (hi - lo))  # enclosure moved below s*
    bad_lines.add(k + 1)
    forged.append(json.dumps(dict(a, margin=m)))
forged_file = os.path.join(work, "forged.jsonl")
with open(forged_file, "w") as f:
    f.write("\n".join(forged) + "\n")
v = run(["verify", inp, forged_file])
reported = {int(line.split(":")[0].split()[1]) for line in v.stdout.decode().splitlines() if line.startswith("line ")}
check("verify rejects every forged margin", v.returncode == 1 and reported == bad_lines, (reported, bad_lines))
check("verify names the margin", all("margin" in line for line in v.stdout.decode().splitlines() if line.startswith("line ")),
      v.stdout)

# classify --margin: the same member; the report's lines; minimal and contact-only answers too.
c, r, s2 = cases[0]
args = ["classify", "--sphere", ",".join(text(x) for x in list(c) + [r]), "--standard-paraboloid", "1,1"]
j = json.loads(run(args + ["--margin", "--json"]).stdout)
check("classify --margin --json equals the batch member", j["margin"] == answers[0]["margin"], j)
report = run(args + ["--margin"]).stdout.decode()
check("the report has the margin", "margin:" in report and "minimal polynomial" in report, report)
j = json.loads(run(args + ["--margin-bits", "80", "--json"]).stdout)
check("--margin-bits 80: width 2^-80", (F(j["margin"]["hi"]) - F(j["margin"]["lo"])) * 2 ** 80 <= F(j["margin"]["lo"]), j)
for extra in (["--evidence", "minimal"], ["--contact-only"]):
    lines_out = run(["batch", inp, "--margin"] + extra).stdout.decode().splitlines()
    check("batch --margin %s: every line has it" % " ".join(extra),
          all(json.loads(line)["margin"] == a["margin"] for line, a in zip(lines_out, answers)))
for bad in (["--margin-bits", "0"], ["--margin-bits", "1001"], ["--margin-bits", "x"]):
    p = run(args + bad)
    check("classify %s: usage error" % " ".join(bad), p.returncode == 2, p.returncode)

# s* beyond the double range: the sphere of radius 1 centred 2^1025 below the vertex (s* = 2^1025,
# the vertex nearest) has approx null (+infinity), and verify accepts it.
big = os.path.join(work, "big.jsonl")
with open(big, "w") as f:
    f.write(json.dumps({"id": "big", "ellipsoid": {"sphere": {"center": [0, 0, str(-2**1025)], "radius": 1}},
                        "paraboloid": {"vertex": [0, 0, 0], "a": 1, "b": 1}}) + "\n")
out = run(["batch", big, "--margin"])
m = json.loads(out.stdout)["margin"]
check("s* = 2^1025: approx null, lo = hi = s*", m["approx"] is None and F(m["lo"]) == F(m["hi"]) == 2**1025, m)
big_answers = os.path.join(work, "big-answers.jsonl")
with open(big_answers, "wb") as f:
    f.write(out.stdout)
v = run(["verify", big, big_answers])
check("verify accepts approx null", v.returncode == 0, v.stdout)

if failures:
    print("check_margin: %d failures" % len(failures))
    for f in failures:
        print("  " + f)
    sys.exit(1)
print("check_margin: %d pairs, every margin checked and verified, forged ones rejected" % len(cases))
