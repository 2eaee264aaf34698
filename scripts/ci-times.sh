#!/usr/bin/env bash
# Time CI as a CI machine sees it: a fresh clone of the committed HEAD, no compiler cache, then .ci/run.
# Prints the time of each stage and step and the slowest tests of both CTest runs (doc/testing.md,
# "Time in CI"). The clone, its build directories and the log stay in WORK_DIR for inspection.
#   scripts/ci-times.sh [WORK_DIR]      (default: a new directory under /tmp)
# Wall-clock figures mean something only on an otherwise idle machine: the load average before and
# after is printed with them; the CPU seconds of each stage depend far less on other work.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
work=${1:-$(mktemp -d /tmp/relpos-ci-times.XXXXXX)}
mkdir -p "$work"
rm -rf "$work/relpos"
git clone -q "$repo" "$work/relpos"
# No cache; instead a launcher that logs the CPU seconds of every compiler call (CMake reads the
# variable from the environment, the pip test's inner build included).
cat >"$work/timed-compile" <<'SH'
#!/usr/bin/env bash
TIMEFORMAT='%U %S'
{ time "$@" 2>&3; } 3>&2 2>"$RELPOS_COMPILE_LOG.$$"
status=$?
out=; prev=
for a in "$@"; do [ "$prev" = -o ] && out=$a; prev=$a; done
echo "$(tail -n 1 "$RELPOS_COMPILE_LOG.$$") $PWD/$out" >>"$RELPOS_COMPILE_LOG"
rm -f "$RELPOS_COMPILE_LOG.$$"
exit $status
SH
chmod +x "$work/timed-compile"
export CMAKE_CXX_COMPILER_LAUNCHER=$work/timed-compile RELPOS_COMPILE_LOG=$work/compiles.log
unset CMAKE_C_COMPILER_LAUNCHER
rm -f "$RELPOS_COMPILE_LOG"
log=$work/ci.log
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
SECONDS=0
(cd "$work/relpos" && .ci/run) >"$log" 2>&1 || { tail -n 60 "$log"; echo "relpos: .ci/run failed (log: $log)"; exit 1; }
total=$SECONDS

echo "commit $(git -C "$work/relpos" rev-parse --short HEAD), $(nproc) cores, load average before $load_before," \
     "after $(cut -d' ' -f1-3 /proc/loadavg); log: $log"
echo
echo "| step | seconds |"
echo "|---|---|"
sed -n 's/^relpos: \(.*\) in \([0-9]*\) s$/| \1 | \2 |/p;
        s/^relpos: stage \(.*\) took \([0-9]*\) s (CPU \([0-9]*\) s user, \([0-9]*\) s system)$/| **stage \1** (CPU \3 + \4) | **\2** |/p' \
  "$log"
echo "| **.ci/run** | **$total** |"
echo
echo "Compiler CPU seconds (user + system) by build:"
awk -v root="$work/relpos/" '{
  path = substr($3, 1, length(root)) == root ? substr($3, length(root) + 1) : "(temporary: package tests)"
  if ($3 ~ /\/$/) path = "(no object file: cgal_licences preprocessing)"
  else if ((i = index(path, "/tests/check_headers/")) > 0) path = substr(path, 1, i - 1) "/tests/check_headers"
  else if ((i = index(path, "/tests/pip-test/")) > 0) path = substr(path, 1, i - 1) "/tests/pip-test (pip install)"
  else if ((i = index(path, "/")) > 0) path = substr(path, 1, i - 1)
  cpu[path] += $1 + $2; n[path]++ }
  END { for (p in cpu) printf "  %7.1f  %3d calls  %s\n", cpu[p], n[p], p }' "$RELPOS_COMPILE_LOG" | sort -rn
for build in build build-asan; do
  echo
  echo "Slowest tests in $build (seconds, CTest -j$(nproc)):"
  grep -v -e '^---' "$work/relpos/$build/Testing/Temporary/CTestCostData.txt" | awk 'NF == 3 { print $3, $1 }' |
    sort -rn | head -n 10 | awk '{ printf "  %6.1f  %s\n", $1, $2 }'
done
