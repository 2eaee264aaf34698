#!/usr/bin/env bash
# The installed package, checked from outside: `cmake --install` into a temporary prefix, then the
# consumer project (tests/package/consumer) built once with find_package(relpos CONFIG REQUIRED) and
# once with `g++ $(pkg-config --cflags --libs relpos)`; both must print the README example's answer, I.
#   check_package.sh BUILD_DIR CONSUMER_SOURCE_DIR [CMAKE]
set -euo pipefail
build=$1
consumer=$2
cmake=${3:-cmake}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix

"$cmake" --install "$build" --prefix "$prefix" >"$tmp/install.log" || { cat "$tmp/install.log"; exit 1; }
for f in include/relpos/classify.hpp bin/relpos; do
  [ -e "$prefix/$f" ] || { echo "not installed: $f"; exit 1; }
done
libdir=$(dirname "$(find "$prefix" -name librelpos.a | head -n1)")
[ -f "$libdir/pkgconfig/relpos.pc" ] || { echo "not installed: relpos.pc"; exit 1; }
[ -n "$(find "$prefix" -name relposConfig.cmake)" ] || { echo "not installed: relposConfig.cmake"; exit 1; }

# 1. CMake: find_package + relpos::relpos (only the prefix is given).
"$cmake" -S "$consumer" -B "$tmp/cmake-build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" \
  >"$tmp/configure.log" 2>&1 || { cat "$tmp/configure.log"; exit 1; }
"$cmake" --build "$tmp/cmake-build" >"$tmp/build.log" 2>&1 || { cat "$tmp/build.log"; exit 1; }
out=$("$tmp/cmake-build/app")
[ "$out" = "I" ] || { echo "find_package consumer printed '$out', expected I"; exit 1; }
echo "find_package consumer: $out"

# The exported target must not impose build-only flags on its users.
if grep -rqE "ffp-contract|frounding-math" "$(dirname "$(find "$prefix" -name relposConfig.cmake)")"; then
  echo "build-only flags in the exported usage requirements"; exit 1
fi

# 2. pkg-config.
export PKG_CONFIG_PATH=$libdir/pkgconfig
flags=$(pkg-config --cflags --libs relpos)
g++ -std=c++17 -O1 "$consumer/main.cpp" -o "$tmp/app-pc" $flags 2>"$tmp/pc.log" || { cat "$tmp/pc.log"; exit 1; }
out=$("$tmp/app-pc")
[ "$out" = "I" ] || { echo "pkg-config consumer printed '$out', expected I"; exit 1; }
echo "pkg-config consumer: $out ($flags)"
