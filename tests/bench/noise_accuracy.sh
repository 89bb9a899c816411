#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Accuracy of the filtered noise colour T(mean, sigma) (sec. 4.2) and of the
# naive C0(mean) against a supersampled reference (32 x 32 jittered samples
# per square footprint), per bundled map and LOD, for 6-octave gradient fBm and
# turbulence (build/tests/bench/cmfilter-noise-accuracy; docs/noise-accuracy.md).
# Charts: gaussian with the 2048-value table solid (the default 256-value
# table dotted: its value axis dominates at small sigma), naive dashed.
# Writes WORK/noise-accuracy.csv (noise,map,lod,width,method,mean,p95,max),
# copies it to docs/data/, and draws docs/images/noise-accuracy-{fbm,turbulence}.png
# and docs/images/noise-accuracy-mixture.png (the worst map's mean error per
# LOD for each method: one Gaussian, sub-footprints, the oracle, the best
# one-lookup table).
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
# The worst map per LOD and method, both noises side by side.
python3 - "$csv" "$work" <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
worst = {}
for r in rows:
    key = (r["noise"], r["method"], float(r["lod"]))
    worst[key] = max(worst.get(key, 0.0), float(r["mean"]))
for (noise, method, lod), value in sorted(worst.items()):
    with open(f"{sys.argv[2]}/worst-{noise}-{method}.dat", "a") as f:
        f.write(f"{lod} {value}\n")
EOF
series=("gaussian-2048:7:blue:gaussian (2048 values)" "oracle-2048:4:gray:oracle: own mean and sd, one Gaussian"
        "conditional-table:13:dark-green:one lookup at best: E[C | filtered mean] per LOD"
        "mixture-4:9:orange:mixture, up to 4 x 4" "mixture:5:brown:mixture, up to 8 x 8 (256 values)"
        "mixture-2048:5:red:mixture, up to 8 x 8 (2048 values)")
{
  echo 'set terminal pngcairo size 1200,520 font "sans,11"'
  echo "set output \"$root/docs/images/noise-accuracy-mixture.png\""
  echo 'set multiplot layout 1,2 title "Worst bundled map per LOD: one Gaussian against sub-footprints (mean CIEDE2000 vs 32x32 supersampling)"'
  echo 'set logscale y; set yrange [0.1:40]; set xrange [-9.2:2.2]; set grid; set key top left font ",9"'
  echo 'set xlabel "LOD = log2(footprint width / base period)"; set ylabel "worst map mean CIEDE2000"'
  echo 'set arrow 1 from -9.2,1 to 2.2,1 nohead dt 4 lw 2 lc rgb "black"'
  for noise in fbm turbulence; do
    echo "set title \"$noise (gradient, 6 octaves)\""
    plots=""
    for s in "${series[@]}"; do
      IFS=: read -r m pt colour title <<< "$s"
      plots+="'$work/worst-$noise-$m.dat' with linespoints lw 2 pt $pt lc rgb '$colour' title '$title', "
    done
    echo "plot ${plots%, }"
  done
  echo 'unset multiplot'
} > "$work/mixture.gp"
gnuplot "$work/mixture.gp"
rm -f "$work"/*.dat
echo "noise_accuracy: wrote $csv" >&2
