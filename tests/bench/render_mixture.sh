#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# render --method mixture against gaussian on texture drivers
# (docs/render.md, "Texture drivers: mixture against gaussian"): the bundled
# image scene and the same ground plane with scikit-image's camera through
# the stripes map, benched at SIZE (default 160x90) against the bench's
# reference; then the cost at 640 x 360, one thread, best of 3, with
# pyramids of order 2 and 4 named by the scenes. Writes WORK/bench.csv (and
# the charts) and WORK/cost.txt.
#
#   bash tests/bench/render_mixture.sh BUILD_DIR WORK_DIR [SIZE]
set -euo pipefail
build=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
size=${3:-160x90}
root=$(cd "$(dirname "$0")/../.." && pwd)
cmf="$build/tools/cmfilter"

/usr/bin/python3 -c "import sys, skimage.io, skimage.data as d; skimage.io.imsave(sys.argv[1], d.camera(), check_contrast=False)" \
  "$work/camera.png"
scene() {  # scene FILE DRIVER_JSON MAP DOMAIN
  cat > "$1" <<JSON
{
  "camera": {"position": [0, 1.5, 0], "look_at": [0, 0.9, 10], "up": [0, 1, 0], "fov_degrees": 50, "resolution": [640, 360]},
  "light": {"direction": [0.4, 1, -0.3], "radiance": [0.9, 0.9, 0.9], "ambient": [0.1, 0.1, 0.1]},
  "background": [0.55, 0.65, 0.8],
  "surfaces": [
    {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
     "mapping": {"type": "planar", "origin": [0, 0, 0], "u_axis": [0.125, 0, 0], "v_axis": [0, 0, 0.125]},
     "material": {"colormap": {"image": "$3", "domain": $4}, "driver": $2}}
  ]
}
JSON
}
scene "$work/plane-camera-stripes.json" '{"image": "camera.png"}' "$root/luts/stripes.png" "[0, 1]"
"$cmf" bench "$work/plane-camera-stripes.json" "$root/examples/scenes/plane-image-terrain.json" --csv "$work/bench.csv" \
  --charts "$work" --resolution "$size" --repeats 1 \
  --only "naive,gaussian 256x256 sqrt,mixture,exact,supersample 16,supersample 64"

# Cost: the same scenes naming pyramids of two and four moments.
: > "$work/cost.txt"
for d in camera:"$work/camera.png":stripes:"[0, 1]" terrain:"$root/examples/noise-driver.png":terrain:"[0.002, 0.998]"; do
  IFS=: read -r name driver map domain <<< "$d"
  for order in 2 4; do
    "$cmf" bake-moments "$driver" -o "$work/$name-$order.exr" --order "$order" --wrap periodic -q
    scene "$work/$name-$order.json" "{\"moments\": \"$name-$order.exr\"}" "$root/luts/$map.png" "$domain"
  done
  for run in 2:gaussian 4:gaussian 4:mixture; do
    order=${run%%:*} method=${run##*:} best=""
    for i in 1 2 3; do
      t=$("$cmf" render "$work/$name-$order.json" --method "$method" --threads 1 -o "$work/cost.exr" --json |
          /usr/bin/python3 -c "import json, sys; print(json.load(sys.stdin)['seconds'])")
      best=$(/usr/bin/python3 -c "import sys; print(min(float(x) for x in sys.argv[1:]))" $t $best)
    done
    echo "$name order $order $method $best s" | tee -a "$work/cost.txt"
  done
done
rm -f "$work/cost.exr"
