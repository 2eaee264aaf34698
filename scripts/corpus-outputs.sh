#!/usr/bin/env bash
# Every answer the CLI writes on the project's corpora, one file per corpus and mode, so that two
# builds can be compared byte for byte (a refactoring must leave every position, report and
# certificate unchanged):
#   scripts/corpus-outputs.sh BUILD_DIR OUT_DIR      # writes OUT_DIR/*.out
#   scripts/corpus-outputs.sh --compare OLD NEW      # byte for byte, the scene summaries' timings masked
# The corpora: the examples, the hostile inputs, the regime files (spheres and matrices, as
# benchmarks/batch_bench.py writes them, 2 000 lines each), the edge cases, the fuzz seed corpus, the
# scene examples and a generated scene, one-pair reports, a motion, and `verify` on full answers; the
# general pairs (tests/general_cases_jsonl.cpp: every type, every position, mapped and scaled), the
# paraboloids off the z axis and the pairs scaled by 10^300 and 10^-300 (batch_bench.py's
# write_off_axis and write_scaled).
set -euo pipefail
if [ "${1:-}" = "--compare" ]; then
  old=$2 new=$3 status=0
  for f in "$old"/*.out; do
    b=$(basename "$f")
    # A scene's summary reports its run time: those members are masked, every other byte compared.
    mask() { sed -E 's/"(seconds|bodies_per_second)":\{[^}]*\}/"\1":{}/g' "$1"; }
    if cmp -s <(mask "$f") <(mask "$new/$b"); then echo "same      $b"; else echo "DIFFERENT $b"; status=1; fi
  done
  exit $status
fi
cd "$(dirname "$0")/.."
build=$(cd "$1" && pwd)
out=$2
mkdir -p "$out"
out=$(cd "$out" && pwd)
cli=$build/cli/relpos
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Regime files, written by the benchmark's own generator.
/usr/bin/python3 - "$tmp" <<'PY'
import sys
sys.path.insert(0, "benchmarks")
from batch_bench import write_off_axis, write_regime, write_scaled
write_regime(sys.argv[1] + "/regime-sphere.jsonl", 2000, form="sphere")
write_regime(sys.argv[1] + "/regime-matrix.jsonl", 2000, form="matrix")
write_off_axis(sys.argv[1] + "/off-axis.jsonl", 600)
write_scaled(sys.argv[1] + "/scaled-quadric.jsonl", 300, kind="quadric", shift=300)
write_scaled(sys.argv[1] + "/scaled-paraboloid.jsonl", 60, kind="paraboloid", shift=300)
PY
"$build/tests/edge_cases_jsonl" >"$tmp/edges.jsonl" 2>/dev/null || true
"$build/tests/general_cases_jsonl" 300 36 4 >"$tmp/general.jsonl" 2>/dev/null || true
: >"$tmp/fuzz.jsonl"
for f in fuzz/corpus/batch_line/*; do
  tr -d '\n\r' <"$f" >>"$tmp/fuzz.jsonl"
  echo >>"$tmp/fuzz.jsonl"
done

batch() {  # name input args...
  local name=$1 input=$2
  shift 2
  "$cli" batch "$input" --threads 2 "$@" >"$out/$name.out" 2>&1 || echo "exit $?" >>"$out/$name.out"
}
for input in examples/mixed.jsonl tests/hostile/hostile.jsonl "$tmp/regime-sphere.jsonl" "$tmp/regime-matrix.jsonl" \
  "$tmp/edges.jsonl" "$tmp/fuzz.jsonl" examples/scene-container.jsonl "$tmp/general.jsonl" "$tmp/off-axis.jsonl" \
  "$tmp/scaled-quadric.jsonl" "$tmp/scaled-paraboloid.jsonl"; do
  n=$(basename "$input" .jsonl)
  batch "$n-full" "$input"
  batch "$n-minimal" "$input" --evidence minimal
  batch "$n-double" "$input" --numbers double
  batch "$n-contact" "$input" --contact-only
  batch "$n-digits30" "$input" --digits 30
done
"$cli" verify examples/mixed.jsonl "$out/mixed-full.out" >"$out/verify-mixed.out" 2>&1 || true
"$cli" verify "$tmp/edges.jsonl" "$out/edges-full.out" >"$out/verify-edges.out" 2>&1 || true
"$cli" verify "$tmp/regime-sphere.jsonl" "$out/regime-sphere-full.out" >"$out/verify-regime.out" 2>&1 || true
"$cli" verify "$tmp/general.jsonl" "$out/general-full.out" >"$out/verify-general.out" 2>&1 || true
"$cli" verify "$tmp/off-axis.jsonl" "$out/off-axis-full.out" >"$out/verify-off-axis.out" 2>&1 || true

scene() {  # name args...
  local name=$1
  shift
  "$cli" scene --no-progress --threads 2 "$@" >"$out/$name.out" 2>&1 || echo "exit $?" >>"$out/$name.out"
}
scene scene-jsonl --standard-paraboloid 1,2 examples/scene-container.jsonl
scene scene-csv --standard-paraboloid 1,2 examples/scene-container.csv --format csv
scene scene-generated --generate 3000 --seed 7

{
  "$cli" classify --sphere "0,1/2,92281/129600,1/4" --standard-paraboloid "6/5,3/2"
  "$cli" classify --sphere "0,1/2,92281/129600,1/4" --standard-paraboloid "6/5,3/2" --json
  "$cli" classify --ellipsoid '{"center":[0,0,1],"axes":["1/4","1/8","1/8"],"rotation":[1,2,3,4]}' \
    --paraboloid '{"vertex":[0,0,0],"a":1,"b":2}'
  "$cli" classify --sphere "1,0,131/192,1/4" --standard-paraboloid 1,2 --digits 40
  "$cli" classify --sphere "0,0,1/2,1/2" --standard-paraboloid 1,1
  "$cli" classify --sphere "0,0,3,2" --standard-paraboloid 1,1 --contact-only
} >"$out/classify.out" 2>&1 || true
"$cli" motion --sphere 0,0,0,1/4 --standard-paraboloid 1,2 --translation '[[], [], ["-9/4", 0, 1]]' \
  --t0 0 --t1 2 >"$out/motion.out" 2>&1 || true
"$cli" motion --sphere 0,0,0,1/4 --standard-paraboloid 1,2 --translation '[[], [], ["-9/4", 0, 1]]' \
  --t0 0 --t1 2 --json >"$out/motion-timeline.out" 2>&1 || true
ls "$out" | wc -l | sed 's/^/relpos: corpus outputs written: /'
