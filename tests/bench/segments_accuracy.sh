#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The segment pyramid (`bake-moments --segments`) against the box-filtered
# ground truth (`apply --method reference`), LOD 1..8, with gaussian beside
# it and each apply timed (one thread, the same script) for the cost against
# gaussian, on the drivers of color_pyramid_accuracy.sh (the 96 photograph
# cases, camera through every map in luts/, the two-valued, offset and HDR
# drivers through stripes). Per case:
#   segments-exact  every exact breakpoint of the map (the channels it needs)
#   segments-TOL    the fewest breakpoints within a mean CIEDE2000 of TOL
#                   over the driver (default 0.5)
#   recoloured      the map with its channels permuted (B, R, G: other
#                   colours, the same breakpoints) through segments-exact,
#                   against the reference of that map: what recolouring
#                   after the bake gives
#   recoloured-TOL  the permuted map through segments-TOL (on its own
#                   least-squares colours), where apply accepts it (a map
#                   that fits the kept breakpoints worse than the baked map
#                   is refused: counted, no row)
# Writes WORK/segments-accuracy.csv (set,driver,map,lod,method,channels,mean,max,ms)
# and prints per set and method the worst mean, the channels and the time ratio.
#
#   bash tests/bench/segments_accuracy.sh BUILD_DIR WORK_DIR [TOL] [SETS]
# (SETS: any of "photographs every-map drivers", default all three; copy the
# cmfilter binary aside first if the build may change while it runs).
set -euo pipefail
build=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
tol=${3:-0.5}
root=$(cd "$(dirname "$0")/../.." && pwd)
cmf=${CMFILTER:-$build/tools/cmfilter}
oiiotool=${OIIOTOOL:-oiiotool}
sets=" ${4:-photographs every-map drivers} "

csv="$work/segments-accuracy.csv"
echo "set,driver,map,lod,method,channels,mean,max,ms" > "$csv"
: > "$work/refused.txt"
stat() { awk -v k="$2" '$1 == "dE2000" && $2 == k { print $3 }' "$1"; }
channels() { /usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['channels'])" "$1"; }

run_case() {  # set driver-name driver-file map domain
  local set=$1 d=$2 file=$3 map=$4 domain=$5
  local table="$work/$map-$domain-table.exr" permuted="$work/$map-$domain-permuted.exr"
  if [ ! -f "$table" ]; then
    "$cmf" bake-colormap "$root/luts/$map.png" -o "$table" --domain="$domain" -q
    "$oiiotool" "$root/luts/$map.png" --ch B,R,G -o "$work/$map-permuted.png"
    "$cmf" bake-colormap "$work/$map-permuted.png" -o "$permuted" --domain="$domain" -q
  fi
  "$cmf" bake-moments "$file" -o "$work/$d-moments.exr" -q
  "$cmf" bake-moments "$file" --segments "$table" -o "$work/$d-$map-exact.exr" --json > "$work/exact.json"
  "$cmf" bake-moments "$file" --segments "$table" --tolerance "$tol" -o "$work/$d-$map-tol.exr" --json > "$work/tol.json"
  local ce ct
  ce=$(channels "$work/exact.json")
  ct=$(channels "$work/tol.json")
  for lod in 1 2 3 4 5 6 7 8; do
    "$cmf" apply --moments "$work/$d-moments.exr" --table "$table" --lod "$lod" --threads 1 --method reference \
      -o "$work/ref.exr" -q
    "$cmf" apply --moments "$work/$d-moments.exr" --table "$permuted" --lod "$lod" --threads 1 --method reference \
      -o "$work/ref-permuted.exr" -q
    for m in gaussian segments-exact "segments-$tol" recoloured "recoloured-$tol"; do
      local ref="$work/ref.exr" t="$table" n=2
      case $m in
        gaussian) args=(--moments "$work/$d-moments.exr" --method gaussian) ;;
        segments-exact) args=(--moments "$work/$d-$map-exact.exr" --method segments); n=$ce ;;
        segments-*) args=(--moments "$work/$d-$map-tol.exr" --method segments); n=$ct ;;
        recoloured) args=(--moments "$work/$d-$map-exact.exr" --method segments); n=$ce; t=$permuted
                    ref="$work/ref-permuted.exr" ;;
        recoloured-*) args=(--moments "$work/$d-$map-tol.exr" --method segments); n=$ct; t=$permuted
                      ref="$work/ref-permuted.exr" ;;
      esac
      if ! "$cmf" apply "${args[@]}" --table "$t" --lod "$lod" --threads 1 -o "$work/out.exr" > "$work/apply.txt" \
           2> "$work/apply.err"; then
        [ "$m" = "recoloured-$tol" ] || { cat "$work/apply.err" >&2; exit 1; }
        echo "$set,$d,$map,$lod: the permuted map refused by the tolerance pyramid" >> "$work/refused.txt"
        continue
      fi
      ms=$(awk '$1 == "time" { print $2 }' "$work/apply.txt")
      "$cmf" compare "$ref" "$work/out.exr" > "$work/compare.txt"
      echo "$set,$d,$map,$lod,$m,$n,$(stat "$work/compare.txt" mean),$(stat "$work/compare.txt" max),$ms" >> "$csv"
    done
  done
  echo "segments_accuracy: $set $d $map: exact $ce channels, tolerance $tol $ct" >&2
}

