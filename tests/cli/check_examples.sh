#!/usr/bin/env bash
# Check `relpos batch examples/mixed.jsonl` against the expectations encoded in the input.
#
# Usage: tests/cli/check_examples.sh PATH/TO/relpos REPO_ROOT
#
# The expected answer of each input line comes from, in this order:
#   1. its "id", when it is a string starting with I-, TI-, C-, TE-, E- or ERR-;
#   2. its "comment", when it reads "expect: POS" (POS one of I, TI, C, TE, E, ERR);
#   3. an error, when the line is blank, is not valid JSON or is not a JSON object.
# A line with none of these is itself a failure (every example must state its answer).
# The output must have exactly one line per input line, in order: the output id must be the input
# id, or the 1-based line number when the input has none (or cannot be read).
# Every valid pair has one of the five positions whatever its size (math.md §8): there is no
# "unclassified" answer any more, so an id prefix U- is no expectation.
# The batch output is then handed to `relpos verify`: every certificate must verify (error lines of
# invalid input are skipped), and the numbers of verified and skipped lines must add up.
# Exits 0 when everything matches, 1 on any mismatch, 2 on a usage error or a failed run.
set -u

if [ $# -ne 2 ]; then
  echo "usage: $0 PATH/TO/relpos REPO_ROOT" >&2
  exit 2
fi
relpos=$1
root=$2
input="$root/examples/mixed.jsonl"
if [ ! -x "$relpos" ]; then
  echo "check_examples: '$relpos' is not an executable" >&2
  exit 2
fi
if [ ! -r "$input" ]; then
  echo "check_examples: cannot read '$input'" >&2
  exit 2
fi

output=$(mktemp)
trap 'rm -f "$output"' EXIT
"$relpos" batch "$input" >"$output"
rc=$?
if [ $rc -ne 0 ]; then
  echo "check_examples: relpos batch exited with status $rc (expected 0)" >&2
  exit 1
fi

/usr/bin/python3 - "$input" "$output" <<'PY'
import json
import sys

input_path, output_path = sys.argv[1], sys.argv[2]
with open(input_path, encoding="utf-8") as f:
    inputs = f.read().split("\n")
if inputs and inputs[-1] == "":
    inputs.pop()  # the newline that ends the last line
with open(output_path, encoding="utf-8") as f:
    outputs = f.read().split("\n")
if outputs and outputs[-1] == "":
    outputs.pop()

PREFIXES = {"I": "I", "TI": "TI", "C": "C", "TE": "TE", "E": "E", "ERR": "error"}


def reject_constant(name):
    raise ValueError("not JSON: " + name)  # Python would accept NaN and Infinity


def expectation(line):
    """(expected answer, expected output id or None for the line number)."""
    if line.strip() == "":
        return "error", None
    try:
        doc = json.loads(line, parse_constant=reject_constant)
    except ValueError:
        return "error", None
    if not isinstance(doc, dict):
        return "error", None
    has_id = "id" in doc
    ident = doc.get("id")
    if isinstance(ident, str) and "-" in ident and ident.split("-", 1)[0] in PREFIXES:
        return PREFIXES[ident.split("-", 1)[0]], (ident,)
    comment = doc.get("comment")
    if isinstance(comment, str) and comment.startswith("expect: ") and comment[8:] in PREFIXES:
        return PREFIXES[comment[8:]], ((ident,) if has_id else None)
    return None, ((ident,) if has_id else None)


passed = failed = 0
problems = []
if len(outputs) != len(inputs):
    problems.append(f"line count: {len(inputs)} input lines but {len(outputs)} output lines")
for number, line in enumerate(inputs, 1):
    expected, ident = expectation(line)
    want_id = ident[0] if ident is not None else number
    if number > len(outputs):
        failed += 1
        problems.append(f"line {number}: no output line")
        continue
    try:
        answer = json.loads(outputs[number - 1])
    except ValueError as e:
        failed += 1
        problems.append(f"line {number}: output is not JSON ({e}): {outputs[number - 1][:80]}")
        continue
    if not isinstance(answer, dict) or "id" not in answer:
        failed += 1
        problems.append(f"line {number}: output has no id: {outputs[number - 1][:80]}")
        continue
    if answer["id"] != want_id:
        failed += 1
        problems.append(f"line {number}: out of order: output id {json.dumps(answer['id'])}, "
                        f"expected {json.dumps(want_id)}")
        continue
    got = "error" if "error" in answer else answer.get("position")
    if expected is None:
        failed += 1
        problems.append(f"line {number}: the example states no expected answer (id {json.dumps(want_id)})")
    elif got != expected:
        failed += 1
        detail = answer.get("error") or answer.get("rule", "")
        problems.append(f"line {number} ({json.dumps(want_id)}): expected {expected}, got {got} ({detail})")
    else:
        passed += 1

for p in problems:
    print("FAIL " + p)
print(f"examples: {passed} passed, {failed} failed")
sys.exit(0 if failed == 0 and not problems else 1)
PY
rc=$?

# The certificates of the batch output, checked by the independent exact verifier.
verify_out=$("$relpos" verify "$input" "$output" 2>&1)
vrc=$?
echo "$verify_out" | tail -n 20
if [ $vrc -ne 0 ]; then
  echo "FAIL relpos verify exited with status $vrc"
  rc=1
else
  total=$(wc -l <"$input")
  errors=$(grep -c '"error"' "$output")
  summary=$(echo "$verify_out" | tail -n 1)
  if [ "$summary" != "verified $((total - errors)), failed 0, skipped $errors" ]; then
    echo "FAIL relpos verify summary '$summary', expected 'verified $((total - errors)), failed 0, skipped $errors'"
    rc=1
  fi
fi

# The same input with --contact-only: one line per input line, in order, and the contact each
# expected position implies (I, E: none; TI, TE: touching; C: crossing; errors stay errors).
"$relpos" batch --contact-only "$input" >"$output"
if [ $? -ne 0 ]; then
  echo "check_examples: relpos batch --contact-only failed" >&2
  exit 1
fi
/usr/bin/python3 - "$input" "$output" <<'PY' || rc=1
import json
import sys

inputs = [l for l in open(sys.argv[1], encoding="utf-8").read().split("\n")]
if inputs and inputs[-1] == "":
    inputs.pop()
outputs = open(sys.argv[2], encoding="utf-8").read().split("\n")
if outputs and outputs[-1] == "":
    outputs.pop()
CONTACT = {"I": "none", "E": "none", "TI": "touching", "TE": "touching", "C": "crossing"}
problems = []
if len(outputs) != len(inputs):
    problems.append(f"{len(inputs)} input lines, {len(outputs)} output lines")
checked = 0
for number, (line, out) in enumerate(zip(inputs, outputs), 1):
    answer = json.loads(out)
    try:
        doc = json.loads(line, parse_constant=lambda c: (_ for _ in ()).throw(ValueError(c)))
    except ValueError:
        doc = None
    ident = doc.get("id") if isinstance(doc, dict) else None
    prefix = ident.split("-", 1)[0] if isinstance(ident, str) and "-" in ident else None
    if not isinstance(doc, dict) or prefix == "ERR":
        if "error" not in answer:
            problems.append(f"line {number}: expected an error, got {out[:80]}")
        continue
    if prefix in CONTACT:
        checked += 1
        if answer.get("contact") != CONTACT[prefix] or answer.get("position") != prefix:
            problems.append(f"line {number} ({ident}): expected contact {CONTACT[prefix]}, got {out[:120]}")
for p in problems:
    print("FAIL contact-only " + p)
print(f"contact-only: {checked} lines checked, {len(problems)} problems")
sys.exit(1 if problems or checked == 0 else 0)
PY
exit $rc
