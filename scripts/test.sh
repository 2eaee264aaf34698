#!/usr/bin/env bash
# Set up what is missing, build everything, and run the whole test suite (CTest).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build -DRELPOS_BUILD_TESTS=ON
cd build
ctest --output-on-failure -j"$(nproc)"
