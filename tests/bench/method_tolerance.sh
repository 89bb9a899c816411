#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `--tolerance DE` choosing a method per material (docs/apply.md, "Choosing a
# method for a tolerance"): for each photograph (scikit-image's camera, moon,
# coins, gravel; 8-bit grey read as data in [0, 1]) through each bundled map
# (terrain, hue ramp, narrow band, stripes, step), `apply --tolerance DE
# --json` with order-4 moments and the histogram pyramid, so that every
# method (naive, gaussian, mixture, exact) is a candidate; LODs 1..8. Writes
# WORK/method-tolerance.csv: driver,map,tolerance,chosen,error,bytes_per_texel,
# then the worst mean CIEDE2000 of each method and the time of each (ms, one
# thread, every measured LOD), and the command's total time.
#
#   bash tests/bench/method_tolerance.sh BUILD_DIR WORK_DIR [TOLERANCES] [DRIVERS] [MAPS]
set -euo pipefail
build=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
tolerances=(${3:-1 2 5})
drivers=(${4:-camera moon coins gravel})
maps=(${5:-terrain hue-ramp narrow-band stripes step})
root=$(cd "$(dirname "$0")/../.." && pwd)
cmf="$build/tools/cmfilter"

for d in "${drivers[@]}"; do
  /usr/bin/python3 -c "import sys, skimage.io, skimage.data as d; skimage.io.imsave(sys.argv[2], getattr(d, sys.argv[1])(), check_contrast=False)" \
    "$d" "$work/$d.png"
  "$cmf" bake-moments "$work/$d.png" -o "$work/$d-moments.exr" --order 4 --histograms "$work/$d-histograms.exr" -q
done
for map in "${maps[@]}"; do
  "$cmf" bake-colormap "$root/luts/$map.png" -o "$work/$map-table.exr" --values 2048 -q
done

csv="$work/method-tolerance.csv"
echo "driver,map,tolerance,chosen,error,bytes_per_texel,naive,gaussian,mixture,exact,naive_ms,gaussian_ms,mixture_ms,exact_ms,reference_ms,total_ms" > "$csv"
for d in "${drivers[@]}"; do
  for map in "${maps[@]}"; do
    for tol in "${tolerances[@]}"; do
      set +e
      "$cmf" apply --moments "$work/$d-moments.exr" --table "$work/$map-table.exr" --histograms "$work/$d-histograms.exr" \
        --lod 1 --tolerance "$tol" --threads 1 -o "$work/out.exr" --json > "$work/apply.json" 2> "$work/apply.err"
      code=$?
      set -e
      if [ "$code" != 0 ]; then
        echo "$d,$map,$tol,none,,,,,,,,,,,," >> "$csv"
        echo "method_tolerance: $d $map $tol: $(cat "$work/apply.err")" >&2
        continue
      fi
      /usr/bin/python3 - "$work/apply.json" "$d" "$map" "$tol" >> "$csv" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
c = j["choice"]
t = {x["method"]: x for x in c["trials"]}
chosen = t[c["method"]]
row = [sys.argv[2], sys.argv[3], sys.argv[4], c["method"], "%.4g" % c["error"], str(chosen["bytes_per_texel"])]
row += ["%.4g" % t[m]["worst"] for m in ("naive", "gaussian", "mixture", "exact")]
row += ["%.4g" % t[m]["time_ms"] for m in ("naive", "gaussian", "mixture", "exact")]
row += ["%.4g" % c["reference_ms"], "%.4g" % j["time_ms"]]
print(",".join(row))
PY
      echo "method_tolerance: $d $map $tol: $(tail -n 1 "$csv" | cut -d, -f4,5)" >&2
    done
  done
done
rm -f "$work/out.exr" "$work/apply.json" "$work/apply.err"
