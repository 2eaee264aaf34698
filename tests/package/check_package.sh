#!/usr/bin/env bash
# The installed package, checked from outside: `cmake --install` into a temporary prefix, then the
# consumer project (tests/package/consumer) built with find_package(relpos CONFIG REQUIRED), linked
# with librelpos.a and with librelpos.so, configured without a build type and without a warning, and
# built with `g++ $(pkg-config --cflags --libs relpos)`; each must print what
# examples/cpp/classify_text.cpp documents. Every installed header must compile on its own with the
# pkg-config flags, and none may reach a header of nlohmann_json (a build-only dependency: the package
# names it nowhere, and a consumer needs it neither to compile nor to link).
#   check_package.sh BUILD_DIR CONSUMER_SOURCE_DIR [CMAKE [SHARED]]   (SHARED: ON unless RELPOS_BUILD_SHARED=OFF)
set -euo pipefail
build=$1
consumer=$2
cmake=${3:-cmake}
shared=${4:-ON}
example=$consumer/../../../examples/cpp/classify_text.cpp
check_output=$(dirname "$0")/../examples/check_cpp_example.sh
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix

"$cmake" --install "$build" --prefix "$prefix" >"$tmp/install.log" || { cat "$tmp/install.log"; exit 1; }
for f in include/relpos/classify.hpp include/relpos/version.hpp bin/relpos; do
  [ -e "$prefix/$f" ] || { echo "not installed: $f"; exit 1; }
done
libdir=$(dirname "$(find "$prefix" -name librelpos.a | head -n1)")
apps=app
if [ "$shared" = ON ]; then
  [ -e "$libdir/librelpos.so" ] || { echo "not installed: librelpos.so"; exit 1; }
  apps="app app_shared"
fi
[ -f "$libdir/pkgconfig/relpos.pc" ] || { echo "not installed: relpos.pc"; exit 1; }
[ -n "$(find "$prefix" -name relposConfig.cmake)" ] || { echo "not installed: relposConfig.cmake"; exit 1; }

# 1. CMake: find_package + relpos::relpos and relpos::relpos_shared (only the prefix is given).
"$cmake" -S "$consumer" -B "$tmp/cmake-build" -DCMAKE_PREFIX_PATH="$prefix" \
  >"$tmp/configure.log" 2>&1 || { cat "$tmp/configure.log"; exit 1; }
if grep -q "Warning" "$tmp/configure.log"; then
  cat "$tmp/configure.log"; echo "find_package(relpos) gave the consumer a warning"; exit 1
fi
"$cmake" --build "$tmp/cmake-build" >"$tmp/build.log" 2>&1 || { cat "$tmp/build.log"; exit 1; }
for app in $apps; do
  bash "$check_output" "$tmp/cmake-build/$app" "$example" >/dev/null
done
# ldd's output kept first: with pipefail, `ldd | grep -q` fails when grep stops at the match and ldd
# then gets SIGPIPE.
if [ "$shared" = ON ]; then
  libs=$(ldd "$tmp/cmake-build/app_shared")
  grep -q "librelpos.so" <<<"$libs" || { echo "app_shared does not load librelpos.so"; exit 1; }
fi
libs=$(ldd "$tmp/cmake-build/app")
! grep -q "librelpos.so" <<<"$libs" || { echo "app (relpos::relpos) loads librelpos.so"; exit 1; }
echo "find_package consumers ($apps): output as documented"

# The exported target must not impose build-only flags on its users.
if grep -rqE "ffp-contract|frounding-math" "$(dirname "$(find "$prefix" -name relposConfig.cmake)")"; then
  echo "build-only flags in the exported usage requirements"; exit 1
fi

# 2. pkg-config (-lrelpos links librelpos.so when it is installed, so the rpath is given).
export PKG_CONFIG_PATH=$libdir/pkgconfig
flags=$(pkg-config --cflags --libs relpos)
g++ -std=c++17 -O1 "$example" -o "$tmp/app-pc" $flags -Wl,-rpath,"$libdir" 2>"$tmp/pc.log" ||
  { cat "$tmp/pc.log"; exit 1; }
bash "$check_output" "$tmp/app-pc" "$example" >/dev/null
echo "pkg-config consumer: output as documented ($flags)"

# 3. Every installed public header compiles on its own, with only the pkg-config flags, and includes
# no header of nlohmann_json, directly or through another (g++ -M lists every header it reads).
for h in "$prefix"/include/relpos/*.hpp "$prefix"/include/relpos/internal/*.hpp; do
  name=${h#"$prefix"/include/}
  echo "#include <$name>" >"$tmp/one.cpp"
  g++ -std=c++17 -fsyntax-only -Wall -Wextra -Werror $(pkg-config --cflags relpos) "$tmp/one.cpp" 2>"$tmp/one.log" ||
    { cat "$tmp/one.log"; echo "$name does not compile on its own"; exit 1; }
  if g++ -std=c++17 -M $(pkg-config --cflags relpos) "$tmp/one.cpp" | grep -q nlohmann; then
    echo "$name reaches a header of nlohmann_json"; exit 1
  fi
done
echo "installed headers compile alone, none reaches nlohmann_json: $(ls "$prefix"/include/relpos/*.hpp \
  "$prefix"/include/relpos/internal/*.hpp | wc -l)"
if grep -rqi nlohmann "$(dirname "$(find "$prefix" -name relposConfig.cmake)")" "$libdir/pkgconfig/relpos.pc"; then
  echo "the installed package names nlohmann_json"; exit 1
fi
