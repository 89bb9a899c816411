#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Error against bytes per level-0 texel on the 96 photograph cases (camera,
# moon, coins, gravel through stripes, step and narrow-band, LOD 1-8): per
# case and method, the worst mean CIEDE2000 over the LODs against the box
# reference, at the bytes a renderer keeps per texel (float32): naive 4,
# gaussian 8, mixture 16 (docs/data/photo-accuracy.csv), the colour pyramid
# 12 (docs/data/color-pyramid-accuracy.csv), the segment pyramid 4 K, with
# every exact breakpoint and with --tolerance 0.5
# (docs/data/segments-accuracy.csv), and exact, the histogram pyramid, 4 a
# distinct value of the driver (docs/data/photo-exact-accuracy.csv:
# photo_accuracy.sh with METHODS exact). Draws docs/images/segments-bytes.png
# (needs gnuplot); errors below 1e-5 (0 up to rounding) are drawn at 1e-5.
#
#   bash tests/bench/segments_bytes_chart.sh [WORK_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
work=${1:-$(mktemp -d)}
mkdir -p "$work"
/usr/bin/python3 - "$root/docs/data" "$work" <<'PY'
import csv, sys, collections
data, work = sys.argv[1], sys.argv[2]
worst = collections.defaultdict(float); size = {}
def add(method, case, mean, nbytes):
    k = (method, case); worst[k] = max(worst[k], mean); size[k] = nbytes
for r in csv.DictReader(open(f"{data}/photo-accuracy.csv")):
    if int(r["lod"]) < 1: continue
    add(r["method"], (r["driver"], r["map"]), float(r["mean"]), {"naive": 4, "gaussian": 8, "mixture": 16}[r["method"]])
import numpy, skimage.data
distinct = {d: len(numpy.unique(getattr(skimage.data, d)())) for d in ("camera", "moon", "coins", "gravel")}
for r in csv.DictReader(open(f"{data}/photo-exact-accuracy.csv")):
    if int(r["lod"]) >= 1 and r["method"] == "exact":
        add("exact", (r["driver"], r["map"]), float(r["mean"]), 4 * distinct[r["driver"]])
for r in csv.DictReader(open(f"{data}/color-pyramid-accuracy.csv")):
    if r["set"] == "photographs" and r["method"] == "color-pyramid":
        add("color-pyramid", (r["driver"], r["map"]), float(r["mean"]), 12)
for r in csv.DictReader(open(f"{data}/segments-accuracy.csv")):
    if r["set"] == "photographs" and r["method"].startswith("segments-"):
        add(r["method"], (r["driver"], r["map"]), float(r["mean"]), 4 * int(r["channels"]))
methods = sorted({m for m, _ in worst})
for m in methods:
    with open(f"{work}/{m}.dat", "w") as out:
        for (mm, case), e in sorted(worst.items()):
            if mm == m: out.write(f"{size[(mm, case)]} {max(e, 1e-5)} {case[0]}-{case[1]}\n")
    print(m, "cases", sum(1 for k in worst if k[0] == m), "worst", max(e for k, e in worst.items() if k[0] == m))
open(f"{work}/methods.txt", "w").write(" ".join(methods))
PY
command -v gnuplot > /dev/null || { echo "segments_bytes_chart: gnuplot not found, data in $work" >&2; exit 0; }
plots=""
i=1
for m in $(cat "$work/methods.txt"); do
  plots+="'$work/$m.dat' using 1:2 with points pt $((i + 4)) ps 1.4 lc $i title '$m', "
  i=$((i + 1))
done
gnuplot <<GNUPLOT
set terminal pngcairo size 1100,650 font "sans,11"
set output "$root/docs/images/segments-bytes.png"
set title "96 photograph cases (4 photographs x stripes, step, narrow-band x LOD 1-8): per driver and map, the worst LOD"
set xlabel "bytes per level-0 texel (float32)"
set ylabel "worst mean CIEDE2000 against the box reference (log; exact drawn at 1e-5)"
set logscale xy
set format y "%g"
set xrange [2:2000]
set yrange [5e-6:50]
set grid
set key outside right top
plot ${plots%, }
GNUPLOT
echo "segments_bytes_chart: wrote docs/images/segments-bytes.png" >&2
