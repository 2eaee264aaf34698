#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-3.0-or-later
# Runs a C++ example (examples/cpp/) and compares what it prints with the "// Output:" comment that
# ends its source, so the output shown to readers is the output it gives.
#   check_cpp_example.sh EXECUTABLE SOURCE
set -euo pipefail
exe=$1
source=$2
expected=$(sed -n '/^\/\/ Output:$/,$p' "$source" | tail -n +2 | sed 's|^// \{0,1\}||')
[ -n "$expected" ] || { echo "$source has no '// Output:' block"; exit 1; }
actual=$("$exe")
if [ "$actual" != "$expected" ]; then
  diff <(echo "$expected") <(echo "$actual") || true
  echo "$exe: output differs from the '// Output:' block of $source (< expected, > actual)"
  exit 1
fi
echo "$(basename "$source"): output as documented"
