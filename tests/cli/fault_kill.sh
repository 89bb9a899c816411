#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# A writer killed (SIGKILL) at a spread of moments, from its start to its
# end (denser towards the end, where the output is written: the i-th of n
# at sqrt(i / (n - 1)) of a whole run's time): after each kill the output is what it was before the run (nothing, or
# the previous complete file, byte for byte) or the run's whole new file,
# never part of one; what the killed runs left beside it are temporaries
# named .<stem>.tmp-<host>-<pid>-<hex><ext> with a killed process's id (each
# run removes those it finds, unless it is killed before it gets there); and
# a run after the kills succeeds, removes the leftovers and writes a file
# oiiotool reads. Two series: one without a file before the first kill, one with a
# previous file (the same command with other parameters).
#   fault_kill.sh CMF SRC WORK KIND    KIND: table, moments or render
# CMFILTER_FAULT_KILLS: kills a series (15; fewer in a sanitized build,
# whose runs are slower).
set -u
source "$(dirname "$0")/fault_commands.sh"
fault_setup "$1" "$2" "$3"
kind=$4
kills=${CMFILTER_FAULT_KILLS:-15}
out=$WORK/out.exr

# The new file and the previous one, each written by a run left alone; the
# new run's time spreads the kills.
fault_command "$kind" "$WORK/reference.exr"
start=$(date +%s%N)
run_cmd
end=$(date +%s%N)
[ "$rc" = 0 ] || { echo "FAIL: the run to compare with failed: $(cat "$WORK/last.err")"; exit 1; }
run_ms=$(((end - start) / 1000000))
echo "${CMD[*]}: $run_ms ms"
fault_command "$kind" "$WORK/previous.exr" 1
run_cmd
[ "$rc" = 0 ] || { echo "FAIL: the run of the previous file failed: $(cat "$WORK/last.err")"; exit 1; }
same_but_date "$WORK/reference.exr" "$WORK/previous.exr" && { echo "FAIL: the previous file equals the new one"; exit 1; }
fault_command "$kind" "$WORK/again.exr"
run_cmd
same_but_date "$WORK/reference.exr" "$WORK/again.exr" || { echo "FAIL: two runs of ${CMD[*]} differ"; exit 1; }

for series in none previous; do
  rm -f "$out" "$WORK/before.exr"
  if [ "$series" = previous ]; then cp "$WORK/previous.exr" "$out" && cp "$out" "$WORK/before.exr"; fi
  left=0 killed=""
  for ((i = 0; i < kills; ++i)); do
    delay_ms=$(awk -v t="$run_ms" -v i="$i" -v n="$kills" 'BEGIN { printf "%d", t * sqrt(i / (n - 1)) }')
    fault_command "$kind" "$out"
    "${CMD[@]}" >/dev/null 2>&1 &
    pid=$!
    killed="$killed $pid"
    sleep "$((delay_ms / 1000)).$(printf '%03d' $((delay_ms % 1000)))"
    kill -KILL "$pid" 2>/dev/null
    wait "$pid"
    status=$?
    if [ ! -e "$out" ]; then
      state="no file"
      [ -e "$WORK/before.exr" ] && fail "kill at $delay_ms ms: $out is gone (it held a complete file before)"
    elif [ -e "$WORK/before.exr" ] && cmp -s "$out" "$WORK/before.exr"; then
      state="the file before"
    elif same_but_date "$out" "$WORK/reference.exr"; then
      state="the whole new file"
    else
      state="a file that is neither the one before nor the new one"
      fail "kill at $delay_ms ms: $out is neither the file before the run nor the whole new file"
    fi
    check_temporaries_named "$out" "$killed"
    n=$(temporaries_of "$out" | grep -c . || true)
    left=$((left + n))
    echo "series '$series', kill at $delay_ms ms: exit $status, $state, $n temporary file(s) left"
    rm -f "$WORK/before.exr"
    [ -e "$out" ] && cp "$out" "$WORK/before.exr"
  done
  echo "series '$series': $left of $kills kills left a temporary"
  # The run after the kills.
  fault_command "$kind" "$out"
  run_cmd
  [ "$rc" = 0 ] || fail "the run after the kills failed (exit $rc): $(cat "$WORK/last.err")"
  check_no_temporaries "$out"
  same_but_date "$out" "$WORK/reference.exr" || fail "the run after the kills wrote another file than the run alone"
  check_readable "$out"
done
[ "$fail" = 0 ] && echo "all kills left the output whole or as it was"
exit $fail
