#!/usr/bin/env bash
# CTest ordinary_bench: a relpos build installed into a temporary prefix, benchmarks/ordinary built
# against it and run with --quick. It fails when relpos's paths (decide_position on prebuilt objects,
# from_doubles + decide_position, decide_position on the doubles in one call, classify with full
# evidence) disagree with classify_exact on a pair, when a certificate is rejected, or when a float
# decision is wrong on more than 1 % of the pairs; no time is checked.
#   benchmarks/ordinary/check_quick.sh BUILD_DIR [CMAKE]
set -euo pipefail
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
bash "$(dirname "$0")/build.sh" "$1" "$work" "${2:-cmake}"
"$work/build/ordinary_bench" --quick --out "$work/quick.json"
