#!/usr/bin/env bash
# Check `relpos scene` on examples/scene-container.jsonl and examples/scene-container.csv against the
# expectations encoded in the inputs, plus options, summaries, determinism and exit codes.
#
# Usage: tests/cli/check_scene.sh PATH/TO/relpos REPO_ROOT
#
# Expected answers (doc/cli.md, "relpos scene"):
#   JSONL: the "id" when it is a string starting with I-, TI-, C-, TE-, E- or ERR-,
#          else a "comment" reading "expect: POS"; lines that are blank or not JSON objects: error.
#          The output id is the input id, or the 1-based line number when there is none.
#   CSV:   the first field when it starts with one of those prefixes, else a preceding comment line
#          "# expect: POS"; the first field is the id (and is echoed) when the line has 5 or 11
#          fields, otherwise the output id is the line number. Lines starting with '#' and blank
#          lines give no output.
# Exits 0 when everything matches, 1 on a mismatch, 2 on a usage error.
set -u

if [ $# -ne 2 ]; then
  echo "usage: $0 PATH/TO/relpos REPO_ROOT" >&2
  exit 2
fi
relpos=$1
root=$2
if [ ! -x "$relpos" ]; then
  echo "check_scene: '$relpos' is not an executable" >&2
  exit 2
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
note() {
  echo "FAIL $*"
  fail=1
}

par="--standard-paraboloid 1,2"
for ext in jsonl csv; do
  input="$root/examples/scene-container.$ext"
  for threads in 1 2 3; do
    "$relpos" scene $par "$input" --threads "$threads" --no-progress >"$tmp/out-$ext-$threads" 2>"$tmp/err-$ext-$threads"
    rc=$?
    [ $rc -eq 0 ] || note "$ext, $threads thread(s): exit status $rc"
  done
  cmp -s "$tmp/out-$ext-1" "$tmp/out-$ext-2" || note "$ext: 1 and 2 threads give different output"
  cmp -s "$tmp/out-$ext-1" "$tmp/out-$ext-3" || note "$ext: 1 and 3 threads give different output"
  # The same input on standard input, format given explicitly.
  "$relpos" scene $par - --format "$ext" <"$input" >"$tmp/stdin-$ext" 2>/dev/null || note "$ext: stdin run failed"
  cmp -s "$tmp/out-$ext-1" "$tmp/stdin-$ext" || note "$ext: standard input gives different output"
  /usr/bin/python3 - "$ext" "$input" "$tmp/out-$ext-1" "$tmp/err-$ext-1" <<'PY' || fail=1
import json
import sys

ext, input_path, output_path, err_path = sys.argv[1:]
PREFIXES = {"I": "I", "TI": "TI", "C": "C", "TE": "TE", "E": "E", "ERR": "error"}
with open(input_path, encoding="utf-8") as f:
    inputs = f.read().split("\n")
if inputs and inputs[-1] == "":
    inputs.pop()
with open(output_path, encoding="utf-8") as f:
    outputs = [l for l in f.read().split("\n") if l != ""]


def reject_constant(name):
    raise ValueError("not JSON: " + name)


def prefix_answer(text):
    if isinstance(text, str) and "-" in text and text.split("-", 1)[0] in PREFIXES:
        return PREFIXES[text.split("-", 1)[0]]
    return None


expected = []  # (line number, expected answer, expected id)
pending = None  # CSV: "# expect: POS" states the answer of the next body line
for number, line in enumerate(inputs, 1):
    if ext == "csv":
        stripped = line.strip()
        if stripped.startswith("# expect: "):
            pending = PREFIXES.get(stripped[10:].split()[0])
        if stripped == "" or stripped.startswith("#"):
            continue
        fields = [x.strip() for x in stripped.split(",")]
        answer = prefix_answer(fields[0]) or pending
        pending = None
        has_id = len(fields) in (5, 11)
        expected.append((number, answer, fields[0] if has_id else number))
        continue
    if line.strip() == "":
        expected.append((number, "error", number))
        continue
    try:
        doc = json.loads(line, parse_constant=reject_constant)
    except ValueError:
        expected.append((number, "error", number))
        continue
    if not isinstance(doc, dict):
        expected.append((number, "error", number))
        continue
    ident = doc.get("id", number)
    answer = prefix_answer(doc.get("id"))
    comment = doc.get("comment")
    if answer is None and isinstance(comment, str) and comment.startswith("expect: "):
        answer = PREFIXES.get(comment[8:])
    expected.append((number, answer, ident))

problems = []
if len(outputs) != len(expected):
    problems.append(f"{len(expected)} body lines but {len(outputs)} output lines")
counts = {}
for (number, answer, ident), out in zip(expected, outputs):
    got = json.loads(out)
    if got.get("id") != ident:
        problems.append(f"line {number}: out of order: id {json.dumps(got.get('id'))}, expected {json.dumps(ident)}")
        continue
    position = "error" if "error" in got else got.get("position")
    if answer is None:
        problems.append(f"line {number}: the example states no expected answer")
    elif position != answer:
        problems.append(f"line {number} ({ident}): expected {answer}, got {position} ({got.get('error', '')})")
    if "error" in got and got.get("line") != number:
        problems.append(f"line {number}: the error line names line {got.get('line')}")
    if "error" not in got:
        counts[position] = counts.get(position, 0) + 1
        if got.get("stage") not in ("inside-certificate", "outside-certificate", "static-double", "semi-static-double", "multiple-root-witness", "interval",
                                    "exact-signs", "exact-roots"):
            problems.append(f"line {number}: unknown stage {got.get('stage')}")
with open(err_path, encoding="utf-8") as f:
    summary = json.loads(f.read().strip().split("\n")[-1])["summary"]
errors = sum(1 for (_, a, _) in expected if a == "error")
if summary["bodies"] != len(expected) - errors or summary["errors"] != errors:
    problems.append(f"summary: bodies {summary['bodies']}, errors {summary['errors']}; expected "
                    f"{len(expected) - errors}, {errors}")
if sum(summary["positions"].values()) != summary["bodies"] or sum(summary["stages"].values()) != summary["bodies"]:
    problems.append("summary: position or stage counts do not add up to the bodies")
for position, n in counts.items():
    if summary["positions"].get(position) != n:
        problems.append(f"summary: {position} counted {summary['positions'].get(position)}, output has {n}")
for p in problems:
    print(f"FAIL {ext}: {p}")
print(f"scene {ext}: {len(expected)} lines checked, {len(problems)} problems")
sys.exit(1 if problems else 0)
PY
done

# --summary-only: no body lines, the same summary.
"$relpos" scene $par "$root/examples/scene-container.csv" --summary-only >"$tmp/quiet" 2>"$tmp/quiet-err"
[ -s "$tmp/quiet" ] && note "--summary-only printed body lines"
grep -q '"summary"' "$tmp/quiet-err" || note "--summary-only printed no summary"

# --generate: deterministic for a seed, and every generated line is classified without error.
"$relpos" scene --generate 300 --seed 11 >"$tmp/g1.csv" || note "--generate failed"
"$relpos" scene --generate 300 --seed 11 >"$tmp/g2.csv"
"$relpos" scene --generate 300 --seed 12 >"$tmp/g3.csv"
cmp -s "$tmp/g1.csv" "$tmp/g2.csv" || note "--generate is not deterministic"
cmp -s "$tmp/g1.csv" "$tmp/g3.csv" && note "--generate ignores the seed"
[ "$(grep -vc '^#' "$tmp/g1.csv")" -eq 300 ] || note "--generate 300 did not write 300 bodies"
"$relpos" scene $par "$tmp/g1.csv" --no-progress >"$tmp/g1.out" 2>"$tmp/g1.err" || note "classifying the generated scene failed"
[ "$(wc -l <"$tmp/g1.out")" -eq 300 ] || note "the generated scene did not give 300 answers"
grep -q '"error"' "$tmp/g1.out" && note "the generated scene has error lines"
grep -q '"bodies":300,"errors":0' "$tmp/g1.err" || note "summary of the generated scene: $(cat "$tmp/g1.err")"

# Exit codes: usage errors 2, bad paraboloid 1, missing file 3.
"$relpos" scene "$root/examples/scene-container.csv" >/dev/null 2>&1
[ $? -eq 2 ] || note "missing paraboloid: expected exit status 2"
"$relpos" scene $par --threads 0 "$root/examples/scene-container.csv" >/dev/null 2>&1
[ $? -eq 2 ] || note "--threads 0: expected exit status 2"
"$relpos" scene $par --format xml "$root/examples/scene-container.csv" >/dev/null 2>&1
[ $? -eq 2 ] || note "--format xml: expected exit status 2"
"$relpos" scene --paraboloid '{"vertex": [0, 0, 0], "a": -1, "b": 2}' "$root/examples/scene-container.csv" >/dev/null 2>&1
[ $? -eq 1 ] || note "bad paraboloid: expected exit status 1"
"$relpos" scene $par "$tmp/does-not-exist.csv" >/dev/null 2>&1
[ $? -eq 3 ] || note "missing file: expected exit status 3"
"$relpos" scene --help | grep -q "relpos scene" || note "scene --help"

[ $fail -eq 0 ] && echo "check_scene: all passed"
exit $fail
