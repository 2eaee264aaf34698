#!/usr/bin/env python3
"""`relpos cases`, `relpos judge`, "meta" and "numbers" end to end (doc/oracle.md).

  - every case of every family, in each form, through `relpos batch` (exact numbers for the exact
    form, --numbers double for the doubles and the matrices): each answer's position is the line's
    truth of that reading (meta.position, double_position, matrix_position; a refused matrix is the
    error meta.matrix_error names), meta is echoed byte for byte, every double-mode answer says
    "numbers": "double", and `relpos verify` verifies every full answer;
  - the issue's line verifies in double mode;
  - `relpos judge` against an independent count in plain Python, on answer files with wrong,
    undecided, missing, duplicate, malformed and unknown answers, grouped two ways; its CSV and
    Markdown totals, --tolerance on hand-written sphere lines, --plot, the adapter of examples/oracle;
  - `relpos scene` echoes meta.

Usage: check_oracle.py RELPOS_CLI SOURCE_DIR
"""
import json
import os
import random
import re
import subprocess
import sys
import tempfile

CLI, SOURCE = sys.argv[1], sys.argv[2]
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def run(args, stdin=None, code=0):
    p = subprocess.run([CLI] + args, input=stdin, capture_output=True, text=True)
    check(p.returncode == code, "%s: exit %d, not %d (%s)" % (" ".join(args[:3]), p.returncode, code, p.stderr[-300:]))
    return p.stdout


def meta_text(line):
    """The raw text of the line's "meta" member (the last member of every line written here)."""
    at = line.index('"meta":')
    return line[at + len('"meta":'):line.rindex("}")]


tmp = tempfile.mkdtemp()
path = lambda name: os.path.join(tmp, name)  # noqa: E731

# ------------------------------------------------------------------------------------------------
# Cases through batch and verify, in three forms.
SPEC = ["all", "--n", "4", "--eps", "1e-3,1e-11,0", "--seed", "5"]
forms = {"exact": ([], "position"), "double": (["--numbers", "double"], "double_position"),
         "matrix": (["--numbers", "double"], "matrix_position")}
for form, (batch_args, truth) in forms.items():
    text = run(["cases"] + SPEC + ["--form", form])
    open(path(form + ".jsonl"), "w").write(text)
    lines = text.splitlines()
    check(len(lines) == 9 * 3 * 4 + 2 * 4, "cases: %d lines" % len(lines))
    for mode in (["--evidence", "full"], ["--evidence", "minimal"], ["--contact-only"]):
        out = run(["batch", path(form + ".jsonl"), "--threads", "2"] + batch_args + mode)
        open(path(form + ".out"), "w").write(out)
        answers = out.splitlines()
        check(len(answers) == len(lines), "%s %s: one answer per line" % (form, mode))
        for line, answer in zip(lines, answers):
            case, a = json.loads(line), json.loads(answer)
            m = case["meta"]
            check(meta_text(answer) == meta_text(line), "%s: meta not echoed byte for byte" % case["id"])
            check(("numbers" in a) == bool(batch_args) and a.get("numbers", "double") == "double",
                  "%s: numbers member %r" % (case["id"], a.get("numbers")))
            if m[truth] is None:
                check(a.get("error") and a["error"].startswith(m["matrix_error"]),
                      "%s: expected the error %r, got %r" % (case["id"], m.get("matrix_error"), answer[:200]))
            else:
                check(a.get("position") == m[truth], "%s %s: %s, not %s" % (case["id"], form, a.get("position"), m[truth]))
        if mode == ["--evidence", "full"]:  # (minimal and contact-only answers carry no certificate)
            v = subprocess.run([CLI, "verify", path(form + ".jsonl"), path(form + ".out")], capture_output=True,
                               text=True)
            check(v.returncode == 0 and "failed 0" in v.stdout,
                  "verify %s %s: %s" % (form, mode, v.stdout[-400:] + v.stderr[-200:]))
    # The exact form's truth is the construction (random: relpos's, checked by its certificate above).
    if form == "exact":
        check(all(json.loads(x)["meta"]["by"] in ("construction", "relpos") for x in lines), "meta.by")

# The issue's line: TI for the doubles, and the answer verifies (it records its number mode).
issue = ('{"id":"t","ellipsoid":{"sphere":{"center":[0,0,0.25000000000000000000025],"radius":0.25}},'
         '"paraboloid":{"vertex":[0,0,0],"a":1,"b":1}}\n')
open(path("issue.jsonl"), "w").write(issue)
out = run(["batch", path("issue.jsonl"), "--numbers", "double"])
check(json.loads(out)["position"] == "TI" and json.loads(out)["numbers"] == "double", "issue line: " + out)
open(path("issue.out"), "w").write(out)
check("verified 1, failed 0" in run(["verify", path("issue.jsonl"), path("issue.out")]), "issue line verifies")
stripped = out.replace(',"numbers":"double"', "")
open(path("issue-bare.out"), "w").write(stripped)
run(["verify", path("issue.jsonl"), path("issue-bare.out")], code=1)  # read exactly: the contact is off
check("verified 1" in run(["verify", path("issue.jsonl"), path("issue-bare.out"), "--numbers", "double"]),
      "verify --numbers double")

