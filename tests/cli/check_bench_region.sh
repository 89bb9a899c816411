#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# bench's references by region (docs/farm.md):
#   check_bench_region.sh CMFILTER SCENE DIR
# With its rays fixed (--max-reference-spp = --reference-spp: one round),
# bench's reference of each region of an uneven 2 x 2 grid (2 threads)
# written by --references has the region as its data window in the frame's
# display window; stitched with oiiotool it is the whole frame's bench
# reference (1 thread), which is `render --method reference` with the same
# rays and seed, bit for bit (idiff with no tolerance, and the pixel data
# byte for byte). The CSV of a region holds its rows.
set -euo pipefail
cmfilter=$1 scene=$2 dir=$3
rm -rf "$dir"
mkdir -p "$dir"
fail() { echo "FAIL: $*"; exit 1; }
same() {
  idiff -q -fail 0 -failpercent 0 -warn 0 "$1" "$2" > /dev/null 2>&1 || return 1
  local bare=(--eraseattrib ".*" --attrib DateTime "2000:01:01 00:00:00" -d float --compression none)
  oiiotool --nosoftwareattrib "$1" "${bare[@]}" -o "$dir/same-1.tif" "$2" "${bare[@]}" -o "$dir/same-2.tif"
  cmp -s "$dir/same-1.tif" "$dir/same-2.tif"
}
name=$(basename "$scene" .json)
bench=(bench "$scene" --reference-spp 1024 --max-reference-spp 1024 --seed 5 --only naive --repeats 1 -q)

mkdir -p "$dir/whole"
"$cmfilter" "${bench[@]}" --threads 1 --csv "$dir/whole.csv" --references "$dir/whole"
read -r width height < <(oiiotool "$dir/whole/$name.reference.exr" --echo "{TOP.width} {TOP.height}" | tail -n 1)
"$cmfilter" render "$scene" --method reference --spp 1024 --seed 5 --threads 2 -o "$dir/render.exr" -q
same "$dir/whole/$name.reference.exr" "$dir/render.exr" ||
  fail "bench's reference is not render --method reference --spp 1024 --seed 5"

xs=(0 $((width / 3)) "$width")
ys=(0 $((2 * height / 3)) "$height")
args=()
for ((r = 0; r < 2; r++)); do
  for ((c = 0; c < 2; c++)); do
    x0=${xs[c]} x1=${xs[c + 1]} y0=${ys[r]} y1=${ys[r + 1]}
    part=$dir/region-$r-$c
    mkdir -p "$part"
    "$cmfilter" "${bench[@]}" --threads 2 --region "$x0,$y0,$x1,$y1" --csv "$part.csv" --references "$part"
    reference=$part/$name.reference.exr
    windows=$(oiiotool "$reference" --echo "{TOP.x},{TOP.y},{TOP.width},{TOP.height} {TOP.full_width},{TOP.full_height}" | tail -n 1)
    [ "$windows" = "$x0,$y0,$((x1 - x0)),$((y1 - y0)) $width,$height" ] ||
      fail "$reference: windows $windows, expected $x0,$y0,$((x1 - x0)),$((y1 - y0)) $width,$height"
    grep -q ",naive,naive," "$part.csv" || fail "$part.csv has no naive row"
    if [ ${#args[@]} = 0 ]; then args=("$reference"); else args+=("$reference" --swap --paste:mergeroi=1 -); fi
  done
done
oiiotool "${args[@]}" -o "$dir/stitched.exr"
same "$dir/stitched.exr" "$dir/whole/$name.reference.exr" ||
  fail "bench's references by region, stitched, differ from its whole reference"
echo "bench references: 4 regions of ${width} x ${height} stitched are the whole reference, bit for bit"
