#!/usr/bin/env bash
# Set up what is missing, build, and run the main job on the bundled examples, readably:
#   1. relpos batch on examples/mixed.jsonl: one line per pair (id, position, rule), then a summary;
#   2. relpos verify: every certificate of those answers checked with rational arithmetic alone;
#   3. the examples' own checker (each id states its expected answer);
#   4. relpos scene on the container scene (many bodies, one paraboloid).
# The raw JSON answers are kept in build/examples/ for a closer look.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build -DRELPOS_BUILD_TESTS=OFF
relpos=build/cli/relpos
out=build/examples
mkdir -p "$out"

echo "== relpos batch examples/mixed.jsonl  (answers: $out/mixed.answers.jsonl)"
"$relpos" batch examples/mixed.jsonl > "$out/mixed.answers.jsonl"
/usr/bin/python3 - "$out/mixed.answers.jsonl" <<'PY'
import collections, json, sys
counts = collections.Counter()
for line in open(sys.argv[1], encoding="utf-8"):
    a = json.loads(line)
    ident = str(a.get("id"))
    if "error" in a:
        counts["error"] += 1
        print(f"  {ident[:34]:34}  error  {a['error'][:70]}")
    else:
        counts[a["position"]] += 1
        print(f"  {ident[:34]:34}  {a['position']:5}  {a['rule'][:70]}")
print()
print("summary: " + ", ".join(f"{k} {counts[k]}" for k in ("I", "TI", "C", "TE", "E", "error") if counts[k]))
PY

echo
echo "== relpos verify examples/mixed.jsonl $out/mixed.answers.jsonl"
"$relpos" verify examples/mixed.jsonl "$out/mixed.answers.jsonl"

echo
echo "== the examples' checker (tests/cli/check_examples.sh)"
tests/cli/check_examples.sh "$relpos" .

echo
echo "== relpos scene --standard-paraboloid 1,2 examples/scene-container.jsonl"
"$relpos" scene --standard-paraboloid 1,2 examples/scene-container.jsonl > "$out/scene.answers.jsonl"
echo "  (answers: $out/scene.answers.jsonl)"
