#!/usr/bin/env bash
# Set up what is missing, build everything, and run the whole test suite (CTest).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build -DRELPOS_BUILD_TESTS=ON
cd build
SECONDS=0
ctest --output-on-failure -j"$(nproc)"
echo "relpos: CTest run in $SECONDS s"
