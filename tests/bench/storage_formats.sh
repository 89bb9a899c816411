#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# What each storage of a moment pyramid and of a colour table costs, in
# bytes and in accuracy (docs/storage.md): every pixel type and compression
# OpenEXR offers (-d, --compression), and tile sizes, against the default
# (float, zip, 64 x 64 tiles for pyramids, scanlines for tables). Accuracy:
# `apply --method gaussian` at LOD 0, 1, 2, 4 and 6 through each map with the
# stored variant, compared (CIEDE2000 mean and max over the image) with the
# same apply from the default files; and, for scale, the default's own error
# against the box-filtered reference (`--method reference`).
#   bash tests/bench/storage_formats.sh BUILD_DIR WORK_DIR [DRIVER] [MAPS...]
# (DRIVER default examples/noise-driver.png; MAPS default luts/terrain.png luts/stripes.png)
# Prints markdown tables on stdout.
set -euo pipefail
build=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
root=$(cd "$(dirname "$0")/../.." && pwd)
driver=${3:-$root/examples/noise-driver.png}
shift 3 2> /dev/null || shift $#
maps=("$@")
[ ${#maps[@]} -gt 0 ] || maps=("$root/luts/terrain.png" "$root/luts/stripes.png")
cmf="$build/tools/cmfilter"
lods=(0 1 2 4 6)
cd "$work"

# "mean max" CIEDE2000 of compare A B.
de() {
  "$cmf" compare "$1" "$2" --json |
    python3 -c "import json,sys; d=json.load(sys.stdin)['ciede2000']; print('%.3g %.3g' % (d['mean'], d['max']))"
}
bytes() { stat -c %s "$1"; }

variants=("float zip" "float piz" "float zips" "float rle" "float none" "float pxr24" "float dwaa"
          "half zip" "half piz" "half pxr24" "half b44" "half dwaa" "half dwab")
name() { echo "$1-$2"; }

"$cmf" bake-moments "$driver" -o moments-float-zip.exr -q
for m in "${maps[@]}"; do
  b=$(basename "$m" .png)
  "$cmf" bake-colormap "$m" -o "table-$b-float-zip.exr" -q --error-samples 0
  for lod in "${lods[@]}"; do
    "$cmf" apply --moments moments-float-zip.exr --table "table-$b-float-zip.exr" --method gaussian --lod "$lod" \
      -o "base-$b-$lod.exr" -q
    "$cmf" apply --moments moments-float-zip.exr --table "table-$b-float-zip.exr" --method reference --lod "$lod" \
      -o "ref-$b-$lod.exr" -q
  done
done

header() {
  local line="| $1 | bytes | vs default |" sep="|---|---:|---:|"
  for m in "${maps[@]}"; do
    for lod in "${lods[@]}"; do line+=" $(basename "$m" .png) L$lod |"; sep+="---:|"; done
  done
  echo "$line"
  echo "$sep"
}

echo "### Moment pyramids ($(basename "$driver"), 64 x 64 tiles): CIEDE2000 mean / max of gaussian against the default files"
echo
header "storage"
line="| gaussian against the reference (the method's own error) | | |"
for m in "${maps[@]}"; do
  b=$(basename "$m" .png)
  for lod in "${lods[@]}"; do read -r mean max < <(de "ref-$b-$lod.exr" "base-$b-$lod.exr"); line+=" $mean / $max |"; done
done
echo "$line"
base_bytes=$(bytes moments-float-zip.exr)
for v in "${variants[@]}"; do
  set -- $v
  f="moments-$(name "$1" "$2").exr"
  [ -e "$f" ] || "$cmf" bake-moments "$driver" -o "$f" -d "$1" --compression "$2" -q
  line="| \`-d $1 --compression $2\` | $(bytes "$f") | $(python3 -c "print('%.2f' % ($(bytes "$f") / $base_bytes))") |"
  for m in "${maps[@]}"; do
    b=$(basename "$m" .png)
    for lod in "${lods[@]}"; do
      "$cmf" apply --moments "$f" --table "table-$b-float-zip.exr" --method gaussian --lod "$lod" -o out.exr -q
      read -r mean max < <(de "base-$b-$lod.exr" out.exr)
      line+=" $mean / $max |"
    done
  done
  echo "$line"
done
echo
echo "Tile sizes (float, zip):"
echo
echo "| --tile | bytes | vs 64 x 64 |"
echo "|---|---:|---:|"
for t in 16 32 64 128 256; do
  f="moments-tile-$t.exr"
  "$cmf" bake-moments "$driver" -o "$f" --tile "$t" "$t" -q
  echo "| $t $t | $(bytes "$f") | $(python3 -c "print('%.2f' % ($(bytes "$f") / $base_bytes))") |"
done

echo
echo "### Colour tables (256 x 256, scanlines): CIEDE2000 mean / max of gaussian against the default files"
echo
header "storage"
for v in "${variants[@]}"; do
  set -- $v
  line="| \`-d $1 --compression $2\` |"
  first=1
  for m in "${maps[@]}"; do
    b=$(basename "$m" .png)
    f="table-$b-$(name "$1" "$2").exr"
    [ -e "$f" ] || "$cmf" bake-colormap "$m" -o "$f" -d "$1" --compression "$2" -q --error-samples 0
    if [ "$first" = 1 ]; then
      base=$(bytes "table-$b-float-zip.exr")
      line+=" $(bytes "$f") ($b) | $(python3 -c "print('%.2f' % ($(bytes "$f") / $base))") |"
      first=0
    fi
    for lod in "${lods[@]}"; do
      "$cmf" apply --moments moments-float-zip.exr --table "$f" --method gaussian --lod "$lod" -o out.exr -q
      read -r mean max < <(de "base-$b-$lod.exr" out.exr)
      line+=" $mean / $max |"
    done
  done
  echo "$line"
done
