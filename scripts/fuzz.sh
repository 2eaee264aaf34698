#!/usr/bin/env bash
# Build the libFuzzer harnesses (fuzz/: clang, -fsanitize=fuzzer,address,undefined) and run each one
# for a while, starting from the seed corpus in fuzz/corpus/<harness>/ (doc/testing.md).
#   scripts/fuzz.sh [SECONDS_PER_HARNESS]      (default 60; CI runs the default)
# New corpus entries go to build-fuzz/corpus-<harness>/ (not into the repository); a crash, a
# sanitizer report, an input slower than 60 s or an invariant violation stops the script with the
# reproducer in build-fuzz/artifacts/. Replay one with build-fuzz/fuzz_<harness> FILE.
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_PER=${1:-60}

# What the library needs (as in scripts/setup.sh) plus clang and its libFuzzer runtime.
PACKAGES=(clang libclang-rt-14-dev make cmake libcgal-dev libgmp-dev libmpfr-dev libmpfi-dev libboost-dev nlohmann-json3-dev
          libflint-dev)
scripts/install-packages.sh "${PACKAGES[@]}"

cmake -S fuzz -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ >/dev/null
cmake --build build-fuzz -j"$(nproc)"
mkdir -p build-fuzz/artifacts
for harness in numbers batch_line classify; do
  work=build-fuzz/corpus-$harness
  mkdir -p "$work"
  options=(-max_total_time="$SECONDS_PER" -timeout=60 -rss_limit_mb=2048 -print_final_stats=1
           -artifact_prefix="build-fuzz/artifacts/$harness-")
  [ -f "fuzz/$harness.dict" ] && options+=(-dict="fuzz/$harness.dict")
  [ "$harness" = classify ] && options+=(-max_len=256) || options+=(-max_len=4096)
  log=build-fuzz/fuzz-$harness.log
  echo "== fuzz_$harness for ${SECONDS_PER} s"
  if ! build-fuzz/fuzz_$harness "${options[@]}" "$work" "fuzz/corpus/$harness" >"$log" 2>&1; then
    tail -n 60 "$log"
    echo "relpos: fuzz_$harness found a defect; reproducer in build-fuzz/artifacts/ (see doc/testing.md)"
    exit 1
  fi
  grep -E "^(Done|stat::number_of_executed_units|stat::new_units_added|stat::peak_rss_mb)" "$log" || true
done