photo() {
  /usr/bin/python3 -c "import sys, skimage.io, skimage.data as d; skimage.io.imsave(sys.argv[2], getattr(d, sys.argv[1])(), check_contrast=False)" \
    "$1" "$work/$1.png"
}
photo camera
if [[ $sets == *" every-map "* ]]; then
  for lut in "$root"/luts/*.png; do
    map=$(basename "$lut" .png)
    [ "$map" = slope-wheel ] && continue
    run_case every-map camera "$work/camera.png" "$map" 0:1
  done
fi
if [[ $sets == *" drivers "* ]]; then
  "$oiiotool" "$work/camera.png" -d float --chnames Y --subc 0.5 --mulc 1e6 --clamp:min=0:max=1 \
    -o "$work/two-valued.exr"
  run_case drivers two-valued "$work/two-valued.exr" stripes 0:1
  "$oiiotool" "$work/camera.png" -d float --chnames Y --addc 1000 -o "$work/offset.exr"
  run_case drivers offset "$work/offset.exr" stripes 1000:1001
  "$oiiotool" "$work/camera.png" -d float --chnames Y --powc 4 --mulc 1000 -o "$work/hdr.exr"
  run_case drivers hdr "$work/hdr.exr" stripes 0:1000
fi
if [[ $sets == *" photographs "* ]]; then
  for d in camera moon coins gravel; do
    [ "$d" = camera ] || photo "$d"
    for map in stripes step narrow-band; do run_case photographs "$d" "$work/$d.png" "$map" 0:1; done
  done
fi
rm -f "$work/ref.exr" "$work/ref-permuted.exr" "$work/out.exr" "$work/compare.txt" "$work/apply.txt" "$work/apply.err"
echo "recoloured-$tol refused (set, driver, map, LOD): $(wc -l < "$work/refused.txt")"
sort -u "$work/refused.txt" | cut -d, -f1-3 | sort -u | sed 's/^/  /'

/usr/bin/python3 - "$csv" <<'PY'
import csv, sys, collections
rows = list(csv.DictReader(open(sys.argv[1])))
worst = collections.defaultdict(float); ms = collections.defaultdict(float)
chan = collections.defaultdict(list); cases = collections.defaultdict(set)
for r in rows:
    k = (r["set"], r["method"])
    worst[k] = max(worst[k], float(r["mean"])); ms[k] += float(r["ms"])
    chan[k].append(int(r["channels"])); cases[k].add((r["driver"], r["map"]))
for s in ("photographs", "every-map", "drivers"):
    g = ms[(s, "gaussian")]
    if not g: continue
    for (ss, m) in sorted(k for k in worst if k[0] == s):
        k = (s, m)
        print(f"{s:12s} {m:16s} cases {len(cases[k]):3d}  channels {min(chan[k])}-{max(chan[k])}  "
              f"worst mean dE2000 {worst[k]:.4g}  apply time / gaussian's {ms[k] / g:.3f}")
print("per map (every-map): channels exact / tolerance, worst mean of the tolerance pyramid")
per = collections.defaultdict(dict)
for r in rows:
    if r["set"] != "every-map": continue
    p = per[r["map"]]
    if r["method"] == "segments-exact": p["exact"] = r["channels"]
    elif r["method"].startswith("segments-"):
        p["tol"] = r["channels"]; p["worst"] = max(p.get("worst", 0.0), float(r["mean"]))
for m, p in sorted(per.items()):
    print(f"  {m:12s} exact {p.get('exact')}  tolerance {p.get('tol')}  worst mean {p.get('worst', 0):.4g}")
PY