# Scene: meta echoed.
scene_line = '{"id":"b","meta":{"k": [1, 2.50]},"ellipsoid":{"sphere":{"center":[0,0,1],"radius":0.25}}}\n'
out = run(["scene", "--standard-paraboloid", "1,1", "--no-progress", "-"], stdin=scene_line)
check(out.strip().endswith(',"meta":{"k": [1, 2.50]}}'), "scene meta: " + out)

# ------------------------------------------------------------------------------------------------
# The judge against an independent count.
cases_lines = open(path("exact.jsonl")).read().splitlines()
cases = [json.loads(x) for x in cases_lines]
POSITIONS = ["I", "TI", "C", "TE", "E"]
rng = random.Random(20240611)


def independent(cases, answer_lines, truth_key, by):
    """The judge's counts, recomputed here: the first answer of an id counts."""
    ids = {json.dumps(c["id"]) for c in cases}
    first, malformed, unknown, duplicate = {}, 0, 0, 0
    for line in answer_lines:
        if not line.strip():
            continue
        try:
            a = json.loads(line)
        except ValueError:
            malformed += 1
            continue
        if not isinstance(a, dict) or "id" not in a:
            malformed += 1
            continue
        key = json.dumps(a["id"])
        if key not in ids:
            unknown += 1
        elif key in first:
            duplicate += 1
        else:
            first[key] = a
    groups, total = {}, {"right": 0, "wrong": 0, "undecided": 0, "missing": 0, "no_truth": 0}
    confusion = {t: {k: 0 for k in POSITIONS + ["undecided", "missing"]} for t in POSITIONS}
    for c in cases:
        truth = c["meta"][truth_key]
        key = tuple(v if isinstance(v, str) else json.dumps(v) for v in (c["meta"].get(k) for k in by))
        g = groups.setdefault(key,
                              {"right": 0, "wrong": 0, "undecided": 0, "missing": 0, "no_truth": 0})
        a = first.get(json.dumps(c["id"]))
        if truth is None:
            kind = "no_truth"
        elif a is None:
            kind, column = "missing", "missing"
        elif "error" in a or a.get("position") not in POSITIONS:
            kind, column = "undecided", "undecided"
        else:
            kind, column = ("right" if a["position"] == truth else "wrong"), a["position"]
        for t in (g, total):
            t[kind] += 1
        if truth is not None:
            confusion[truth][column] += 1
    return groups, total, confusion, (malformed, unknown, duplicate)


for trial in range(6):
    truth_key = ["position", "double_position", "matrix_position"][trial % 3]
    by = [["family", "eps"], ["side"], ["family"]][trial % 3]
    lines = []
    for c in cases:
        r = rng.random()
        if r < 0.08:
            continue  # missing
        position = rng.choice(POSITIONS) if r < 0.4 else c["meta"]["position"]
        if r > 0.9:
            lines.append(json.dumps({"id": c["id"], "position": rng.choice([None, "?", "undecided", 3])}))
        elif r > 0.85:
            lines.append(json.dumps({"id": c["id"], "error": "gave up"}))
        else:
            lines.append(json.dumps({"id": c["id"], "position": position, "extra": [1, 2]}))
        if rng.random() < 0.05:
            lines.append(json.dumps({"id": c["id"], "position": rng.choice(POSITIONS)}))  # duplicate
    lines += ["not json", "[1, 2]", '{"position": "I"}', '{"id": "nobody", "position": "E"}', "", '{"id": 3}']
    rng.shuffle(lines)
    open(path("answers.jsonl"), "w").write("\n".join(lines) + "\n")
    truth_arg = {"position": "exact", "double_position": "double", "matrix_position": "matrix"}[truth_key]
    report = json.loads(run(["judge", path("exact.jsonl"), path("answers.jsonl"), "--truth", truth_arg,
                             "--by", ",".join(by), "--format", "json"]))
    groups, total, confusion, unmatched = independent(cases, lines, truth_key, by)
    for k in total:
        check(report["total"][k] == total[k], "trial %d total %s: %s != %s" % (trial, k, report["total"][k], total[k]))
    check(report["total"]["cases"] == len(cases), "trial %d: cases" % trial)
    check((report["unmatched"]["malformed"], report["unmatched"]["unknown"], report["unmatched"]["duplicate"])
          == unmatched, "trial %d unmatched %s != %s" % (trial, report["unmatched"], unmatched))
    check(report["confusion"] == confusion, "trial %d confusion" % trial)
    mine = {tuple(g["key"][k] for k in by): {k: g[k] for k in total} for g in report["groups"]}
    check(mine == groups, "trial %d groups" % trial)
    bad = total["wrong"] + total["undecided"] + total["missing"]
    check(len(report["misses"]) == bad, "trial %d misses" % trial)
    check(all(m["reproduce"].startswith("relpos classify --ellipsoid '") for m in report["misses"]), "reproduce")
    csv = run(["judge", path("exact.jsonl"), path("answers.jsonl"), "--truth", truth_arg, "--by", ",".join(by),
               "--format", "csv"]).splitlines()
    last = dict(zip(csv[0].split(","), csv[-1].split(",")))
    check(last[by[0]] == "all" and int(last["wrong"]) == total["wrong"], "csv total")
    md = run(["judge", path("exact.jsonl"), path("answers.jsonl"), "--truth", truth_arg])
    check("| all |" in md and "%d malformed, %d unknown id, %d duplicate id" % unmatched in md, "md")

