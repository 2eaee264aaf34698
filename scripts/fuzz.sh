#!/usr/bin/env bash
# Build the libFuzzer harnesses (fuzz/: clang, -fsanitize=fuzzer,address,undefined) and run each one
# for a while, as many at a time as there are cores, starting from the seed corpus in
# fuzz/corpus/<harness>/ (doc/testing.md).
#   scripts/fuzz.sh [SECONDS_PER_HARNESS]      (default 60; CI runs 30)
# New corpus entries go to build-fuzz/corpus-<harness>/ (not into the repository); a crash, a
# sanitizer report, an input slower than 60 s or an invariant violation fails the script with the
# reproducer in build-fuzz/artifacts/. Replay one with build-fuzz/fuzz_<harness> FILE.
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_PER=${1:-60}

# What the library needs (as in scripts/setup.sh) plus clang and its libFuzzer runtime.
PACKAGES=(clang libclang-rt-14-dev make cmake libcgal-dev libgmp-dev libmpfr-dev libmpfi-dev libboost-dev nlohmann-json3-dev
          libflint-dev)
scripts/install-packages.sh "${PACKAGES[@]}"

SECONDS=0
# -O1 -g1, as for scripts/sanitize.sh (and libFuzzer's documentation): three quarters of the compile
# time of -O2 -g (doc/testing.md, "Time in CI"); line tables are all a report's stack trace needs.
cmake -S fuzz -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" >/dev/null
cmake --build build-fuzz -j"$(nproc)"
echo "relpos: build-fuzz configured and built in $SECONDS s"
mkdir -p build-fuzz/artifacts

# One harness for SECONDS_PER seconds (libFuzzer runs on one core).
run_harness() {
  local harness=$1 work=build-fuzz/corpus-$1 log=build-fuzz/fuzz-$1.log
  mkdir -p "$work"
  local options=(-max_total_time="$SECONDS_PER" -timeout=60 -rss_limit_mb=2048 -print_final_stats=1
                 -artifact_prefix="build-fuzz/artifacts/$harness-")
  [ -f "fuzz/$harness.dict" ] && options+=(-dict="fuzz/$harness.dict")
  [ "$harness" = classify ] && options+=(-max_len=256) || options+=(-max_len=4096)
  echo "== fuzz_$harness for ${SECONDS_PER} s"
  if ! build-fuzz/fuzz_$harness "${options[@]}" "$work" "fuzz/corpus/$harness" >"$log" 2>&1; then
    tail -n 60 "$log"
    echo "relpos: fuzz_$harness found a defect; reproducer in build-fuzz/artifacts/ (see doc/testing.md)"
    return 1
  fi
  grep -E "^(Done|stat::number_of_executed_units|stat::new_units_added|stat::peak_rss_mb)" "$log" |
    sed "s/^/fuzz_$harness: /" || true
}
export -f run_harness
export SECONDS_PER
# As many harnesses at a time as there are cores, each still for the full SECONDS_PER seconds; xargs
# fails when one of them does.
SECONDS=0
printf '%s\n' classify batch_line numbers | xargs -P "$(nproc)" -I{} bash -c 'run_harness {}'
echo "relpos: fuzz runs in $SECONDS s"
