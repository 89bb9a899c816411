#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Sigma against LOD for each noise kind: bakes each noise's sigma table with
# `cmfilter bake-noise --csv` and charts the box and Gaussian columns, with
# the noise's global sigma as a horizontal line (docs/noise-accuracy.md).
# Writes docs/data/noise-sigma-KIND.csv and docs/images/noise-sigma-KIND.png.
#
#   bash tests/bench/noise_sigma_charts.sh BUILD_DIR WORK_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
root=$(cd "$(dirname "$0")/../.." && pwd)
cmf="$build/tools/cmfilter"
# kind|spec|extra bake-noise options
noises=(
  "gradient-fbm|fbm:base=gradient,octaves=6|"
  "value-fbm|fbm:base=value,octaves=6|"
  "turbulence|turbulence:base=gradient,octaves=6|"
  "gabor|fbm:base=gabor,octaves=3|--max-footprints 4096"
  "gradient|gradient|"
)
for entry in "${noises[@]}"; do
  IFS='|' read -r kind spec extra <<< "$entry"
  # shellcheck disable=SC2086
  "$cmf" bake-noise --noise "$spec" -o "$work/$kind.exr" --csv "$root/docs/data/noise-sigma-$kind.csv" \
    --json $extra > "$work/$kind.json"
  global=$(python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(d['global']['sigma'])" "$work/$kind.json")
  gnuplot <<GNUPLOT
set terminal pngcairo size 900,600 font "sans,11"
set output "$root/docs/images/noise-sigma-$kind.png"
set title "unresolved sigma against LOD: $spec"
set xlabel "LOD = log2(footprint width / base period)"
set ylabel "sigma (log scale)"
set logscale y
set grid
set key right bottom
set datafile separator ","
plot "$root/docs/data/noise-sigma-$kind.csv" using 1:3 skip 1 with linespoints lw 2 pt 7 title "box", \
     "" using 1:7 skip 1 with linespoints lw 2 pt 5 title "Gaussian", \
     $global with lines dt 2 lw 2 lc rgb "black" title sprintf("global sigma %.4f", $global)
GNUPLOT
  echo "noise_sigma_charts: $kind" >&2
done
