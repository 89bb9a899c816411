#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# render --method segments with a segment pyramid baked once, outside the
# scene: bake-moments --segments of the scene's driver for the stripes map's
# table, named by the scene's driver/segments. Then
#   1. through the stripes map with its channels permuted (B, R, G: other
#      colours on the same breakpoints, no re-bake) it equals --method
#      color-pyramid of that permuted map (the box means of C0(f) baked
#      from the driver's texels, a second computation) within 1e-4;
#   2. through terrain (other breakpoints) it is refused, naming the
#      pyramid, and writes nothing.
#   check_render_segments.sh CMFILTER OIIOTOOL SOURCE_DIR OUT_DIR
set -eu
cmf=$1; oiiotool=$2; src=$3; out=$4/render-segments
mkdir -p "$out"
"$oiiotool" "$src/luts/stripes.png" --ch B,R,G --chnames R,G,B -o "$out/stripes-permuted.png"
# The scenes' map domain, [0.002, 0.998]: the table's breakpoints in driver units.
"$cmf" bake-colormap "$src/luts/stripes.png" --domain 0.002:0.998 -o "$out/stripes-table.exr" -q
"$cmf" bake-moments "$src/examples/noise-driver.png" --segments "$out/stripes-table.exr" --wrap periodic \
       -o "$out/stripes-segments.exr" -q
scene() {  # scene MAP OUTPUT: tests/cli/scenes/texture-driver.json through MAP with the pyramid
  python3 - "$src" "$1" "$out/stripes-segments.exr" "$2" <<'PY'
import json, sys
src, colormap, segments, output = sys.argv[1:]
scene = json.load(open(src + "/tests/cli/scenes/texture-driver.json"))
material = scene["surfaces"][0]["material"]
material["colormap"]["image"] = colormap
material["driver"] = {"image": src + "/examples/noise-driver.png", "segments": segments}
json.dump(scene, open(output, "w"), indent=1)
PY
}
scene "$out/stripes-permuted.png" "$out/permuted.json"
"$cmf" render "$out/permuted.json" --method segments -o "$out/segments.exr" -q
"$cmf" render "$out/permuted.json" --method color-pyramid -o "$out/color-pyramid.exr" -q
"$oiiotool" --fail 1e-4 --hardfail 1e-4 "$out/segments.exr" "$out/color-pyramid.exr" --diff > /dev/null
echo "recoloured: segments equals color-pyramid within 1e-4"

scene "$src/luts/terrain.png" "$out/terrain.json"
rm -f "$out/terrain.exr"
if message=$("$cmf" render "$out/terrain.json" --method segments -o "$out/terrain.exr" 2>&1); then
  echo "FAIL: a pyramid of other breakpoints was taken"; exit 1
fi
echo "$message"
echo "$message" | grep -q "driver/segments: segment pyramid '.*stripes-segments\.exr' holds .* does not fit" ||
  { echo "FAIL: the refusal does not name the pyramid and the misfit"; exit 1; }
[ ! -e "$out/terrain.exr" ] || { echo "FAIL: output written"; exit 1; }
echo "other breakpoints: refused"
