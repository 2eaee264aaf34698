#!/usr/bin/env bash
# Build and run the relpos benchmark, then draw the charts (doc/performance.md).
#
#   benchmarks/run.sh            # full run (~1-2 minutes on 2 cores), seed 20240601
#   benchmarks/run.sh --quick    # smaller family (a), fewer batches
#   benchmarks/run.sh --scene    # only the scene benchmark (scene_bench, 10^6 bodies)
#   benchmarks/run.sh --edge     # only the near-tangent benchmark (edge_bench) and its chart
#   benchmarks/run.sh --general  # general quadrics (general_bench): speed against the float decisions
#                                # and their error rates near tangency, with its chart
#   benchmarks/run.sh --ordinary [ordinary_bench options]   # ordinary pairs and relpos batch against
#                                # the minimal float decision and json.loads, from the installed package
#   benchmarks/run.sh --regime   # regime_bench: the paper's regime against the naive and minimal float
#                                # decisions (doc/performance.md, "The paper's regime")
#   benchmarks/run.sh --python [python_bench options]       # the Python package against float code in
#                                # numpy and in pure Python (doc/python.md, "Measured")
#   benchmarks/run.sh --evidence # where a full-evidence line of relpos batch spends its time, component by
#                                # component (perf; doc/performance.md, "Where a full-evidence line's time goes")
#   benchmarks/run.sh --lanes [lanes_bench options]         # many pairs at once: decide_positions on 10^6
#                                # pairs from doubles against the minimal float decision, scalar and in
#                                # lanes (doc/performance.md, "Many pairs at once")
#
# Outputs: benchmarks/results/{results.csv,stages.csv,summary.json,*.png}.
# Plotting needs matplotlib for /usr/bin/python3 (Debian python3-matplotlib, benchmark-only
# dependency); it is installed with apt-get when missing and apt-get is usable.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="$ROOT/build-bench"
OUT="$ROOT/benchmarks/results"
SEED="${RELPOS_BENCH_SEED:-20240601}"

# benchmarks/run.sh --ordinary: the current sources built (build-ordinary: library and CLI only, or
# the build directory RELPOS_ORDINARY_BUILD, built as it is configured) and installed into a
# temporary prefix; benchmarks/ordinary built against that install and run, then
# benchmarks/batch_bench.py on the installed CLI (both files, --threads 2, 20 000 lines) ->
# benchmarks/results/{ordinary,batch}.json and *_log.txt, and the generated part of the section
# "Ordinary pairs against the minimal float decision" of doc/performance.md rewritten
# (tables.py --ordinary). About a minute; extra arguments go to ordinary_bench.
if [ "${1:-}" = "--ordinary" ]; then
  shift
  if [ -n "${RELPOS_ORDINARY_BUILD:-}" ]; then
    BUILD=$RELPOS_ORDINARY_BUILD
  else
    BUILD="$ROOT/build-ordinary"
    cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DRELPOS_BUILD_TESTS=OFF -DRELPOS_BUILD_BENCHMARKS=OFF \
      -DRELPOS_BUILD_PYTHON=OFF >/dev/null
  fi
  cmake --build "$BUILD" -j2 >/dev/null
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
  bash "$ROOT/benchmarks/ordinary/build.sh" "$BUILD" "$work"
  mkdir -p "$OUT"
  "$work/build/ordinary_bench" --out "$OUT/ordinary.json" "$@" 2>&1 | tee "$OUT/ordinary_log.txt"
  [ "${PIPESTATUS[0]}" = 0 ] || exit 1
  /usr/bin/python3 "$ROOT/benchmarks/batch_bench.py" --cli "$work/prefix/bin/relpos" --lines 20000 --repeat 5 \
    --threads 2 --form both --out "$OUT/batch.json" 2>&1 | tee "$OUT/batch_log.txt"
  [ "${PIPESTATUS[0]}" = 0 ] || exit 1
  /usr/bin/python3 "$ROOT/benchmarks/tables.py" --ordinary "$OUT"
  exit 0
