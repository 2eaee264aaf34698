#!/usr/bin/env bash
# SPDX-License-Identifier: LGPL-3.0-or-later
# The Python package installed the standard way, checked from outside: a copy of the source tree
# (no build directory), a fresh venv of Debian's interpreter, `pip install --no-build-isolation
# --no-index` (setup.py drives CMake), then from / with no PYTHONPATH: `import relpos` must come from
# the venv, classify the README's pair, find the CLI installed in the venv (not a build tree), and
# v/bin/relpos must answer the same pair.
#   check_pip.sh SOURCE_DIR WORK_DIR
set -euo pipefail
src=$1
work=$2
rm -rf "$work"
mkdir -p "$work/src"
trap 'rm -rf "$work"' EXIT
tar -C "$src" --exclude='./build*' --exclude=./.git --exclude='*/__pycache__' -cf - . | tar -C "$work/src" -xf -
unset PYTHONPATH RELPOS_CLI

/usr/bin/python3 -m venv --system-site-packages "$work/v"
start=$(date +%s)
"$work/v/bin/pip" install --no-build-isolation --no-index "$work/src" >"$work/pip.log" 2>&1 ||
  { cat "$work/pip.log"; exit 1; }
echo "pip install: $(( $(date +%s) - start )) s"
rm -rf "$work/src"  # the installed package must not need its source or build tree

cd /
"$work/v/bin/python" - "$work/v" <<'PY'
import os, sys
import relpos, relpos._build, relpos._cli
venv = os.path.realpath(sys.argv[1])
where = os.path.realpath(relpos.__file__)
assert where.startswith(venv + os.sep), "relpos imported from %s, not from the venv" % where
assert relpos._build.build_tree_cli is None, relpos._build.build_tree_cli
cli = os.path.realpath(relpos._cli.find_cli())
assert cli == os.path.join(venv, "bin", "relpos"), cli
p = relpos.Paraboloid.standard((0, 0, 0), "1.2", "1.5")
e = relpos.Ellipsoid.sphere((0, "0.5", "92281/129600"), "1/4")
assert relpos.classify(e, p).position == "I"
print("import relpos %s from %s; CLI %s" % (relpos.__version__, where, cli))
PY
# Typing files shipped with the sources are installed with the package.
site=$("$work/v/bin/python" -c 'import os, relpos; print(os.path.dirname(relpos.__file__))')
for f in $(cd "$src/python/relpos" && ls *.pyi py.typed 2>/dev/null); do
  [ -f "$site/$f" ] || { echo "not installed: relpos/$f"; exit 1; }
done
"$work/v/bin/relpos" --help >/dev/null
out=$("$work/v/bin/relpos" classify --sphere "0,1/2,92281/129600,1/4" --standard-paraboloid "6/5,3/2")
echo "$out" | grep -q "^position: I " || { echo "v/bin/relpos classify printed: $out"; exit 1; }
echo "v/bin/relpos: $(echo "$out" | head -n1)"
