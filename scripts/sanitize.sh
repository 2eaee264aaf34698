#!/usr/bin/env bash
# Build the whole project with AddressSanitizer + UndefinedBehaviorSanitizer and run the test suite.
#   scripts/sanitize.sh
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build-asan -DRELPOS_BUILD_TESTS=ON -DRELPOS_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo
cd build-asan
# The pip test builds a separate uninstrumented package and the licence scan reads no code that runs:
# neither gains from the sanitizers.
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j"$(nproc)" -LE "pip|licence"