# A reproduction line reproduces its truth.
miss = report["misses"][0]
words = re.match(r"relpos classify --ellipsoid '(.*)' --paraboloid '(.*)'$", miss["reproduce"])
out = run(["classify", "--ellipsoid", words.group(1), "--paraboloid", words.group(2), "--json"])
check(json.loads(out)["position"] == miss["truth"], "the reproduction line gives the truth")

# The tolerance on hand-written spheres in z = x^2 + y^2 (s* = c / r below c = 1/2, else
# sqrt(c - 1/4) / r), margins by hand, both read from the case line and from the answer.
spheres = [
    ('{"id":"near","ellipsoid":{"sphere":{"center":[0,0,"1/5"],"radius":"199/1000"}},"paraboloid":{"vertex":[0,0,0],'
     '"a":1,"b":1},"meta":{"family":"s","eps":"1/199","margin":{"lo":"200/199","hi":"200/199"}}}'),
    ('{"id":"circle","ellipsoid":{"sphere":{"center":[0,0,"3/4"],"radius":"7071/10000"}},"paraboloid":{"vertex":[0,0,0],'
     '"a":1,"b":1},"meta":{"family":"s","eps":"1e-4"}}'),
]
open(path("spheres.jsonl"), "w").write("\n".join(spheres) + "\n")
# s* = sqrt(1/2) / r ~ 1.0000096: s*^2 = (1/2) / r^2, the root of 49999041 x^2 - 50000000 in [1, 10001/10000].
margin = '{"lo":"1","hi":"10001/10000","polynomial":["-50000000","0","49999041"]}'
answers = '{"id":"near","position":"TI"}\n{"id":"circle","position":"C","margin":%s}\n' % margin
open(path("sphere-answers.jsonl"), "w").write(answers)
for tau, excused in (("1/201", 1), ("1/199", 2), ("0", 0)):
    r = json.loads(run(["judge", path("spheres.jsonl"), path("sphere-answers.jsonl"), "--tolerance", tau,
                        "--format", "json"]))
    check(r["total"]["excused"] == excused, "tolerance %s: %d excused, not %d" % (tau, r["total"]["excused"], excused))

# --plot, and the adapter of the walkthrough end to end, counted independently.
adapter = os.path.join(SOURCE, "examples", "oracle", "adapter.py")
small = run(["cases", "offaxis", "tiny", "special", "far", "--n", "6", "--eps", "1e-4,1e-10,0"])
open(path("small.jsonl"), "w").write(small)
answered = subprocess.run([sys.executable, adapter], input=small, capture_output=True, text=True, check=True).stdout
check(len(answered.splitlines()) == len(small.splitlines()), "the adapter answers every case")
open(path("small-answers.jsonl"), "w").write(answered)
report = json.loads(run(["judge", path("small.jsonl"), path("small-answers.jsonl"), "--format", "json", "--plot",
                         path("chart.png")]))
_, total, _, _ = independent([json.loads(x) for x in small.splitlines()], answered.splitlines(), "position",
                             ["family", "eps"])
check(report["total"]["wrong"] == total["wrong"] and report["total"]["right"] == total["right"], "adapter counts")
png = open(path("chart.png"), "rb").read()
check(png[:8] == b"\x89PNG\r\n\x1a\n", "the chart is a PNG")
try:
    import matplotlib.image

    check(matplotlib.image.imread(path("chart.png")).shape[:2] == (620, 1000), "matplotlib reads the chart")
except ImportError:
    pass
# Usage errors.
run(["judge", path("small.jsonl")], code=2)
run(["judge", "-", "-"], code=2)
run(["cases"], code=2)
run(["cases", "nonsense"], code=1)
run(["judge", path("small.jsonl"), path("small-answers.jsonl"), "--truth", "maybe"], code=2)

print("check_oracle: %d failures" % len(failures))
sys.exit(1 if failures else 0)
