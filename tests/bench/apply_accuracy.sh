#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Accuracy of `cmfilter apply`'s methods against the box-filtered ground truth
# (`--method reference`), LOD 0..8, for every bundled colour map, on
#   gaussian  a Gaussian-like driver (blurred white noise, mean 0.5, sd 0.18:
#             its 1st-99th percentile range spans 84% of the domain [0, 1])
#   q2 q4 q16 a driver made the same way at QSIZE^2 (default 1024), quantised
#             to 2 (binary), 4 and 16 levels, where `exact` applies
# Tables have VALUES value nodes (default 2048): at LOD 0 (sigma = 0) a
# coarser value axis adds its own bilinear error at the map's hard edges
# (docs/bake-colormap.md), which is not what this experiment measures.
# Writes WORK/accuracy.csv (driver,map,lod,method,mean,p95,max CIEDE2000) and,
# when gnuplot is installed, the charts docs/images/apply-accuracy-*.png.
#
#   bash tests/bench/apply_accuracy.sh BUILD_DIR WORK_DIR [SIZE] [BLUR] [QSIZE] [VALUES]
#   bash tests/bench/apply_accuracy.sh --charts WORK_DIR [SIZE] [BLUR] [QSIZE]   (charts only)
# (docs/apply.md shows the figures of `... build /tmp/accuracy 2048 8 1024 2048`).
set -euo pipefail
if [ "${1:-}" = --charts ]; then  # --charts WORK_DIR [SIZE] [BLUR] [QSIZE]: redraw from WORK_DIR/accuracy.csv
  charts_only=1
  shift
  set -- . "$@"
fi
build=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
size=${3:-2048}
blur=${4:-8}
qsize=${5:-1024}
values=${6:-2048}
root=$(cd "$(dirname "$0")/../.." && pwd)
cmf="$build/tools/cmfilter"
make_drivers="$build/tests/bench/cmfilter-make-drivers"
maps=(terrain stripes step narrow-band hue-ramp)
drivers=(gaussian q2 q4 q16)

# Charts from $csv into docs/images (needs gnuplot).
draw_charts() {
if command -v gnuplot > /dev/null; then
  for d in "${drivers[@]}"; do
    for map in "${maps[@]}"; do
      for m in naive gaussian exact; do
        awk -F, -v d="$d" -v map="$map" -v m="$m" '$1 == d && $2 == map && $4 == m { print $3, $5 }' "$csv" \
          > "$work/$d-$map-$m.dat"
      done
    done
  done
  for d in "${drivers[@]}"; do
    title="Gaussian-like driver (noise blurred by ${blur} texels, ${size}^2)"
    [ "$d" = gaussian ] || title="the same kind of driver quantised to ${d#q} levels (${qsize}^2)"
    label=""
    [ "$d" = gaussian ] || label='set label "exact: 0 up to float rounding (drawn at 1e-4)" at 0.2,2e-4' 
    plots=""
    for i in "${!maps[@]}"; do
      map=${maps[$i]}
      plots+="'$work/$d-$map-gaussian.dat' using 1:(\$2 > 0 ? \$2 : 1e-4) with linespoints lw 2 pt 7 lc $((i + 1)) title '$map gaussian', "
      plots+="'$work/$d-$map-naive.dat' using 1:(\$2 > 0 ? \$2 : 1e-4) with linespoints lw 1 dt 2 pt 6 lc $((i + 1)) title '$map naive', "
      [ "$d" = gaussian ] || plots+="'$work/$d-$map-exact.dat' using 1:(\$2 > 0 ? \$2 : 1e-4) with linespoints lw 1 dt 3 pt 4 lc $((i + 1)) title '$map exact', "
    done
    gnuplot <<GNUPLOT
set terminal pngcairo size 1100,700 font "sans,11"
set output "$root/docs/images/apply-accuracy-$d.png"
set title "$title: mean CIEDE2000 against the box-filtered reference"
set xlabel "LOD (log2 of the footprint width in driver texels)"
set ylabel "mean CIEDE2000 (log scale)"
set logscale y
set yrange [1e-4:100]
set xrange [-0.2:8.2]
set grid
set key outside right top
set arrow from -0.2,1 to 8.2,1 nohead dt 4 lw 2 lc rgb "black"
set label "target for gaussian: 1.0" at 0,1.3
${label}
plot ${plots%, }
GNUPLOT
  done
  rm -f "$work"/*.dat
else
  echo "apply_accuracy: gnuplot not found, no charts (apt-get install gnuplot-nox)" >&2
fi
}

csv="$work/accuracy.csv"
if [ "${charts_only:-}" = 1 ]; then draw_charts; exit 0; fi

"$make_drivers" gaussian "$size" "$blur" "$work/gaussian.exr"
"$make_drivers" gaussian "$qsize" "$blur" "$work/gaussian-q.exr" 2
for q in 2 4 16; do "$make_drivers" quantise "$q" "$work/gaussian-q.exr" "$work/q$q.exr"; done
for map in "${maps[@]}"; do
  "$cmf" bake-colormap "$root/luts/$map.png" -o "$work/$map-table.exr" --values "$values" -q
done
for d in "${drivers[@]}"; do
  histograms=()
  [ "$d" = gaussian ] || histograms=(--histograms "$work/$d-histograms.exr")
  "$cmf" bake-moments "$work/$d.exr" -o "$work/$d-moments.exr" "${histograms[@]}" -q
done

echo "driver,map,lod,method,mean,p95,max" > "$csv"
# The CIEDE2000 line of `compare`: "dE2000 mean X", "dE2000 p95 X", "dE2000 max X".
stat() { awk -v k="$2" '$1 == "dE2000" && $2 == k { print $3 }' "$1"; }
for d in "${drivers[@]}"; do
  methods=(naive gaussian)
  extra=()
  if [ "$d" != gaussian ]; then methods+=(exact); extra=(--histograms "$work/$d-histograms.exr"); fi
  for map in "${maps[@]}"; do
    for lod in 0 1 2 3 4 5 6 7 8; do
      common=(--moments "$work/$d-moments.exr" --table "$work/$map-table.exr" --lod "$lod" -q)
      # (the few texels of the Gaussian driver beyond [0, 1] take the end
      # colours of these clamp maps, in every method alike: no warning needed)
      "$cmf" apply "${common[@]}" --method reference -o "$work/ref.exr" 2> /dev/null
      for m in "${methods[@]}"; do
        "$cmf" apply "${common[@]}" "${extra[@]}" --method "$m" -o "$work/out.exr" 2> /dev/null
        "$cmf" compare "$work/ref.exr" "$work/out.exr" > "$work/compare.txt"
        echo "$d,$map,$lod,$m,$(stat "$work/compare.txt" mean),$(stat "$work/compare.txt" p95),$(stat "$work/compare.txt" max)" >> "$csv"
      done
      echo "apply_accuracy: $d $map LOD $lod" >&2
    done
  done
done
rm -f "$work/ref.exr" "$work/out.exr" "$work/compare.txt"

draw_charts
echo "apply_accuracy: wrote $csv" >&2
