#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# compare --warn / --fail / --gate: the exit code says which threshold the
# chosen CIEDE2000 statistic exceeds (5 warn, 6 fail), strictly over, with a
# line on stderr; thresholds either side of each statistic (read from the
# run's own --json, whose values tests elsewhere check against independent
# computations) flip the result; bad thresholds and statistics exit 3.
#   check_compare_gates.sh CMFILTER A B
set -uo pipefail
cmf=$1 a=$2 b=$3
fail=0
stat() { "$cmf" compare "$a" "$b" --json | python3 -c "import json,sys; print(json.load(sys.stdin)['ciede2000']['$1'])"; }
scale() { python3 -c "print(repr($1 * $2))"; }
expect() {  # expect CODE PATTERN ARGS...
  local code=$1 pattern=$2; shift 2
  local err rc
  err=$("$cmf" compare "$@" 2>&1 >/dev/null); rc=$?
  if [ "$rc" != "$code" ]; then echo "FAIL: compare $* exited $rc, expected $code: $err"; fail=1; return; fi
  if [ -n "$pattern" ] && ! grep -qE -- "$pattern" <<< "$err"; then
    echo "FAIL: compare $* printed '$err', expected /$pattern/"; fail=1
  fi
}
mean=$(stat mean) p95=$(stat p95) max=$(stat max)
echo "mean $mean p95 $p95 max $max"
python3 -c "import sys; sys.exit(0 if 0 < $mean < $max else 1)" || { echo "FAIL: the fixture needs 0 < mean < max"; exit 1; }
expect 6 "^cmfilter compare: FAIL: CIEDE2000 max .* > --fail" "$a" "$b" --fail "$(scale "$max" 0.999)"
expect 0 "" "$a" "$b" --fail "$(scale "$max" 1.001)"
expect 0 "" "$a" "$b" --fail "$max"                       # strictly over
expect 5 "^cmfilter compare: WARN: CIEDE2000 max" "$a" "$b" --warn "$(scale "$max" 0.5)" --fail "$(scale "$max" 2)"
expect 6 "FAIL" "$a" "$b" --warn "$(scale "$max" 0.5)" --fail "$(scale "$max" 0.9)"
expect 0 "" "$a" "$b" --gate mean --fail "$(scale "$mean" 1.001)"
expect 6 "FAIL: CIEDE2000 mean" "$a" "$b" --gate mean --fail "$(scale "$mean" 0.999)"
expect 6 "FAIL: CIEDE2000 p95" "$a" "$b" --gate p95 --fail "$(scale "$p95" 0.999)" -q
expect 0 "" "$a" "$a" --fail 0                              # identical images pass a zero gate
expect 3 "--fail -1(\\.0+)? is invalid" "$a" "$b" --fail -1
expect 3 "--gate 'median' is unknown \\(expected mean, p95 or max\\)" "$a" "$b" --gate median --fail 1
# The JSON says which gate ran and what it found, with typed values.
json=$("$cmf" compare "$a" "$b" --json --fail "$(scale "$max" 0.999)" 2>/dev/null); rc=$?
[ "$rc" = 6 ] || { echo "FAIL: --json --fail exited $rc"; fail=1; }
python3 - "$json" "$max" <<'PY' || fail=1
import json, sys
g = json.loads(sys.argv[1])["gate"]
ok = (g["statistic"] == "max" and g["result"] == "fail" and g["exit_code"] == 6 and g["warn"] is None
      and isinstance(g["value"], float) and g["value"] == float(sys.argv[2]))
print("gate json:", g)
sys.exit(0 if ok else 1)
PY
exit $fail
