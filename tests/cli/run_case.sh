#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# One command-line test case: runs a command and checks its exit code, that
# stderr matches a pattern and holds exactly one "error:" line (errors are
# printed once), and that the named outputs (and no temporary files beside
# them) exist afterwards.
#   run_case.sh --exit N [--stderr ERE] [--stdout ERE] [--absent PATH]... -- CMD ARGS...
set -u
want_exit=0; want_err=""; want_out=""; absent=()
while [ $# -gt 0 ]; do
  case "$1" in
    --exit) want_exit=$2; shift 2 ;;
    --stderr) want_err=$2; shift 2 ;;
    --stdout) want_out=$2; shift 2 ;;
    --absent) absent+=("$2"); shift 2 ;;
    --) shift; break ;;
    *) echo "run_case.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
for p in "${absent[@]+"${absent[@]}"}"; do rm -f "$p"; done
out=$(mktemp); err=$(mktemp)
trap 'rm -f "$out" "$err"' EXIT
"$@" >"$out" 2>"$err"
code=$?
fail=0
echo "command: $*"; echo "exit: $code"; echo "stderr:"; cat "$err"; echo "stdout:"; head -c 4000 "$out"
if [ "$code" != "$want_exit" ]; then echo "FAIL: exit code $code, expected $want_exit"; fail=1; fi
if [ -n "$want_err" ] && ! grep -Eq -- "$want_err" "$err"; then echo "FAIL: stderr does not match /$want_err/"; fail=1; fi
if [ -n "$want_out" ] && ! grep -Eq -- "$want_out" "$out"; then echo "FAIL: stdout does not match /$want_out/"; fail=1; fi
if [ "$want_exit" != 0 ]; then
  n=$(grep -c "error:" "$err")
  if [ "$n" != 1 ]; then echo "FAIL: expected exactly one 'error:' line on stderr, found $n"; fail=1; fi
fi
for p in "${absent[@]+"${absent[@]}"}"; do
  if [ -e "$p" ]; then echo "FAIL: $p exists but should not"; fail=1; fi
  # AtomicOutput's temporary files are ".<stem>.tmp-<host>-<pid>-<hex><ext>"
  # beside the destination; only this output's own count (other tests write beside it).
  dir=$(dirname "$p"); base=$(basename "$p"); stem=${base%.*}
  if [ -d "$dir" ] && ls -a "$dir" | grep -qF ".$stem.tmp-"; then echo "FAIL: temporary file of $p left in $dir"; fail=1; fi
done
exit $fail
