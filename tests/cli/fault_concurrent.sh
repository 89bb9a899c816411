#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Two writers of the same output started together, a few rounds: the same
# command twice, and the command beside one with other parameters. Each
# exits 0 or fails with one message naming the output, at least one
# succeeds, the output is byte for byte the file one of them writes when run
# alone (never a mix of the two), oiiotool reads it, and no temporary is left.
#   fault_concurrent.sh CMF SRC WORK
# CMFILTER_FAULT_ROUNDS: rounds a kind (4; 2 in a sanitized build, whose runs
# are slower: one of each pairing).
set -u
source "$(dirname "$0")/fault_commands.sh"
fault_setup "$1" "$2" "$3"
rounds=${CMFILTER_FAULT_ROUNDS:-4}

for kind in table moments render; do
  for variant in 0 1; do
    fault_command "$kind" "$WORK/alone-$variant.exr" "$variant"
    run_cmd
    [ "$rc" = 0 ] || { echo "FAIL: $kind run alone failed: $(cat "$WORK/last.err")"; exit 1; }
  done
  out=$WORK/$kind.exr
  for ((r = 0; r < rounds; ++r)); do
    rm -f "$out"
    second=$((r % 2))  # even rounds: the same command twice
    fault_command "$kind" "$out" 0
    "${CMD[@]}" >/dev/null 2>"$WORK/first.err" &
    first_pid=$!
    fault_command "$kind" "$out" "$second"
    "${CMD[@]}" >/dev/null 2>"$WORK/second.err" &
    second_pid=$!
    wait "$first_pid"
    first_rc=$?
    wait "$second_pid"
    second_rc=$?
    echo "$kind round $r (second run variant $second): exits $first_rc and $second_rc"
    for which in first second; do
      code=${which}_rc
      [ "${!code}" = 0 ] && continue
      echo "  $which: $(cat "$WORK/$which.err")"
      [ "$(error_lines "$WORK/$which.err")" = 1 ] || fail "$kind round $r: the failed $which run printed no single error"
      grep -qF "'$out'" "$WORK/$which.err" || fail "$kind round $r: the failed $which run does not name '$out'"
    done
    [ "$first_rc" = 0 ] || [ "$second_rc" = 0 ] || fail "$kind round $r: both runs failed"
    if same_but_date "$out" "$WORK/alone-0.exr"; then
      :
    elif [ "$second" = 1 ] && same_but_date "$out" "$WORK/alone-1.exr"; then
      :
    else
      fail "$kind round $r: $out is not the file either run writes alone"
    fi
    check_readable "$out"
    check_no_temporaries "$out"
  done
done
[ "$fail" = 0 ] && echo "every round left one whole file"
exit $fail
