#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Reproducible outputs: check_reproducible.sh CMFILTER MAP DRIVER WORKDIR
# - the same map and driver baked in two folders of different depths (two
#   checkouts, two farm nodes) give byte-identical tables and moments: no
#   time stamp, and the source recorded relative to the output;
# - the recorded sources still resolve: apply --method reference reads the
#   driver and map the files record, before and after the folder moves;
# - SOURCE_DATE_EPOCH=1700000000 gives that time, in UTC, as DateTime (as
#   `date -u` prints it), and no variable gives no DateTime at all;
# - a malformed SOURCE_DATE_EPOCH is refused (exit 3), writing nothing.
set -uo pipefail
cmf=$1 map=$2 driver=$3 work=$4
fail=0
rm -rf "$work" && mkdir -p "$work"
bake() {  # bake ROOT: a checkout-like tree ROOT/{maps,drivers,out}
  mkdir -p "$1/maps" "$1/drivers" "$1/out"
  cp "$map" "$1/maps/map.png" && cp "$driver" "$1/drivers/driver.png"
  "$cmf" bake-colormap "$1/maps/map.png" -o "$1/out/table.exr" -q &&
    "$cmf" bake-moments "$1/drivers/driver.png" -o "$1/out/moments.exr" -q
}
bake "$work/a" || { echo "FAIL: bake in a"; exit 1; }
bake "$work/b/deeper/still" || { echo "FAIL: bake in b"; exit 1; }
for f in table.exr moments.exr; do
  cmp "$work/a/out/$f" "$work/b/deeper/still/out/$f" || { echo "FAIL: $f differs between the two folders"; fail=1; }
done
oiiotool --info -v "$work/a/out/moments.exr" | grep -F 'cmfilter:source: "../drivers/driver.png"' > /dev/null ||
  { echo "FAIL: the moments do not record ../drivers/driver.png"; oiiotool --info -v "$work/a/out/moments.exr" | grep source; fail=1; }
if oiiotool --info -v "$work/a/out/table.exr" | grep -q DateTime; then
  echo "FAIL: a table without SOURCE_DATE_EPOCH has a DateTime"; fail=1
fi
apply_ref() {
  (cd "$1" && "$cmf" apply --moments out/moments.exr --table out/table.exr --method reference --lod 1 -o out/ref.exr -q)
}
apply_ref "$work/a" || { echo "FAIL: apply could not find the recorded driver and map"; fail=1; }
mv "$work/a" "$work/a-moved"
apply_ref "$work/a-moved" || { echo "FAIL: apply after the folder moved"; fail=1; }

expected=$(date -u -d @1700000000 '+%Y:%m:%d %H:%M:%S')
SOURCE_DATE_EPOCH=1700000000 "$cmf" bake-colormap "$map" -o "$work/dated.exr" -q || { echo "FAIL: dated bake"; fail=1; }
oiiotool --info -v "$work/dated.exr" | grep -F "DateTime: \"$expected\"" > /dev/null ||
  { echo "FAIL: SOURCE_DATE_EPOCH=1700000000 did not give DateTime $expected"; oiiotool --info -v "$work/dated.exr" | grep -i date; fail=1; }
SOURCE_DATE_EPOCH=1700000000 "$cmf" bake-colormap "$map" -o "$work/dated-again.exr" -q
cmp "$work/dated.exr" "$work/dated-again.exr" || { echo "FAIL: dated bakes differ"; fail=1; }

err=$(SOURCE_DATE_EPOCH=yesterday "$cmf" bake-colormap "$map" -o "$work/bad-date.exr" 2>&1); rc=$?
[ "$rc" = 3 ] || { echo "FAIL: SOURCE_DATE_EPOCH=yesterday exited $rc"; fail=1; }
grep -qF "SOURCE_DATE_EPOCH 'yesterday' is not a time" <<< "$err" || { echo "FAIL: message '$err'"; fail=1; }
[ -e "$work/bad-date.exr" ] && { echo "FAIL: a partial output was left"; fail=1; }
[ "$fail" = 0 ] && echo "reproducible: byte-identical in two folders, sources resolved after a move, SOURCE_DATE_EPOCH honoured"
exit $fail
