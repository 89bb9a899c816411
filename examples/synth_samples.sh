#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The bundled synthesis samples (docs/synthesis.md), besides the synthetic
# stacks of make_stacks.sh:
#   brick.png, grass.png, gravel.png  crops of scikit-image's photographs
#                 (Debian's python3-skimage), 512 x 512 reduced to 128 x 128
#                 then the top-left 64 x 64 (the paper's sample size);
#   terrain.png   a procedural texture: fBm of gradient noise through
#                 luts/terrain.png (cmfilter noise-image, over -0.8..0.8, then apply at LOD 0
#                 by naive, which is C(f) exactly there), 64 x 64.
#   bash examples/synth_samples.sh CMFILTER_BINARY OUTPUT_DIR
set -euo pipefail
cmfilter=${1:?usage: synth_samples.sh CMFILTER_BINARY OUTPUT_DIR}
out=${2:?usage: synth_samples.sh CMFILTER_BINARY OUTPUT_DIR}
root=$(cd "$(dirname "$0")/.." && pwd)
photos=/usr/lib/python3/dist-packages/skimage/data
mkdir -p "$out"
for name in brick grass gravel; do
  if [ ! -f "$photos/$name.png" ]; then
    echo "synth_samples.sh: $photos/$name.png is missing (install Debian's python3-skimage)" >&2
    exit 2
  fi
  oiiotool "$photos/$name.png" --resize 128x128 --cut 64x64+0+0 -d uint8 -o "$out/$name.png"
done
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$cmfilter" noise-image --noise fbm:base=gradient,octaves=5,seed=3 --size 64x64 --scale 0.08 \
  -o "$tmp/terrain-driver.exr" -q
"$cmfilter" bake-colormap "$root/luts/terrain.png" --domain=-0.8:0.8 -o "$tmp/terrain-table.exr" -q
"$cmfilter" bake-moments "$tmp/terrain-driver.exr" -o "$tmp/terrain-moments.exr" -q
"$cmfilter" apply --moments "$tmp/terrain-moments.exr" --table "$tmp/terrain-table.exr" --lod 0 --method naive \
  -o "$out/terrain.png" -q
