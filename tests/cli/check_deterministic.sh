#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# One command's determinism: check_deterministic.sh DIR -- COMMAND ARGS...
# ARGS name the output folder as @OUT@ and the thread count as @THREADS@.
# The command runs with 1 thread, with 2, and with 2 again, each into a
# folder of its own; every file each run writes must be byte for byte the
# first run's (no time stamps, inputs recorded relative to the output). On a
# difference it says where: pixels (idiff -fail 0), metadata (oiiotool), or
# text (diff).
set -euo pipefail
dir=$1
shift
[ "$1" = -- ] && shift
rm -rf "$dir"
runs=(t1:1 t2:2 t2-again:2)
for run in "${runs[@]}"; do
  name=${run%%:*} threads=${run##*:}
  mkdir -p "$dir/$name"
  args=()
  for a in "$@"; do
    a=${a//@OUT@/$dir/$name}
    args+=("${a//@THREADS@/$threads}")
  done
  "${args[@]}" > "$dir/$name.log" 2>&1 || { echo "run $name failed:"; cat "$dir/$name.log"; exit 1; }
done
is_image() {
  case "${1,,}" in *.exr|*.png|*.tif|*.tiff|*.jpg|*.hdr) return 0 ;; *) return 1 ;; esac
}
first=$dir/t1
files=$(cd "$first" && find . -type f | sort)
[ -n "$files" ] || { echo "the command wrote nothing into $first"; exit 1; }
for run in "${runs[@]:1}"; do
  other=$dir/${run%%:*}
  other_files=$(cd "$other" && find . -type f | sort)
  [ "$files" = "$other_files" ] || { echo "runs t1 and ${run%%:*} wrote different files"; exit 1; }
  for f in $files; do
    cmp -s "$first/$f" "$other/$f" && continue
    echo "$f: bytes differ between t1 and ${run%%:*}"
    if is_image "$f"; then
      idiff -q -fail 0 -failpercent 0 -warn 0 "$first/$f" "$other/$f" > /dev/null || echo "$f: pixels differ"
      diff <(oiiotool --info -v -a "$first/$f" | sed "s|$first||g") <(oiiotool --info -v -a "$other/$f" | sed "s|$other||g")
    else
      diff "$first/$f" "$other/$f" | head -20
    fi
    exit 1
  done
done
echo "deterministic: $(echo "$files" | wc -l) files, byte-identical for 1 and 2 threads and across runs"
