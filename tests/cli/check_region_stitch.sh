#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Regions stitched are the whole render, bit for bit (docs/farm.md):
#   check_region_stitch.sh CMFILTER SCENE DIR THREADS -- RENDER_OPTION... -- CONTROL_OPTION...
# renders SCENE whole with 1 thread (the one-machine render, with its AOVs),
# then as six regions of an uneven 3 x 2 grid with THREADS threads, each an
# EXR whose data window is the region and whose display window is the frame
# (checked, and the region --json reports), stitches the regions (and each
# AOV) with oiiotool's paste at each tile's own data window, and compares
# each stitched frame with the whole one: idiff with no tolerance, and the
# pixel data byte for byte (uncompressed float TIFFs without attributes).
# The check must be able to fail: one region rendered with CONTROL_OPTIONS
# in place of RENDER_OPTIONS (another method or seed) must make the stitched
# frame differ.
set -euo pipefail
cmfilter=$1 scene=$2 dir=$3 threads=$4
shift 4
[ "${1:-}" = -- ] && shift
options=()
while [ $# -gt 0 ] && [ "$1" != -- ]; do options+=("$1"); shift; done
[ $# -gt 0 ] && shift
control=("$@")
rm -rf "$dir"
mkdir -p "$dir"
fail() { echo "FAIL: $*"; exit 1; }

root=$(cd "$(dirname "$0")/../.." && pwd)
# Pixel data without attributes (uncompressed float TIFF, a fixed date), so
# that cmp compares pixel bytes: a -0 against a 0 counts.
bare=(--eraseattrib ".*" --attrib DateTime "2000:01:01 00:00:00" -d float --compression none)
# paste_args TILE...: the documented stitch (docs/farm.md) as oiiotool
# arguments, leaving the frame on the top of the stack.
paste_args() {
  pasted=("$1")
  shift
  local tile
  for tile in "$@"; do pasted+=("$tile" --swap --paste:mergeroi=1 -); done
}

"$cmfilter" render "$scene" "${options[@]}" --threads 1 -o "$dir/full.exr" --aov "$dir/full" -q
read -r width height < <(oiiotool "$dir/full.exr" --echo "{TOP.width} {TOP.height}" | tail -n 1)
aovs=(mean sigma lod)
[ -f "$dir/full.shaded.exr" ] && aovs+=(shaded)
xs=(0 $((width / 4 + 1)) $((2 * width / 3)) "$width")
ys=(0 $((height / 3)) "$height")
tiles=()
regions=()
jsons=()
echo_windows=()
expected=""
for ((r = 0; r < 2; r++)); do
  for ((c = 0; c < 3; c++)); do
    x0=${xs[c]} x1=${xs[c + 1]} y0=${ys[r]} y1=${ys[r + 1]}
    tile=$dir/tile-$r-$c
    "$cmfilter" render "$scene" "${options[@]}" --threads "$threads" --region "$x0,$y0,$x1,$y1" \
                -o "$tile.exr" --aov "$tile" --json > "$tile.json"
    jsons+=("$tile.json" "$x0,$y0,$x1,$y1")
    for image in "$tile.exr" "$tile".{mean,sigma,lod}.exr; do
      echo_windows+=("$image" --echo "$image {TOP.x},{TOP.y},{TOP.width},{TOP.height} {TOP.full_x},{TOP.full_y},{TOP.full_width},{TOP.full_height}")
      expected+="$image $x0,$y0,$((x1 - x0)),$((y1 - y0)) 0,0,$width,$height"$'\n'
    done
    tiles+=("$tile")
    regions+=("$x0,$y0,$x1,$y1")
  done
done

# Every region's image and AOVs: the region as the data window, the frame as
# the display window.
windows=$(oiiotool "${echo_windows[@]}")
[ "$windows"$'\n' = "$expected" ] || fail "data and display windows:"$'\n'"$windows"$'\n'"expected:"$'\n'"$expected"

python3 - "$width,$height" "${jsons[@]}" <<'PY' || fail "a region's --json does not report its region and size"
import json, sys
size = [int(v) for v in sys.argv[1].split(",")]
for path, region in zip(sys.argv[2::2], sys.argv[3::2]):
    j = json.load(open(path))
    assert j["region"] == [int(v) for v in region.split(",")], (path, j["region"])
    assert j["size"] == size, (path, j["size"])
    assert len(j["aov"]) >= 3, path
PY

# The image through the example's stitch (its coverage check too), compared
# with idiff and by bytes; each AOV stitched and made bare in one oiiotool.
bash "$root/examples/farm/stitch.sh" "$dir/frame.exr" "${tiles[@]/%/.exr}"
idiff -q -fail 0 -failpercent 0 -warn 0 "$dir/frame.exr" "$dir/full.exr" > /dev/null 2>&1 ||
  fail "the stitched regions differ from the whole render (idiff)"
ops=(--nosoftwareattrib "$dir/frame.exr" "${bare[@]}" -o "$dir/frame.tif" "$dir/full.exr" "${bare[@]}" -o "$dir/full.tif")
for aov in "${aovs[@]}"; do
  paste_args "${tiles[@]/%/.$aov.exr}"
  ops+=("${pasted[@]}" "${bare[@]}" -o "$dir/frame.$aov.tif" "$dir/full.$aov.exr" "${bare[@]}" -o "$dir/full.$aov.tif")
done
oiiotool "${ops[@]}"
cmp -s "$dir/frame.tif" "$dir/full.tif" || fail "the stitched regions differ from the whole render"
for aov in "${aovs[@]}"; do
  cmp -s "$dir/frame.$aov.tif" "$dir/full.$aov.tif" || fail "the stitched $aov AOVs differ from the whole render's"
done

# The control: region 4 rendered otherwise must show.
"$cmfilter" render "$scene" "${control[@]}" --threads "$threads" --region "${regions[4]}" -o "$dir/control.exr" -q
stitched=("${tiles[@]/%/.exr}")
stitched[4]=$dir/control.exr
paste_args "${stitched[@]}"
oiiotool --nosoftwareattrib "${pasted[@]}" "${bare[@]}" -o "$dir/control.tif"
if cmp -s "$dir/control.tif" "$dir/full.tif"; then
  fail "a region rendered with ${control[*]} left the stitched frame the same: the check cannot fail"
fi
echo "regions stitched: ${width} x ${height}, 6 regions at $threads thread(s), the image and its AOVs (${aovs[*]}) bit for bit the whole render"
