#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# -u/--update (maketx's spelling) on bake-colormap, bake-moments and
# bake-noise: a second run whose outputs record the same build (inputs by
# content, parameters, cmfilter version) does nothing, says so and leaves the
# files untouched (same inode and modification time); a changed parameter, a
# changed input, a missing second output, or a record of another build (as
# another cmfilter version writes) rebuilds. Without -u every run rebuilds.
# The same inputs in another folder are the same build.
#   check_update.sh CMFILTER MAP DRIVER WORKDIR
set -uo pipefail
cmf=$1 map=$2 driver=$3 work=$4
fail=0
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
cp "$map" map.png && cp "$driver" driver.png
stamp() { stat -c '%i %Y.%y' "$1"; }
# expect WORD COMMAND...: WORD is "skips" or "builds"; the command must exit 0.
expect() {
  local word=$1; shift
  local out; out=$("$@" 2>&1) || { echo "FAIL: $* exited non-zero: $out"; fail=1; return; }
  if [ "$word" = skips ]; then
    grep -q "^up to date: " <<< "$out" || { echo "FAIL: expected a skip from: $*"; echo "$out"; fail=1; }
  else
    grep -q "^up to date: " <<< "$out" && { echo "FAIL: expected a build from: $*"; echo "$out"; fail=1; }
  fi
}
untouched() {  # untouched FILE STAMP
  [ "$(stamp "$1")" = "$2" ] || { echo "FAIL: $1 was rewritten"; fail=1; }
}

# bake-colormap
"$cmf" bake-colormap map.png -o table.exr -q --values 64 --sigmas 32 || fail=1
sleep 1.1  # a rewrite would show in the modification time
before=$(stamp table.exr)
expect skips "$cmf" bake-colormap map.png -o table.exr --values 64 --sigmas 32 -u
expect skips "$cmf" bake-colormap map.png -o table.exr --sigmas 32 --values 64 --update --threads 1  # order, threads
untouched table.exr "$before"
expect builds "$cmf" bake-colormap map.png -o table.exr --values 128 --sigmas 32 -u         # a parameter
expect builds "$cmf" bake-colormap map.png -o table.exr --values 128 --sigmas 32            # no -u: always
expect skips "$cmf" bake-colormap map.png -o table.exr --values 128 --sigmas 32 -u
oiiotool map.png --cmul 0.9 -d uint8 -o map-dark.png && mv map-dark.png map.png  # the input's content changes
expect builds "$cmf" bake-colormap map.png -o table.exr --values 128 --sigmas 32 -u
# Another build's record (another cmfilter version, say): rebuilt.
oiiotool table.exr --attrib cmfilter:build 0000 -o other.exr && mv other.exr table.exr
expect builds "$cmf" bake-colormap map.png -o table.exr --values 128 --sigmas 32 -u
# Moved inputs are the same build: a copy of the folder skips.
mkdir -p elsewhere/deeper && cp map.png table.exr elsewhere/deeper/
pushd elsewhere/deeper > /dev/null
expect skips "$cmf" bake-colormap map.png -o table.exr --values 128 --sigmas 32 -u
popd > /dev/null
# The JSON says so.
json=$("$cmf" bake-colormap map.png -o table.exr --values 128 --sigmas 32 -u --json)
python3 -c "import json,sys; d=json.loads(sys.argv[1]); assert d['up_to_date'] is True and len(d['build']) == 64, d" "$json" ||
  { echo "FAIL: -u --json: $json"; fail=1; }

# bake-moments, with its second output
"$cmf" bake-moments driver.png -o moments.exr --histograms hist.exr -q || fail=1
sleep 1.1
before=$(stamp moments.exr)
expect skips "$cmf" bake-moments driver.png -o moments.exr --histograms hist.exr -u
untouched moments.exr "$before"
rm hist.exr
expect builds "$cmf" bake-moments driver.png -o moments.exr --histograms hist.exr -u
expect builds "$cmf" bake-moments driver.png -o moments.exr --wrap periodic -u

# bake-noise
"$cmf" bake-noise --noise gradient:seed=3 --lod-step 1 --max-footprints 1024 -o sigma.exr -q || fail=1
expect skips "$cmf" bake-noise --noise gradient:seed=3 --lod-step 1 --max-footprints 1024 -o sigma.exr -u
expect builds "$cmf" bake-noise --noise gradient:seed=4 --lod-step 1 --max-footprints 1024 -o sigma.exr -u
[ "$fail" = 0 ] && echo "update: up-to-date outputs skipped and untouched; parameter, input, output and record changes rebuilt"
exit $fail
