#!/usr/bin/env bash
# Check `relpos motion` end to end: answers known by construction (doc/math.md §7), the JSON
# fields, the text report and the exit codes.
#
# Usage: tests/cli/check_motion.sh PATH/TO/relpos
# Exits 0 when everything matches, 1 on any mismatch, 2 on a usage error.
set -u
if [ $# -ne 1 ] || [ ! -x "$1" ]; then
  echo "usage: $0 PATH/TO/relpos" >&2
  exit 2
fi
relpos=$1
fail=0
check() {  # check NAME CONDITION-RESULT
  if [ "$2" != 0 ]; then
    echo "FAIL: $1"
    fail=1
  else
    echo "ok:   $1"
  fi
}

# 1. Contact at sqrt(2) on the axis of z = x^2 + y^2/4 (TE), then TI at sqrt(5/2).
out=$("$relpos" motion --sphere 0,0,0,1/4 --standard-paraboloid 1,2 --translation '[[], [], ["-9/4", 0, 1]]' \
  --t0 0 --t1 2 --digits 30 --json)
check "sqrt(2) run exits 0" $?
/usr/bin/python3 - "$out" <<'EOF'
import json, sys
j = json.loads(sys.argv[1])
fc = j["first_contact"]
assert fc["kind"] == "contact", fc
assert fc["position"] == "TE", fc
assert fc["time"]["decimal"] == "1.41421356237309504880168872421", fc["time"]
assert fc["time"]["polynomial"] == ["-2", "0", "1"], fc["time"]
assert fc["time"]["exact"] is None
spans = [s["position"] for s in j["timeline"]["spans"]]
assert spans == ["E", "TE", "C", "TI", "I"], spans
changes = j["timeline"]["changes"]
assert [(c["before"], c["at"], c["after"]) for c in changes] == [("E", "TE", "C"), ("C", "TI", "I")], changes
assert changes[1]["time"]["polynomial"] == ["-5", "0", "2"], changes[1]
assert j["timeline"]["discriminant_identically_zero"] is False
EOF
check "sqrt(2) JSON: first contact, spans, changes, minimal polynomials" $?

# 2. Rational contact 17/15 through the wall of z = x^2 + y^2, first contact only, text report.
out=$("$relpos" motion --sphere 0,0,0,0.25 --standard-paraboloid 1,1 --translation '[[2, -1], 0, ["53/180"]]' \
  --t0 0 --t1 4 --first-contact)
check "17/15 run exits 0" $?
echo "$out" | grep -q "first contact: t\* = 1.13333333333  (exactly 17/15)"
check "17/15 text report" $?
echo "$out" | grep -q "^timeline"
check "--first-contact prints no timeline" $((1 - $?))

# 3. A rotating ellipsoid (world frame, pivot at its centre) grazing the vertex at t = 1.
out=$("$relpos" motion --ellipsoid '{"center":[0,0,-1],"axes":["1/2",1,"1/4"]}' --standard-paraboloid 1,2 \
  --rotation '[[1],[0,1],[],[]]' --pivot center --t0 0 --t1 2 --json)
check "rotation run exits 0" $?
/usr/bin/python3 - "$out" <<'EOF'
import json, sys
j = json.loads(sys.argv[1])
assert j["first_contact"]["time"]["exact"] == "1", j["first_contact"]
assert j["motion"]["pivot"] == ["0", "0", "-1"], j["motion"]
assert [s["position"] for s in j["timeline"]["spans"]] == ["E", "TE", "E"]
EOF
check "rotation JSON: grazing TE at t = 1" $?

# 4. Contact at t0 is a result.
out=$("$relpos" motion --sphere 0,0,0,1/4 --standard-paraboloid 1,2 --translation '[[], [], ["-1/4", 1]]' \
  --t0 0 --t1 1 --first-contact --json)
/usr/bin/python3 - "$out" <<'EOF'
import json, sys
fc = json.loads(sys.argv[1])["first_contact"]
assert fc["kind"] == "not-exterior-at-start" and fc["position"] == "TE" and fc["time"]["exact"] == "0", fc
EOF
check "contact at t0" $?

# 5. Exit codes: usage errors 2, input errors 1.
"$relpos" motion --sphere 0,0,0,1/4 --standard-paraboloid 1,2 --t0 0 >/dev/null 2>&1
check "missing --t1 is a usage error (2)" $(($? != 2))
"$relpos" motion --sphere 0,0,0,1/4 --standard-paraboloid 1,2 --t0 0 --t1 1 --bogus >/dev/null 2>&1
check "unknown option is a usage error (2)" $(($? != 2))
"$relpos" motion --sphere 0,0,0,1/4 --standard-paraboloid 1,2 --t0 1 --t1 0 >/dev/null 2>&1
check "t0 > t1 is an input error (1)" $(($? != 1))
"$relpos" motion --sphere 0,0,0,1/4 --standard-paraboloid 1,2 --rotation '[[-1,1],[1,-1],[],[]]' --t0 0 --t1 2 \
  >/dev/null 2>&1
check "a quaternion vanishing on [t0, t1] is an input error (1)" $(($? != 1))
"$relpos" motion --sphere 0,0,0,1/4 --standard-paraboloid 1,2 --translation '[[1],[2]]' --t0 0 --t1 1 \
  >/dev/null 2>&1
check "a translation with 2 components is an input error (1)" $(($? != 1))
err=$("$relpos" motion --sphere 0,0,0,1/4 --quadric '[[1,0,0,0],[0,1,0,0],[0,0,-1,0],[0,0,0,-1]]' --t0 0 --t1 1 \
  2>&1 >/dev/null)
check "a general quadric is a usage error (2) saying what is not supported" \
  $(($? != 2 || $(echo "$err" | grep -c "elliptic paraboloid only") != 1))
"$relpos" motion --help | grep -q "Usage: relpos motion"
check "motion --help" $?

exit $fail
