#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Accuracy of the filtered noise colour T(mean, sigma) (sec. 4.2) and of the
# naive C0(mean) against a supersampled reference (32 x 32 jittered samples
# per square footprint), per bundled map and LOD, for 6-octave gradient fBm and
# turbulence (build/tests/bench/cmfilter-noise-accuracy; docs/noise-accuracy.md).
# Charts: gaussian with the 2048-value table solid (the default 256-value
# table dotted: its value axis dominates at small sigma), naive dashed.
# Writes WORK/noise-accuracy.csv (noise,map,lod,width,method,mean,p95,max),
# copies it to docs/data/, and draws docs/images/noise-accuracy-{fbm,turbulence}.png.
#
#   bash tests/bench/noise_accuracy.sh BUILD_DIR WORK_DIR [P]
set -euo pipefail
build=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
points=${3:-4096}
root=$(cd "$(dirname "$0")/../.." && pwd)
prog="$build/tests/bench/cmfilter-noise-accuracy"
maps=(terrain stripes step narrow-band hue-ramp)
csv="$work/noise-accuracy.csv"

"$prog" "$root/luts" fbm 'fbm:base=gradient,octaves=6' "$points" > "$work/fbm.csv"
"$prog" "$root/luts" turbulence 'turbulence:base=gradient,octaves=6' "$points" > "$work/turbulence.csv"
{ cat "$work/fbm.csv"; tail -n +2 "$work/turbulence.csv"; } > "$csv"
cp "$csv" "$root/docs/data/noise-accuracy.csv"

for noise in fbm turbulence; do
  plots=""
  for i in "${!maps[@]}"; do
    map=${maps[$i]}
    for m in gaussian gaussian-2048 naive; do
      awk -F, -v n="$noise" -v map="$map" -v m="$m" '$1 == n && $2 == map && $5 == m { print $3, $6 }' "$csv" \
        > "$work/$noise-$map-$m.dat"
    done
    plots+="'$work/$noise-$map-gaussian-2048.dat' using 1:(\$2 > 0 ? \$2 : 1e-3) with linespoints lw 2 pt 7 lc $((i + 1)) title '$map gaussian (2048 values)', "
    plots+="'$work/$noise-$map-gaussian.dat' using 1:(\$2 > 0 ? \$2 : 1e-3) with lines lw 1 dt 3 lc $((i + 1)) title '$map gaussian (256 values)', "
    plots+="'$work/$noise-$map-naive.dat' using 1:(\$2 > 0 ? \$2 : 1e-3) with linespoints lw 1 dt 2 pt 6 lc $((i + 1)) title '$map naive', "
  done
  gnuplot <<GNUPLOT
set terminal pngcairo size 1100,700 font "sans,11"
set output "$root/docs/images/noise-accuracy-$noise.png"
set title "$noise (gradient, 6 octaves), ${points} footprints per LOD: mean CIEDE2000 vs 32x32 supersampling"
set xlabel "LOD = log2(footprint width / base period)"
set ylabel "mean CIEDE2000 (log scale)"
set logscale y
set yrange [1e-3:100]
set xrange [-9.2:2.2]
set grid
set key outside right top
set arrow from -9.2,1 to 2.2,1 nohead dt 4 lw 2 lc rgb "black"
set label "target: 1.0" at -9,1.3
plot ${plots%, }
GNUPLOT
done
rm -f "$work"/*.dat
echo "noise_accuracy: wrote $csv" >&2
