#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# A disk that fills up while the output is written: each writer exits
# non-zero with one message naming its output and saying why, and leaves no
# output and no temporary. Twice: under RLIMIT_FSIZE (ulimit -f, with SIGXFSZ
# ignored, so write() fails with EFBIG), and on a real full disk, a 256 KiB
# tmpfs mounted in a mount namespace of the test's own (unshare -rm; skipped
# where the system allows none), so write() fails with ENOSPC.
#   fault_full_disk.sh CMF SRC WORK
set -u
source "$(dirname "$0")/fault_commands.sh"
fault_setup "$1" "$2" "$3"
limit_kb=64

for kind in table moments render; do
  out=$WORK/full-$kind.exr
  fault_command "$kind" "$out"
  # The file fits without the limit: the failure below is the limit's.
  run_cmd
  [ "$rc" = 0 ] || fail "$kind: the run without a limit failed: $(cat "$WORK/last.err")"
  size=$(stat -c %s "$out" 2>/dev/null || echo 0)
  [ "$size" -gt $((limit_kb * 1024)) ] || fail "$kind: the output ($size bytes) fits in $limit_kb KiB"
  rm -f "$out"
  (
    trap '' XFSZ
    ulimit -f "$limit_kb"
    exec "${CMD[@]}"
  ) >"$WORK/last.out" 2>"$WORK/last.err"
  rc=$?
  check_failed_cleanly "$out" "$out" "$kind under ulimit -f $limit_kb"
  grep -qF "file size limit of $((limit_kb * 1024)) bytes (ulimit -f)" "$WORK/last.err" ||
    fail "$kind: the message does not say the file reached the size limit"
done
mkdir -p "$WORK/disk"
if ! unshare -rm mount -t tmpfs -o size=256k tmpfs "$WORK/disk" 2>/dev/null; then
  echo "a full tmpfs: skipped (no mount namespace of our own: unshare -rm fails here)"
else
  for kind in table moments render; do
    out=$WORK/disk/full-$kind.exr
    fault_command "$kind" "$out"
    # The tmpfs lives as long as the namespace: what the run left on it is
    # listed there.
    unshare -rm bash -c 'mount -t tmpfs -o size=256k tmpfs "$1" || exit 99
      disk=$1; shift; "$@" >/dev/null 2>"$disk.err"; rc=$?; ls -A "$disk" >"$disk.left"; exit $rc' \
      _ "$WORK/disk" "${CMD[@]}"
    rc=$?
    cp "$WORK/disk.err" "$WORK/last.err"
    what="$kind on a full 256 KiB tmpfs"
    echo "$what: exit $rc: $(cat "$WORK/last.err")"
    [ "$rc" != 99 ] || { fail "$what: the tmpfs could not be mounted"; continue; }
    [ "$rc" != 0 ] || fail "$what: exit 0, expected a failure"
    [ "$(error_lines "$WORK/last.err")" = 1 ] || fail "$what: expected exactly one error from cmfilter on stderr"
    grep -qF -- "'$out'" "$WORK/last.err" || fail "$what: the message does not name '$out'"
    grep -qF "the disk holding '$WORK/disk' is full" "$WORK/last.err" || fail "$what: the message does not say the disk is full"
    [ ! -s "$WORK/disk.left" ] || fail "$what: left on the disk: $(cat "$WORK/disk.left")"
  done
fi
[ "$fail" = 0 ] && echo "every writer failed cleanly on a full disk"
exit $fail
