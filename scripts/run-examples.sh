#!/usr/bin/env bash
# Set up what is missing, build, and classify the bundled examples (JSON Lines in, JSON Lines out).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build -DRELPOS_BUILD_TESTS=OFF
for f in examples/*.jsonl; do
  echo "== relpos batch $f"
  build/cli/relpos batch "$f"
done
