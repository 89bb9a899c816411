#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Small image stacks for the stack commands' bad-input tests, each wrong in
# one way only: a good 8-light stack of 8 x 8 PNGs made with oiiotool, and
# light files that break one rule each.
#   make_stack_fixtures.sh OIIOTOOL DIR
set -euo pipefail
oiiotool=$1
dir=$2
rm -rf "$dir"
mkdir -p "$dir"
cd "$dir"
# The same colour under every light: every model holds it exactly.
for k in 0 1 2 3 4 5 6 7 8 9 10 11; do
  "$oiiotool" --pattern constant:color=0.6,0.5,0.3 8x8 3 -d uint8 -o img-$k.png
done
"$oiiotool" --pattern constant:color=0.6,0.5,0.3 4x4 3 -d uint8 -o small.png
"$oiiotool" --pattern constant:color=0.5,0.5,0.5 9x8 3 -d uint8 -o wide.png
"$oiiotool" --pattern constant:color=0.5 8x8 1 -d uint8 -o grey.png

# Twelve lights over three elevations: a good PTM and HSH set (the bad
# stacks take the first eight).
good_lights=(
  "0.8 0 0.6" "0 0.8 0.6" "-0.8 0 0.6" "0 -0.8 0.6"
  "0.3 0.3 0.905539" "-0.3 0.3 0.905539" "-0.3 -0.3 0.905539" "0.3 -0.3 0.905539"
  "0.6 0.6 0.52915" "-0.6 0.6 0.52915" "-0.6 -0.6 0.52915" "0.6 -0.6 0.52915")
lp() {  # lp NAME COUNT then lines on stdin
  { echo "$2"; cat; } > "$1"
}
{ for k in 0 1 2 3 4 5 6 7 8 9 10 11; do echo "img-$k.png ${good_lights[$k]}"; done; } | lp good.lp 12
{ for k in 0 1 2 3 4 5 6 7; do echo "img-$k.png ${good_lights[$k]}"; done; } | lp count.lp 9
{ for k in 0 1 2 3 4 5 6 7; do echo "small.png ${good_lights[$k]}"; done; } | lp small.lp 8
{ for k in 0 1 2 3 4 5 6; do echo "img-$k.png ${good_lights[$k]}"; done; echo "gone.png 0 0 1"; } | lp missing.lp 8
{ for k in 0 1 2 3 4 5 6; do echo "img-$k.png ${good_lights[$k]}"; done; echo "wide.png 0 0 1"; } | lp size.lp 8
{ for k in 0 1 2 3 4 5 6; do echo "img-$k.png ${good_lights[$k]}"; done; echo "grey.png 0 0 1"; } | lp channels.lp 8
{ for k in 0 1 2 3 4 5 6; do echo "img-$k.png ${good_lights[$k]}"; done; echo "img-7.png 0 0 0"; } | lp zero.lp 8
{ for k in 0 1 2 3 4 5 6; do echo "img-$k.png ${good_lights[$k]}"; done; echo "img-7.png 0 inf 1"; } | lp infinite.lp 8
{ for k in 0 1 2 3 4 5 6; do echo "img-$k.png ${good_lights[$k]}"; done; echo "img-7.png 0.5 0 -0.2"; } | lp below.lp 8
{ for k in 0 1 2 3 4 5 6; do echo "img-$k.png ${good_lights[$k]}"; done; echo "img-7.png 0,5 0 0,8"; } | lp comma.lp 8
{ for k in 0 1 2; do echo "img-$k.png ${good_lights[$k]}"; done; echo "img-3.png 0 0.8"
  for k in 4 5 6 7; do echo "img-$k.png ${good_lights[$k]}"; done; } | lp malformed.lp 8
{ for k in 0 1 2 3 4; do echo "img-$k.png ${good_lights[$k]}"; done; } | lp five.lp 5
# All eight on the line lv = 0 (x from -0.9 to 0.9): collinear.
{ k=0; for x in -0.9 -0.6 -0.3 -0.1 0.1 0.3 0.6 0.9; do echo "img-$k.png $x 0 $(awk -v x=$x 'BEGIN{print sqrt(1-x*x)}')"; k=$((k+1)); done; } | lp collinear.lp 8
# All twelve at 30 degrees of elevation.
{ for k in 0 1 2 3 4 5 6 7 8 9 10 11; do awk -v k=$k 'BEGIN { a = k * 3.14159265358979 / 6; printf "img-%d.png %.9f %.9f 0.5\n", k, 0.866025404 * cos(a), 0.866025404 * sin(a) }'; done; } | lp elevation.lp 12
