#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# render --method auto on every bundled microsurface scene (docs/render.md,
# "A method per material"): at each tolerance, the method chosen per
# microsurface (measured against exact on the view,
# render/microsurface_method_choice.h), its worst band against exact, the
# probes chosen then (surface_probe_choice.h), the choices' and the
# render's wall time; beside it, each fixed one-ray method's
# render time and every image's mean CIEDE2000 against a 1024-ray reference
# (over the whole frame, as docs/microsurface.md's tables; the sky's pixels
# are equal in both). Writes WORK_DIR/render-auto-microsurfaces.csv and
# prints the docs' tables.
#   bash tests/bench/render_auto_microsurfaces.sh BUILD_DIR WORK_DIR [THREADS] [TOLERANCES]
set -euo pipefail
build=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
threads=${3:-0}
tolerances=${4:-"0.5 1 2 4"}
root=$(cd "$(dirname "$0")/../.." && pwd)
cmfilter="$build/tools/cmfilter"

field() { python3 -c "import json, sys; j = json.load(sys.stdin); print($1)"; }
mean_de() {
  "$cmfilter" compare "$1" "$2" --threads "$threads" --json | field 'round(j["ciede2000"]["mean"], 2)'
}
now() { date +%s.%N; }

csv="$work/render-auto-microsurfaces.csv"
echo "scene,tolerance,method,choice_worst_vs_exact,probes,wall_seconds,render_seconds,mean_de00_vs_reference" > "$csv"
for scene in "$root"/examples/scenes/plane-microsurface-*.json; do
  name=$(basename "$scene" .json)
  name=${name#plane-microsurface-}
  "$cmfilter" render "$scene" --method reference --threads "$threads" -o "$work/$name-reference.exr" -q
  for m in naive gaussian gaussian-exact exact; do
    start=$(now)
    s=$("$cmfilter" render "$scene" --method "$m" --threads "$threads" -o "$work/$name-$m.exr" --json -q |
        field 'round(j["seconds"], 2)')
    wall=$(python3 -c "print(round($(now) - $start, 2))")
    echo "$name,,$m,,16,$wall,$s,$(mean_de "$work/$name-$m.exr" "$work/$name-reference.exr")" >> "$csv"
  done
  for t in $tolerances; do
    start=$(now)
    "$cmfilter" render "$scene" --method auto --tolerance "$t" --threads "$threads" -o "$work/$name-auto-$t.exr" \
      --json -q > "$work/$name-auto-$t.json"
    wall=$(python3 -c "print(round($(now) - $start, 2))")
    read -r chosen worst probes s < <(field '" ".join([j["microsurface_methods"][0]["choice"]["method"], str(round(next(t["worst"] for t in j["microsurface_methods"][0]["choice"]["trials"] if t["method"] == j["microsurface_methods"][0]["choice"]["method"]), 2)), str(j["surface_probes"][0]["choice"]["probes"]), str(round(j["seconds"], 2))])' < "$work/$name-auto-$t.json")
    echo "$name,$t,$chosen,$worst,$probes,$wall,$s,$(mean_de "$work/$name-auto-$t.exr" "$work/$name-reference.exr")" >> "$csv"
  done
done

python3 - "$csv" <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
print("| scene | method | render (s) | mean CIEDE2000 against the reference |")
print("|---|---|---:|---:|")
for r in rows:
    if not r["tolerance"]:
        print(f"| {r['scene']} | {r['method']} | {r['render_seconds']} | {r['mean_de00_vs_reference']} |")
print()
print("| scene | --tolerance | chosen | worst band against exact | probes | wall (s), choices and render | render (s) | mean CIEDE2000 against the reference |")
print("|---|---:|---|---:|---:|---:|---:|---:|")
for r in rows:
    if r["tolerance"]:
        print(f"| {r['scene']} | {r['tolerance']} | {r['method']} | {r['choice_worst_vs_exact']} | {r['probes']} | {r['wall_seconds']} | {r['render_seconds']} | {r['mean_de00_vs_reference']} |")
EOF
echo "wrote $csv" >&2