fi
# benchmarks/run.sh --evidence: the CLI built in build-evidence (Release), then evidence_profile.py
# (perf record on `relpos batch --evidence full` over the sphere, matrix and user regime files) ->
# benchmarks/results/evidence.json and evidence_log.txt, and its table in doc/performance.md rewritten
# (tables.py --evidence). About a minute; needs perf (Debian linux-perf).
if [ "${1:-}" = "--evidence" ]; then
  shift
  BUILD="$ROOT/build-evidence"
  cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DRELPOS_BUILD_TESTS=OFF -DRELPOS_BUILD_BENCHMARKS=OFF \
    -DRELPOS_BUILD_PYTHON=OFF >/dev/null
  cmake --build "$BUILD" -j2 --target relpos_cli >/dev/null
  mkdir -p "$OUT"
  /usr/bin/python3 "$ROOT/benchmarks/evidence_profile.py" --cli "$BUILD/cli/relpos" --out "$OUT/evidence.json" "$@" 2>&1 |
    tee "$OUT/evidence_log.txt"
  [ "${PIPESTATUS[0]}" = 0 ] || exit 1
  /usr/bin/python3 "$ROOT/benchmarks/tables.py" --evidence "$OUT"
  exit 0
fi
# benchmarks/run.sh --python: the extension and the CLI built in build-python (Release), then
# python_bench.py's decide paths -> benchmarks/results/python.json and python_log.txt, and the tables of
# doc/python.md ("Measured") and doc/performance.md ("Python") rewritten (tables.py --python). Under a
# minute; extra arguments go to python_bench.py.
if [ "${1:-}" = "--python" ]; then
  shift
  BUILD="$ROOT/build-python"
  cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DRELPOS_BUILD_TESTS=OFF -DRELPOS_BUILD_BENCHMARKS=OFF \
    >/dev/null
  cmake --build "$BUILD" -j2 --target relpos_python >/dev/null
  mkdir -p "$OUT"
  PYTHONPATH="$BUILD/python" RELPOS_CLI="$BUILD/cli/relpos" /usr/bin/python3 "$ROOT/benchmarks/python_bench.py" \
    --skip-dask --out "$OUT/python.json" "$@" 2>&1 | tee "$OUT/python_log.txt"
  [ "${PIPESTATUS[0]}" = 0 ] || exit 1
  /usr/bin/python3 "$ROOT/benchmarks/tables.py" --python "$OUT"
  exit 0
fi
cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DRELPOS_BUILD_BENCHMARKS=ON -DRELPOS_BUILD_TESTS=OFF >/dev/null
# benchmarks/run.sh --scene [N]: only the scene benchmark (N bodies, default 10^6; a few minutes,
# about 3 GB of memory) -> benchmarks/results/scene.json and scene_log.txt (doc/performance.md).
if [ "${1:-}" = "--scene" ]; then
  cmake --build "$BUILD" -j2 --target scene_bench
  mkdir -p "$OUT"
  "$BUILD/benchmarks/scene_bench" --n "${2:-1000000}" --seed "$SEED" --out "$OUT" 2>&1 | tee "$OUT/scene_log.txt"
  exit "${PIPESTATUS[0]}"
fi
# benchmarks/run.sh --regime: regime_bench (--n 20000 --full 600 --batches 15 --rounds 5) ->
# benchmarks/results/regime.json and regime_log.txt, and its table in doc/performance.md rewritten
# (tables.py --regime). About a minute.
if [ "${1:-}" = "--regime" ]; then
  cmake --build "$BUILD" -j2 --target regime_bench
  mkdir -p "$OUT"
  "$BUILD/benchmarks/regime_bench" --n 20000 --full 600 --batches 15 --rounds 5 --out "$OUT/regime.json" 2>&1 |
    tee "$OUT/regime_log.txt"
  [ "${PIPESTATUS[0]}" = 0 ] || exit 1
  /usr/bin/python3 "$ROOT/benchmarks/tables.py" --regime "$OUT"
  exit 0
