#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Samples for the synthesis commands' tests, each bad one wrong in one way:
# a 24 x 24 noise image (and a second one, another sample), a 12 x 12 one
# (too small for a map made from the first), an empty file, a BTF manifest
# of two view slots of the stack fixtures' 8 x 8 stack, and coordinate maps
# written by oiiotool: one in range and one pointing outside the sample.
#   make_synth_fixtures.sh OIIOTOOL STACK_FIXTURES DIR
set -euo pipefail
oiiotool=$1
stacks=$2
dir=$3
rm -rf "$dir"
mkdir -p "$dir"
cd "$dir"
"$oiiotool" --pattern noise:type=uniform:min=0.1:max=0.9:seed=3 24x24 3 -d uint8 -o sample.png
"$oiiotool" --pattern noise:type=uniform:min=0.1:max=0.9:seed=4 24x24 3 -d uint8 -o other.png
"$oiiotool" --pattern noise:type=uniform:min=0.1:max=0.9:seed=5 12x12 3 -d uint8 -o small.png
: > empty.png
cat > btf.json <<JSON
{"format": "cmfilter-btf", "version": 1,
 "views": [{"lights": "$stacks/good.lp", "view": [0, 0, 1]},
           {"lights": "$stacks/good.lp", "view": [0.5, 0, 0.866]}]}
JSON
meta=(--attrib cmfilter:kind coordinate-map --attrib:type=int cmfilter:format_version 1
      --attrib cmfilter:sample sample.png --attrib cmfilter:sample_hash 0
      --attrib cmfilter:sample_kind image --attrib:type=int cmfilter:sample_width 24
      --attrib:type=int cmfilter:sample_height 24 --attrib:type=int cmfilter:sample_periodic 0
      --attrib:type=int cmfilter:k 1 --attrib:type=int cmfilter:neighbourhood 1
      --attrib:type=int cmfilter:levels 1 --attrib:type=int cmfilter:toroidal 0
      --attrib:type=int cmfilter:seed 1)
"$oiiotool" --pattern constant:color=0.3,0.6 8x8 2 --chnames u,v "${meta[@]}" -d float -o map-inside.exr
"$oiiotool" --pattern constant:color=1.5,0.6 8x8 2 --chnames u,v "${meta[@]}" -d float -o map-outside.exr
