#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# One command's determinism: check_deterministic.sh DIR -- COMMAND ARGS...
# ARGS name the output folder as @OUT@ and the thread count as @THREADS@.
# The command runs with 1 thread, with 2, and with 2 again; every file each
# run writes must equal the first run's: images pixel for pixel (idiff
# -fail 0) with the same metadata but for timings (cmfilter:seconds,
# cmfilter:fit_seconds, DateTime), other files byte for byte but for lines
# that record a time in seconds ("render_seconds": in a stack record).
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
metadata() { oiiotool --info -v -a "$1" | grep -vE 'cmfilter:(fit_)?seconds|DateTime|^ *[^ ]+ *: *[0-9]+ x [0-9]+' | sed "s|$2||g"; }
first=$dir/t1
files=$(cd "$first" && find . -type f | sort)
[ -n "$files" ] || { echo "the command wrote nothing into $first"; exit 1; }
for run in "${runs[@]:1}"; do
  other=$dir/${run%%:*}
  other_files=$(cd "$other" && find . -type f | sort)
  [ "$files" = "$other_files" ] || { echo "runs t1 and ${run%%:*} wrote different files"; exit 1; }
  for f in $files; do
    if is_image "$f"; then
      idiff -q -fail 0 -failpercent 0 -warn 0 "$first/$f" "$other/$f" > /dev/null ||
        { echo "$f: pixels differ between t1 and ${run%%:*}"; exit 1; }
      diff <(metadata "$first/$f" "$first") <(metadata "$other/$f" "$other") ||
        { echo "$f: metadata differs between t1 and ${run%%:*}"; exit 1; }
    else
      # Text files may name the run's own folder, and record timings.
      plain() { sed -e "s|$2||g" "$1" | grep -vE '_?seconds"?[:,=]|"seconds"'; }
      diff <(plain "$first/$f" "$first") <(plain "$other/$f" "$other") > /dev/null ||
        { echo "$f differs between t1 and ${run%%:*}"; exit 1; }
    fi
  done
done
echo "deterministic: $(echo "$files" | wc -l) files, identical for 1 and 2 threads and across runs"