fi
# benchmarks/run.sh --lanes: lanes_bench (10^6 pairs of the ordinary regime, 2 x 10^5 of the user
# regime, 5 rounds) -> benchmarks/results/lanes.json and lanes_log.txt, and its tables in
# doc/performance.md rewritten (tables.py --lanes). A few minutes; about 1 GB of memory.
if [ "${1:-}" = "--lanes" ]; then
  shift
  cmake --build "$BUILD" -j2 --target lanes_bench
  mkdir -p "$OUT"
  "$BUILD/benchmarks/lanes_bench" --n 1000000 --user-n 200000 --rounds 5 --out "$OUT/lanes.json" "$@" 2>&1 |
    tee "$OUT/lanes_log.txt"
  [ "${PIPESTATUS[0]}" = 0 ] || exit 1
  /usr/bin/python3 "$ROOT/benchmarks/tables.py" --lanes "$OUT"
  exit 0
fi
# benchmarks/run.sh --general: general_bench (20 000 ellipsoid pairs and 5 000 pairs of every type,
# 9 rounds) -> benchmarks/results/general_log.txt, then general_bench --edge (the tangencies of every
# type nudged by 10^-k under 6 congruences each) -> general_edge.csv, general_edge_log.txt and
# general_edge.png, and its table in doc/performance.md rewritten (tables.py --general). A minute or two.
if [ "${1:-}" = "--general" ]; then
  cmake --build "$BUILD" -j2 --target general_bench
  mkdir -p "$OUT"
  "$BUILD/benchmarks/general_bench" 20000 9 2>&1 | tee "$OUT/general_log.txt"
  [ "${PIPESTATUS[0]}" = 0 ] || exit 1
  "$BUILD/benchmarks/general_bench" --edge "$OUT" 6 2>&1 | tee "$OUT/general_edge_log.txt"
  [ "${PIPESTATUS[0]}" = 0 ] || exit 1
  /usr/bin/python3 "$ROOT/benchmarks/plot.py" --general "$OUT"
  /usr/bin/python3 "$ROOT/benchmarks/tables.py" --general "$OUT"
  exit 0
fi
# benchmarks/run.sh --edge: spheres at 2^-k from exact tangencies (a few minutes) ->
# benchmarks/results/edge.csv, edge_log.txt and near_tangency.png (doc/performance.md, "Near tangency").
if [ "${1:-}" = "--edge" ]; then
  cmake --build "$BUILD" -j2 --target edge_bench
  mkdir -p "$OUT"
  "$BUILD/benchmarks/edge_bench" --out "$OUT" 2>&1 | tee "$OUT/edge_log.txt"
  /usr/bin/python3 "$ROOT/benchmarks/plot.py" --edge "$OUT"
  /usr/bin/python3 "$ROOT/benchmarks/tables.py" --edge "$OUT"
  exit 0
fi
cmake --build "$BUILD" -j2 --target relpos_bench
mkdir -p "$OUT"
"$BUILD/benchmarks/relpos_bench" --seed "$SEED" --out "$OUT" "$@" 2>&1 | tee "$OUT/log.txt"

PY=/usr/bin/python3
if ! "$PY" -c 'import matplotlib' 2>/dev/null; then
  if command -v apt-get >/dev/null && [ "$(id -u)" = 0 ]; then
    apt-get install -y python3-matplotlib >/dev/null
  else
    echo "matplotlib missing for $PY: install python3-matplotlib to draw the charts" >&2
    exit 1
  fi
fi
"$PY" "$ROOT/benchmarks/plot.py" "$OUT"
/usr/bin/python3 "$ROOT/benchmarks/tables.py" "$OUT"
