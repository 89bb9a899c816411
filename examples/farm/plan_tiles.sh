#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Prints one command line per tile of a frame: `cmfilter render` of the
# tile's region (--region x0,y0,x1,y1: x0,y0 inclusive, x1,y1 exclusive),
# each writing its own OpenEXR file (the region as its data window, the
# frame as its display window; docs/farm.md). Each line is a whole task:
# it reads only the scene and its inputs, writes only its own file (whole,
# or not at all), and gives the same bytes every time it runs, so a farm may
# run the lines in any order, on any machine, retry or repeat any of them.
#   plan_tiles.sh CMFILTER SCENE WxH COLUMNSxROWS OUTDIR [RENDER_OPTION...] > tiles.tasks
# Tiles are named OUTDIR/tile-<row>-<column>.exr; column c spans
# [floor(c W / COLUMNS), floor((c + 1) W / COLUMNS)), rows likewise.
set -euo pipefail
usage="usage: plan_tiles.sh CMFILTER SCENE WxH COLUMNSxROWS OUTDIR [RENDER_OPTION...]"
[ $# -ge 5 ] || { echo "$usage" >&2; exit 1; }
cmfilter=$1 scene=$2 size=$3 grid=$4 outdir=$5
shift 5
pair() {  # "AxB" -> "A B", both integers >= 1
  [[ $1 =~ ^([1-9][0-9]*)x([1-9][0-9]*)$ ]] || { echo "plan_tiles.sh: '$1' is not $2 (expected AxB)" >&2; exit 1; }
  echo "${BASH_REMATCH[1]} ${BASH_REMATCH[2]}"
}
read -r width height < <(pair "$size" "a size")
read -r columns rows < <(pair "$grid" "a tile grid")
if [ "$columns" -gt "$width" ] || [ "$rows" -gt "$height" ]; then
  echo "plan_tiles.sh: $columns x $rows tiles do not fit $width x $height pixels" >&2
  exit 1
fi
. "$(dirname "$0")/task_line.sh"
for ((r = 0; r < rows; r++)); do
  y0=$((r * height / rows)) y1=$(((r + 1) * height / rows))
  for ((c = 0; c < columns; c++)); do
    x0=$((c * width / columns)) x1=$(((c + 1) * width / columns))
    printf -v tile '%s/tile-%03d-%03d.exr' "$outdir" "$r" "$c"
    task_line "$cmfilter" render "$scene" --size "$size" --region "$x0,$y0,$x1,$y1" -o "$tile" -q "$@"
  done
done
