#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The baked colour pyramid (`bake-moments --method color-pyramid`, float32
# and half) against the box-filtered ground truth (`apply --method
# reference`, computed from the driver on the fly), LOD 1..8, with gaussian
# beside it and each apply timed (one thread, the same script) for the cost
# against gaussian:
#   photographs  scikit-image's camera, moon, coins and gravel (8-bit grey,
#                data in [0, 1]) through the bundled stripes, step and
#                narrow band: the 96 cases of docs/apply.md;
#   every map    camera through every colour map in luts/ (slope-wheel, a 2-D
#                map of slope vectors, is no colour map of one driver);
#   drivers      a two-valued one (camera thresholded at 0.5), an offset one
#                (1000 + camera, its map's domain [1000, 1001]) and a float
#                HDR one (camera^4 x 1000 in [0, 1000], domain [0, 1000]),
#                each through stripes.
# Writes WORK/color-pyramid-accuracy.csv (set,driver,map,lod,method,mean,max,ms)
# and prints the worst mean per set and method, and the time ratios.
#
#   bash tests/bench/color_pyramid_accuracy.sh BUILD_DIR WORK_DIR [VALUES] [SETS]
# (SETS: any of "photographs every-map drivers", default all three).
# (docs/apply.md shows the figures of `... build /tmp/cp 2048`).
set -euo pipefail
build=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
values=${3:-2048}
root=$(cd "$(dirname "$0")/../.." && pwd)
cmf="$build/tools/cmfilter"
oiiotool=${OIIOTOOL:-oiiotool}
sets=" ${4:-photographs every-map drivers} "
methods=(gaussian color-pyramid color-pyramid-half)

csv="$work/color-pyramid-accuracy.csv"
echo "set,driver,map,lod,method,mean,max,ms" > "$csv"
stat() { awk -v k="$2" '$1 == "dE2000" && $2 == k { print $3 }' "$1"; }

# One driver through one map: bake the moments, the table (over DOMAIN) and
# both colour pyramids, then every LOD by every method against the reference.
run_case() {  # set driver-name driver-file map domain
  local set=$1 d=$2 file=$3 map=$4 domain=$5
  local table="$work/$map-$domain-table.exr"
  [ -f "$table" ] || "$cmf" bake-colormap "$root/luts/$map.png" -o "$table" --values "$values" --domain="$domain" -q
  "$cmf" bake-moments "$file" -o "$work/$d-moments.exr" -q
  "$cmf" bake-moments "$file" --method color-pyramid --table "$table" -o "$work/$d-$map-cp.exr" -q
  "$cmf" bake-moments "$file" --method color-pyramid --table "$table" -d half -o "$work/$d-$map-cp-half.exr" -q
  for lod in 1 2 3 4 5 6 7 8; do
    "$cmf" apply --moments "$work/$d-moments.exr" --table "$table" --lod "$lod" --threads 1 --method reference \
      -o "$work/ref.exr" -q
    for m in "${methods[@]}"; do
      case $m in
        gaussian) args=(--moments "$work/$d-moments.exr" --method gaussian) ;;
        color-pyramid) args=(--moments "$work/$d-$map-cp.exr" --method color-pyramid) ;;
        color-pyramid-half) args=(--moments "$work/$d-$map-cp-half.exr" --method color-pyramid) ;;
      esac
      "$cmf" apply "${args[@]}" --table "$table" --lod "$lod" --threads 1 -o "$work/out.exr" > "$work/apply.txt"
      ms=$(awk '$1 == "time" { print $2 }' "$work/apply.txt")
      "$cmf" compare "$work/ref.exr" "$work/out.exr" > "$work/compare.txt"
      echo "$set,$d,$map,$lod,$m,$(stat "$work/compare.txt" mean),$(stat "$work/compare.txt" max),$ms" >> "$csv"
    done
  done
  echo "color_pyramid_accuracy: $set $d $map" >&2
}

photo() {
  /usr/bin/python3 -c "import sys, skimage.io, skimage.data as d; skimage.io.imsave(sys.argv[2], getattr(d, sys.argv[1])(), check_contrast=False)" \
    "$1" "$work/$1.png"
}
photo camera
if [[ $sets == *" photographs "* ]]; then
  for d in camera moon coins gravel; do
    [ "$d" = camera ] || photo "$d"
    for map in stripes step narrow-band; do run_case photographs "$d" "$work/$d.png" "$map" 0:1; done
  done
fi
if [[ $sets == *" every-map "* ]]; then
  for lut in "$root"/luts/*.png; do
    map=$(basename "$lut" .png)
    [ "$map" = slope-wheel ] && continue
    run_case every-map camera "$work/camera.png" "$map" 0:1
  done
fi
if [[ $sets == *" drivers "* ]]; then
  "$oiiotool" "$work/camera.png" -d float --chnames Y --subc 0.5 --mulc 1e6 --clamp:min=0:max=1 \
    -o "$work/two-valued.exr"
  run_case drivers two-valued "$work/two-valued.exr" stripes 0:1
  "$oiiotool" "$work/camera.png" -d float --chnames Y --addc 1000 -o "$work/offset.exr"
  run_case drivers offset "$work/offset.exr" stripes 1000:1001
  "$oiiotool" "$work/camera.png" -d float --chnames Y --powc 4 --mulc 1000 -o "$work/hdr.exr"
  run_case drivers hdr "$work/hdr.exr" stripes 0:1000
fi
rm -f "$work/ref.exr" "$work/out.exr" "$work/compare.txt" "$work/apply.txt"

/usr/bin/python3 - "$csv" <<'PY'
import csv, sys, collections
rows = list(csv.DictReader(open(sys.argv[1])))
worst = collections.defaultdict(float); count = collections.Counter(); ms = collections.defaultdict(float)
for r in rows:
    k = (r["set"], r["method"])
    worst[k] = max(worst[k], float(r["mean"])); count[k] += 1; ms[k] += float(r["ms"])
for s in ("photographs", "every-map", "drivers"):
    g = ms[(s, "gaussian")]
    if not g: continue
    for m in ("gaussian", "color-pyramid", "color-pyramid-half"):
        k = (s, m)
        print(f"{s:12s} {m:19s} cases {count[k]:3d}  worst mean dE2000 {worst[k]:.6g}  apply time / gaussian's {ms[k] / g:.3f}")
PY
