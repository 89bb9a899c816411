#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Stitches the tiles `render --region` wrote (OpenEXR, each tile's region its
# data window in the frame's display window) into the whole frame, bit for
# bit: each tile is pasted at its own data window (oiiotool --paste with
# position '-') onto what the tiles before it made, the two data windows
# merged (mergeroi=1); the first tile's metadata is kept. Fails unless the
# tiles cover the display window exactly: their data windows together span
# it, and their areas add up to its area (no gap, no overlap).
#   stitch.sh OUTPUT.exr TILE.exr...
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: stitch.sh OUTPUT.exr TILE.exr..." >&2; exit 1; }
output=$1
shift
count=$#
# Each tile's area, in one oiiotool.
echoes=()
for tile in "$@"; do echoes+=("$tile" --echo "{TOP.width*TOP.height}"); done
area=$(oiiotool "${echoes[@]}" | awk '{ s += $1 } END { print s }')
args=("$1")
shift
for tile in "$@"; do
  # The stack is (frame so far, tile); --swap makes the tile the
  # foreground, pasted over the frame so far.
  args+=("$tile" --swap --paste:mergeroi=1 -)
done
# Written beside the output and renamed into place once it is checked, so
# that OUTPUT is whole or absent.
partial=$(dirname "$output")/.$(basename "$output" .exr).stitch-$$.exr
trap 'rm -f "$partial"' EXIT
windows=$(oiiotool "${args[@]}" -d float -o "$partial" --echo "{TOP.x},{TOP.y},{TOP.width},{TOP.height} {TOP.full_x},{TOP.full_y},{TOP.full_width},{TOP.full_height} {TOP.full_width*TOP.full_height}" | tail -n 1)
data=${windows%% *} rest=${windows#* }
display=${rest% *} full_area=${rest#* }
if [ "$data" != "$display" ] || [ "$area" != "$full_area" ]; then
  echo "stitch.sh: $count tiles of $area pixels in all span $data (x,y,width,height), not the frame $display" \
       "of $full_area pixels" >&2
  exit 1
fi
mv -f "$partial" "$output"
