#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Storage options as maketx spells them (-d, --tile, --compression) on the
# commands that write tables and pyramids: OpenImageIO reads back the pixel
# type, tiles and compression asked for; every half or tiled artefact reads
# back into apply and render; half moments give apply's result within the
# error docs/storage.md measures (LOD 4: mean CIEDE2000 < 0.05 against float),
# lossless compressions give the same pixels (idiff -fail 0); a driver whose
# squared deviation does not fit a half is refused, writing nothing.
#   check_storage.sh CMFILTER MAP DRIVER WORKDIR
set -uo pipefail
cmf=$1 map=$2 driver=$3 work=$4
fail=0
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
run() { "$@" > last.out 2> last.err || { echo "FAIL: $*"; cat last.err; fail=1; return 1; }; }
has() {  # has FILE TEXT...: oiiotool --info -v FILE shows each TEXT
  local f=$1; shift
  local info; info=$(oiiotool --info -v "$f")
  for t in "$@"; do grep -qF -- "$t" <<< "$info" || { echo "FAIL: $f: no '$t' in:"; echo "$info" | head -8; fail=1; }; done
}
run "$cmf" bake-colormap "$map" -o table-float.exr -q --error-samples 0
run "$cmf" bake-colormap "$map" -o table-half.exr -q --error-samples 0 -d half --tile 32 16 --compression piz &&
  has table-half.exr "half openexr" "tile size: 32 x 16" 'compression: "piz"'
run "$cmf" bake-moments "$driver" -o moments-float.exr -q
run "$cmf" bake-moments "$driver" -o moments-half.exr -q -d half --tile 128 32 --compression zip:9 &&
  has moments-half.exr "half openexr" "tile size: 128 x 32" 'compression: "zip"'
run "$cmf" bake-moments "$driver" -o moments-piz.exr -q --compression piz
run "$cmf" bake-noise --noise fbm:octaves=2 -o noise-half.exr -q -d half --max-footprints 1024 && has noise-half.exr "half openexr"
# Lossless: the same pixels.
idiff -q -fail 0 -failpercent 0 -warn 0 moments-float.exr moments-piz.exr > /dev/null ||
  { echo "FAIL: piz moments differ from zip moments"; fail=1; }
# Half files read back everywhere; the error half moments cost at LOD 4.
run "$cmf" apply --moments moments-float.exr --table table-float.exr --lod 4 -o float.exr -q
run "$cmf" apply --moments moments-half.exr --table table-half.exr --lod 4 -o half.exr -q
if run "$cmf" compare float.exr half.exr --json; then
  python3 -c "import json,sys; m=json.load(open('last.out'))['ciede2000']['mean']; sys.exit(0 if 0 < m < 0.05 else 1)" ||
    { echo "FAIL: half files at LOD 4: mean CIEDE2000 not in (0, 0.05):"; cat last.out; fail=1; }
fi
run "$cmf" info moments-half.exr && grep -q "moment pyramid" last.out || { echo "FAIL: info on half moments"; fail=1; }
# A squared deviation past 65504 does not fit a half: refused, nothing written.
oiiotool --pattern fill:top=0:bottom=100000 16x16 1 -d float -o big.exr
"$cmf" bake-moments big.exr -o big-half.exr -d half > last.out 2> last.err; rc=$?
[ "$rc" = 3 ] || { echo "FAIL: a driver past half range exited $rc"; cat last.err; fail=1; }
grep -q "does not fit a half (|v| <= 65504); write float" last.err || { echo "FAIL: message:"; cat last.err; fail=1; }
ls -a | grep -q "big-half" && { echo "FAIL: a partial output was left"; ls -a; fail=1; }
run "$cmf" bake-moments big.exr -o big-float.exr -q
[ "$fail" = 0 ] && echo "storage: types, tiles and compressions read back; half moments within 0.05 at LOD 4; half overflow refused"
exit $fail
