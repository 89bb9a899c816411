#!/usr/bin/env bash
# The main job on the bundled example: bake a prefiltered table (eq. 10) for
# every colour map in luts/, describe each, and write an sRGB preview of each
# table (sigma grows downwards) for a person to look at.
#   bash examples/run.sh CMFILTER_BINARY OUTPUT_DIR
set -euo pipefail
cmfilter=${1:?usage: run.sh CMFILTER_BINARY OUTPUT_DIR}
out=${2:?usage: run.sh CMFILTER_BINARY OUTPUT_DIR}
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out/tables" "$out/previews"
for map in "$root"/luts/*.png; do
  name=$(basename "$map" .png)
  "$cmfilter" bake-colormap "$map" -o "$out/tables/$name.exr"
  "$cmfilter" info "$out/tables/$name.exr" > "$out/tables/$name.txt"
  oiiotool "$out/tables/$name.exr" --resize 512x256 --colorconvert linear sRGB -d uint8 \
           -o "$out/previews/$name.png"
done
echo
echo "example outputs in $out:"
echo "  tables/*.exr    prefiltered colour-map tables (open with oiiotool --info -v or cmfilter info)"
echo "  tables/*.txt    what cmfilter info says of each"
echo "  previews/*.png  each table in sRGB: value left to right, sigma 0 (top) to sigma-max (bottom)"
