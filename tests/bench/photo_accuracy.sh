#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `cmfilter apply` on photographs through hard-edged maps: every method
# against the box-filtered ground truth (`--method reference`), LOD 1..8.
# Drivers: scikit-image's camera, moon, coins and gravel (8-bit grey, read as
# data in [0, 1]); maps: the bundled stripes, step and narrow band, tables of
# VALUES value nodes (default 2048, as apply_accuracy.sh). Methods: naive,
# gaussian (2 moments), mixture (4 moments, bake-moments --order 4) and, when
# METHODS names it, exact (the histogram pyramid: every one of up to 256
# values; 0 up to rounding, and about a hundred times gaussian's time). Also
# times each method's apply (one thread), for the cost against gaussian.
# Writes WORK/photo-accuracy.csv (driver,map,lod,method,mean,p95,max,ms).
#
#   bash tests/bench/photo_accuracy.sh BUILD_DIR WORK_DIR [VALUES] [DRIVERS] [METHODS]
# (docs/apply.md shows the figures of `... build /tmp/photo 2048` and of
# `... build /tmp/photo-exact 2048 camera "gaussian mixture exact"`).
set -euo pipefail
build=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
values=${3:-2048}
drivers=(${4:-camera moon coins gravel})
root=$(cd "$(dirname "$0")/../.." && pwd)
cmf="$build/tools/cmfilter"
maps=(stripes step narrow-band)
methods=(${5:-naive gaussian mixture})

for d in "${drivers[@]}"; do
  /usr/bin/python3 -c "import sys, skimage.io, skimage.data as d; skimage.io.imsave(sys.argv[2], getattr(d, sys.argv[1])(), check_contrast=False)" \
    "$d" "$work/$d.png"
  "$cmf" bake-moments "$work/$d.png" -o "$work/$d-moments.exr" --order 4 --histograms "$work/$d-histograms.exr" -q
done
for map in "${maps[@]}"; do
  "$cmf" bake-colormap "$root/luts/$map.png" -o "$work/$map-table.exr" --values "$values" -q
done

csv="$work/photo-accuracy.csv"
echo "driver,map,lod,method,mean,p95,max,ms" > "$csv"
stat() { awk -v k="$2" '$1 == "dE2000" && $2 == k { print $3 }' "$1"; }
for d in "${drivers[@]}"; do
  for map in "${maps[@]}"; do
    for lod in 1 2 3 4 5 6 7 8; do
      common=(--moments "$work/$d-moments.exr" --table "$work/$map-table.exr" --lod "$lod" --threads 1)
      "$cmf" apply "${common[@]}" --method reference -o "$work/ref.exr" -q
      for m in "${methods[@]}"; do
        "$cmf" apply "${common[@]}" --histograms "$work/$d-histograms.exr" --method "$m" -o "$work/out.exr" \
          > "$work/apply.txt"
        ms=$(awk '$1 == "time" { print $2 }' "$work/apply.txt")
        "$cmf" compare "$work/ref.exr" "$work/out.exr" > "$work/compare.txt"
        echo "$d,$map,$lod,$m,$(stat "$work/compare.txt" mean),$(stat "$work/compare.txt" p95),$(stat "$work/compare.txt" max),$ms" >> "$csv"
      done
      echo "photo_accuracy: $d $map LOD $lod" >&2
    done
  done
done
rm -f "$work/ref.exr" "$work/out.exr" "$work/compare.txt" "$work/apply.txt"
