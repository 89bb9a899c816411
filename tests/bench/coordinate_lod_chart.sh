#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Error of rendering through a coordinate map at LOD L = 1 .. 6 against the
# box-filtered full-size output, per method (coordinate_lookup.h): the naive
# mip of the coordinates, the centre texel's coordinate, the synthesis's own
# level maps (where the map has them) and the per-footprint patch offsets.
# Runs build/tests/bench/cmfilter-coordinate-lod-accuracy with ARGS (default:
# --synthetic-seams, random rectangular patches of a procedural sample), and
# writes OUT_DIR/coordinate-lod-accuracy.csv, OUT_DIR/coordinate-lod-rmse.png
# (RMSE per LOD) and OUT_DIR/coordinate-lod-time.png (ms per LOD).
#
#   bash tests/bench/coordinate_lod_chart.sh BUILD_DIR OUT_DIR [ARGS...]
set -euo pipefail
build=$(cd "$1" && pwd)
mkdir -p "$2"
out=$(cd "$2" && pwd)
shift 2
args=("$@")
if [ ${#args[@]} -eq 0 ]; then args=(--synthetic-seams); fi
csv="$out/coordinate-lod-accuracy.csv"
"$build/tests/bench/cmfilter-coordinate-lod-accuracy" "${args[@]}" > "$csv"

methods=(naive point levels patches)
rmse_plots=""
time_plots=""
for i in "${!methods[@]}"; do
  m=${methods[$i]}
  awk -F, -v m="$m" '$2 == m { print $1, $3, $5 }' "$csv" > "$out/coordinate-lod-$m.dat"
  [ -s "$out/coordinate-lod-$m.dat" ] || continue
  rmse_plots+="'$out/coordinate-lod-$m.dat' using 1:(\$2 > 0 ? \$2 : 1e-6) with linespoints lw 2 pt 7 lc $((i + 1)) title '$m', "
  time_plots+="'$out/coordinate-lod-$m.dat' using 1:3 with linespoints lw 2 pt 7 lc $((i + 1)) title '$m', "
done
awk -F, '$2 == "reference" { print $1, $5 }' "$csv" > "$out/coordinate-lod-reference.dat"
time_plots+="'$out/coordinate-lod-reference.dat' using 1:2 with linespoints lw 1 dt 2 pt 6 lc 8 title 'reference (full size, box-filtered)'"

gnuplot <<GNUPLOT
set terminal pngcairo size 900,600 font "sans,11"
set output "$out/coordinate-lod-rmse.png"
set title "Rendering through a coordinate map at LOD L: RMSE against the box-filtered full-size output"
set xlabel "LOD L (footprint 2^L x 2^L texels)"
set ylabel "RMSE (log scale)"
set logscale y
set grid
set key top left
plot ${rmse_plots%, }
set output "$out/coordinate-lod-time.png"
set title "Time per LOD level rendered (ms, fastest of 3)"
set ylabel "ms (log scale)"
plot $time_plots
GNUPLOT
echo "wrote $csv, $out/coordinate-lod-rmse.png, $out/coordinate-lod-time.png"
