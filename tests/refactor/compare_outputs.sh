#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Behaviour is unchanged by a refactor when two cmfilter binaries (before and
# after) write the same outputs, bit for bit: every command of the example job
# (examples/run.sh), every bundled scene by naive, gaussian and reference at a
# small size (AOVs too), a table, a moment pyramid, a histogram-driven render,
# a noise image and a noise sigma table.
#   bash tests/refactor/compare_outputs.sh OLD_CMFILTER NEW_CMFILTER WORK_DIR
# Pixels are compared with `idiff -a -fail 0 -warn 0` (every subimage and MIP
# level, no tolerance) and by a hash of the file's pixels; metadata with
# `oiiotool --info -v -a`, and text outputs (info, compare, --json, CSV) with
# diff, after removing time stamps, the version and timings. Exits 1 and
# lists every file that differs.
set -euo pipefail
old=${1:?usage: compare_outputs.sh OLD_CMFILTER NEW_CMFILTER WORK_DIR}
new=${2:?usage: compare_outputs.sh OLD_CMFILTER NEW_CMFILTER WORK_DIR}
work=${3:?usage: compare_outputs.sh OLD_CMFILTER NEW_CMFILTER WORK_DIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
size=${CMFILTER_COMPARE_SIZE:-48x27}
threads=${CMFILTER_COMPARE_THREADS:-2}
mkdir -p "$work"
work=$(cd "$work" && pwd)

# Writes every output of one binary under $2.
run_all() {
  local cmf=$1 out=$2
  rm -rf "$out"; mkdir -p "$out/tables" "$out/filtered" "$out/render" "$out/noise" "$out/scenes"
  local map name lod method scene
  for map in "$root"/luts/*.png; do
    name=$(basename "$map" .png)
    [ "$(oiiotool "$map" --echo "{TOP.height}")" = 1 ] || continue
    "$cmf" bake-colormap "$map" -o "$out/tables/$name.exr" --threads "$threads" -q
    "$cmf" info "$out/tables/$name.exr" > "$out/tables/$name.info.txt"
    "$cmf" info "$out/tables/$name.exr" --json > "$out/tables/$name.info.json"
  done
  "$cmf" bake-colormap "$root/luts/terrain.png" -o "$out/tables/terrain-sqrt-64.exr" --sigma-spacing sqrt \
         --values 64 --sigmas 32 --threads "$threads" -q
  "$cmf" bake-colormap "$root/luts/stripes.png" -o "$out/tables/stripes-tol1.exr" --tolerance 1 \
         --threads "$threads" --json > "$out/tables/stripes-tol1.json"
  local driver="$root/examples/noise-driver.png"
  "$cmf" bake-moments "$driver" -o "$out/filtered/noise-moments.exr" --threads "$threads" -q
  "$cmf" info "$out/filtered/noise-moments.exr" > "$out/filtered/noise-moments.info.txt"
  for table in "$out"/tables/*.exr; do
    name=$(basename "$table" .exr)
    for lod in 0 3 6; do
      for method in reference naive gaussian; do
        "$cmf" apply --moments "$out/filtered/noise-moments.exr" --table "$table" --lod "$lod" \
               --method "$method" -o "$out/filtered/$name-lod$lod-$method.png" --threads "$threads" -q 2>/dev/null
      done
      "$cmf" compare "$out/filtered/$name-lod$lod-reference.png" "$out/filtered/$name-lod$lod-gaussian.png" \
             > "$out/filtered/$name-lod$lod-compare.txt"
    done
  done
  # exact (sec. 4.1) on an 8-bit copy of the driver, through its histogram pyramid.
  "$cmf" bake-moments "$work/driver8.png" -o "$out/filtered/driver8-moments.exr" \
         --histograms "$out/filtered/driver8-histograms.exr" --threads "$threads" -q
  "$cmf" apply --moments "$out/filtered/driver8-moments.exr" --histograms "$out/filtered/driver8-histograms.exr" \
         --table "$out/tables/stripes.exr" --lod 3 --method exact -o "$out/filtered/stripes-lod3-exact.png" \
         --threads "$threads" -q 2>/dev/null
  "$cmf" apply --moments "$out/filtered/noise-moments.exr" --table "$out/tables/terrain.exr" --lod 2.5 \
         -o "$out/filtered/terrain-lod2.5.exr" --threads "$threads" -q
  "$cmf" compare "$out/filtered/terrain-lod0-reference.png" "$out/filtered/terrain-lod0-naive.png" \
         --heatmap "$out/filtered/terrain-heatmap.png" --json > "$out/filtered/terrain-compare.json"

  "$cmf" noise-image --noise fbm:base=gradient,octaves=4,seed=3 --size 64x64 -o "$out/noise/fbm.exr" -q
  "$cmf" bake-noise --noise fbm:base=gradient,octaves=3,seed=1 --max-footprints 1024 --threads "$threads" \
         -o "$out/noise/fbm-sigma.exr" --csv "$out/noise/fbm-sigma.csv" -q
  "$cmf" info "$out/noise/fbm-sigma.exr" > "$out/noise/fbm-sigma.info.txt"

  local w=${size%x*} h=${size#*x}
  for scene in "$root"/examples/scenes/*.json; do
    name=$(basename "$scene" .json)
    python3 "$root/tests/cli/write_small_scene.py" "$scene" "$out/scenes/$name.json" "$w" "$h" > /dev/null
    for method in naive gaussian reference; do
      "$cmf" render "$out/scenes/$name.json" --method "$method" -o "$out/render/$name-$method.exr" \
             --aov "$out/render/$name-$method" --threads "$threads" --json > "$out/render/$name-$method.json" 2>/dev/null \
        || echo "exit $?" > "$out/render/$name-$method.failed"
    done
  done
  for name in plane-microsurface-sand-snow plane-snake; do
    "$cmf" render "$out/scenes/$name.json" --method gaussian-exact -o "$out/render/$name-gaussian-exact.exr" \
           --threads "$threads" -q
  done
  "$cmf" render "$out/scenes/plane-fbm-terrain.json" --method gaussian --tolerance 1 \
         -o "$out/render/plane-fbm-terrain-tol1.exr" --threads "$threads" -q
  # exact through the histogram pyramid of the 8-bit driver.
  python3 - "$out/scenes/plane-image-terrain.json" "$work/driver8.png" "$out/scenes/plane-image8-terrain.json" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
scene["surfaces"][0]["material"]["driver"]["image"] = sys.argv[2]
json.dump(scene, open(sys.argv[3], "w"), indent=2)
PY
  "$cmf" render "$out/scenes/plane-image8-terrain.json" --method exact \
         -o "$out/render/plane-image8-terrain-exact.exr" --threads "$threads" -q
  "$cmf" render "$out/scenes/plane-fbm-terrain.json" --method supersample --spp 4 \
         -o "$out/render/plane-fbm-terrain-ss4.png" --threads "$threads" -q
  "$cmf" bench "$out/scenes/plane-fbm-terrain.json" --repeats 1 --csv "$out/render/bench.csv" \
         --threads "$threads" -q
}

# Text with time stamps, versions and timings removed.
normalised() {
  sed -E -e '/DateTime|cmfilter:version|Software|oiio:SHA-1/d' \
         -e 's/"(seconds|time|elapsed[a-z_]*|[a-z_]*seconds[a-z_]*|[a-z_]*_ms)": *[0-9.e+-]+/"\1": T/g' \
         -e 's/[0-9]+\.[0-9]+ s\b/T s/g' "$1" | sed -E "s#$work/(old|new)#WORK#g"
}

# The 8-bit driver is made once: PNG files carry the time they were written.
oiiotool "$root/examples/noise-driver.png" -d uint8 -o "$work/driver8.png"
# A bench CSV without its timing columns, paths normalised.
csv_without_timings() {
  python3 -c '
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
keep = [i for i, n in enumerate(rows[0]) if not any(w in n for w in ("second", "time", "speed", "ratio"))]
for r in rows: print(",".join(r[i] for i in keep))' "$1" | sed -E "s#$work/(old|new)#WORK#g"
}

echo "compare_outputs: writing the old binary's outputs" >&2
run_all "$old" "$work/old"
echo "compare_outputs: writing the new binary's outputs" >&2
run_all "$new" "$work/new"

differ=0 files=0
while IFS= read -r rel; do
  files=$((files + 1))
  a="$work/old/$rel" b="$work/new/$rel"
  if [ ! -f "$b" ]; then echo "only before: $rel"; differ=1; continue; fi
  case "$rel" in
    *.exr|*.png|*.tif|*.jpg)
      if ! idiff -a -fail 0 -warn 0 "$a" "$b" > /dev/null 2>&1; then
        echo "pixels differ: $rel"; differ=1
      fi
      if ! diff <(oiiotool --info -v -a "$a" | sed 1d | normalised /dev/stdin) \
                <(oiiotool --info -v -a "$b" | sed 1d | normalised /dev/stdin) > /dev/null; then
        echo "metadata differs: $rel"; differ=1
      fi ;;
    bench.csv|*/bench.csv)
      # Columns of seconds differ run to run; the rest (methods, options, errors) must not.
      if ! diff <(csv_without_timings "$a") <(csv_without_timings "$b") > /dev/null; then
        echo "differs: $rel"; differ=1
      fi ;;
    *)
      if ! diff <(normalised "$a") <(normalised "$b") > /dev/null; then echo "differs: $rel"; differ=1; fi ;;
  esac
done < <(cd "$work/old" && find . -type f | sed 's#^\./##' | sort)
while IFS= read -r rel; do
  [ -f "$work/old/$rel" ] || { echo "only after: $rel"; differ=1; }
done < <(cd "$work/new" && find . -type f | sed 's#^\./##' | sort)
if [ "$differ" = 0 ]; then
  echo "compare_outputs: $files files, all identical (pixels bit for bit, metadata but time stamps and version)"
else
  echo "compare_outputs: outputs differ (above)"; exit 1
fi
