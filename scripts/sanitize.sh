#!/usr/bin/env bash
# Build the library, the CLI and the tests with AddressSanitizer + UndefinedBehaviorSanitizer and run
# every test that runs relpos code.
#   scripts/sanitize.sh
set -euo pipefail
cd "$(dirname "$0")/.."
# -O1 -g1 rather than RelWithDebInfo's -O2 -g: the optimisation level ASan's documentation advises, and
# line tables are all a sanitizer's stack trace needs; it halves the compile time of the CGAL-heavy
# sources, which is most of this script's time (doc/testing.md, "Time in CI").
# The ladder's per-stage counters are compiled in here (RELPOS_STAGE_COUNTERS, src/decide/counters.hpp): the
# one build that exercises the option, and test_ladder then checks the library's own counts too.
scripts/setup.sh build-asan -DRELPOS_BUILD_TESTS=ON -DRELPOS_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DRELPOS_STAGE_COUNTERS=ON
cd build-asan
# Skipped: the pip test (it builds a separate uninstrumented package) and the tests labelled static
# (documentation, include floors, header compilation and licence scans: no relpos code runs in them).
SECONDS=0
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j"$(nproc)" -LE "pip|static"
echo "relpos: sanitizer CTest run in $SECONDS s"
