#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Outputs that cannot be written and inputs cut short: an output in a
# directory that is a file (and in a read-only directory, when not run as
# root, whom permissions do not stop), an output that is a directory, and
# inputs truncated to half their bytes or emptied. Each run exits non-zero
# with one message naming the file at fault and leaves nothing partial.
#   fault_bad_paths.sh CMF SRC WORK
set -u
source "$(dirname "$0")/fault_commands.sh"
fault_setup "$1" "$2" "$3"

for kind in table moments render; do
  # The output's directory is a file.
  touch "$WORK/plain"
  out=$WORK/plain/$kind.exr
  fault_command "$kind" "$out"
  run_cmd
  check_failed_cleanly "$out" "$out" "$kind into a directory that is a file"
  grep -qF "'$WORK/plain' is not a directory" "$WORK/last.err" || fail "$kind: the message does not name '$WORK/plain'"

  # A read-only directory.
  if [ "$(id -u)" = 0 ]; then
    echo "$kind into a read-only directory: skipped (root writes there anyway; the directory that is a file stands in)"
  else
    mkdir -p "$WORK/read-only" && chmod 555 "$WORK/read-only"
    out=$WORK/read-only/$kind.exr
    fault_command "$kind" "$out"
    run_cmd
    check_failed_cleanly "$out" "$out" "$kind into a read-only directory"
    chmod 755 "$WORK/read-only"
  fi

  # The output is a directory.
  out=$WORK/$kind-directory.exr
  mkdir -p "$out"
  fault_command "$kind" "$out"
  run_cmd
  echo "$kind onto a directory: exit $rc: $(cat "$WORK/last.err")"
  [ "$rc" != 0 ] || fail "$kind onto a directory: exit 0"
  grep -qF "'$out': it is a directory" "$WORK/last.err" || fail "$kind onto a directory: the message does not say so"
  [ -d "$out" ] && [ -z "$(ls -A "$out")" ] || fail "$kind onto a directory: the directory was changed"
  check_no_temporaries "$out"
done

# Inputs cut short: the table's colour map, the moment bake's driver, the
# render's sigma table (named by a scene written here), each truncated to
# half its bytes and, separately, emptied.
#   cut_and_run HOW SOURCE CUT OUTPUT WHAT CMD...: CUT, a copy of SOURCE cut
# to HOW (half or empty), read by CMD, which must fail naming it.
cut_and_run() {
  local how=$1 source=$2 cut=$3 output=$4 what=$5
  shift 5
  cp "$source" "$cut" || exit 1
  if [ "$how" = half ]; then truncate -s $(($(stat -c %s "$cut") / 2)) "$cut"; else : >"$cut"; fi
  CMD=("$@")
  run_cmd
  check_failed_cleanly "$output" "$cut" "$what cut to $how"
}
for how in half empty; do
  out=$WORK/cut-table-$how.exr
  cut_and_run "$how" "$SRC/luts/terrain.png" "$WORK/map-$how.png" "$out" "table from a colour map" \
    "$CMF" bake-colormap "$WORK/map-$how.png" -o "$out" -q
  out=$WORK/cut-moments-$how.exr
  cut_and_run "$how" "$WORK/driver.exr" "$WORK/driver-$how.exr" "$out" "moments from a driver" \
    "$CMF" bake-moments "$WORK/driver-$how.exr" -o "$out" -q
  sed -e "s|\"../../luts/terrain.png\"|\"$SRC/luts/terrain.png\"|" -e "s|\"fbm-gradient-6.exr\"|\"$WORK/sigma-$how.exr\"|" \
    "$SRC/examples/scenes/plane-fbm-terrain.json" >"$WORK/scene-$how.json"
  grep -qF "$WORK/sigma-$how.exr" "$WORK/scene-$how.json" || fail "the scene does not name the cut sigma table"
  out=$WORK/cut-render-$how.exr
  cut_and_run "$how" "$SRC/examples/scenes/fbm-gradient-6.exr" "$WORK/sigma-$how.exr" "$out" "render with a sigma table" \
    "$CMF" render "$WORK/scene-$how.json" -o "$out" -q
done
[ "$fail" = 0 ] && echo "every bad path and cut input failed cleanly"
exit $fail
