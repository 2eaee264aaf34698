#!/usr/bin/env bash
# Install a relpos build into WORK/prefix and build benchmarks/ordinary against it in WORK/build:
# WORK/build/ordinary_bench and WORK/prefix/bin/relpos are then what a user of the package has.
#   benchmarks/ordinary/build.sh BUILD_DIR WORK_DIR [CMAKE]
set -euo pipefail
build=$1
work=$2
cmake=${3:-cmake}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
mkdir -p "$work"
"$cmake" --install "$build" --prefix "$work/prefix" >"$work/install.log" || { cat "$work/install.log"; exit 1; }
"$cmake" -S "$here" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" >"$work/configure.log" 2>&1 ||
  { cat "$work/configure.log"; exit 1; }
"$cmake" --build "$work/build" >"$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
