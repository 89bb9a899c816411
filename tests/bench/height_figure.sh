#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The bundled microsurface scene by every method, side by side like the
# paper's figure 8 (docs/microsurface.md): naive, gaussian, gaussian-exact,
# exact and the ray-traced reference (its eq. 14 albedo, shaded by the
# plane's normal as the filtered methods are, and its fully shaded image),
# each titled with its time and its mean CIEDE2000 against the reference
# over the pixels a surface covers; a second reference with another seed
# gives the reference's own noise. The filtered methods take the paper's
# masking (eq. 13, --masking uncorrelated), as the docs' table does. Writes WORK_DIR/height-figure.png and
# WORK_DIR/height-figure.csv, and prints the table of the docs.
#   bash tests/bench/height_figure.sh BUILD_DIR WORK_DIR [THREADS] [SCENE]
set -euo pipefail
build=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
threads=${3:-0}
root=$(cd "$(dirname "$0")/../.." && pwd)
scene=${4:-$root/examples/scenes/plane-microsurface-sand-snow.json}
cmfilter="$build/tools/cmfilter"
methods="naive gaussian gaussian-exact exact reference"

seconds() { python3 -c 'import json, sys; print(round(json.load(sys.stdin)["seconds"], 2))'; }
mean_de() {
  "$cmfilter" compare "$1" "$2" --json | python3 -c 'import json, sys; print(round(json.load(sys.stdin)["ciede2000"]["mean"], 2))'
}

declare -A time
for m in $methods; do
  extra=(--masking uncorrelated)
  [[ $m == reference ]] && extra=(--aov "$work/reference")
  time[$m]=$("$cmfilter" render "$scene" --method "$m" --threads "$threads" --seed 1 -o "$work/$m.exr" --json -q "${extra[@]}" | seconds)
done
"$cmfilter" render "$scene" --method reference --threads "$threads" --seed 2 -o "$work/reference-b.exr" -q

{
  echo "method,seconds,mean_de00"
  for m in $methods; do
    if [[ $m == reference ]]; then
      echo "reference,${time[$m]},$(mean_de "$work/reference-b.exr" "$work/reference.exr")"
    else
      echo "$m,${time[$m]},$(mean_de "$work/$m.exr" "$work/reference.exr")"
    fi
  done
} > "$work/height-figure.csv"

# PNGs for gnuplot (sRGB).
for m in $methods reference.shaded; do
  oiiotool "$work/$m.exr" --colorconvert linear sRGB -d uint8 -o "$work/$m.png"
done

python3 - "$work" <<'EOF'
import csv, sys
work = sys.argv[1]
rows = {r["method"]: r for r in csv.DictReader(open(f"{work}/height-figure.csv"))}
print("| method | time (s) | mean CIEDE2000 against the reference |")
print("|---|---:|---:|")
for m, r in rows.items():
    label = "reference (another seed)" if m == "reference" else m
    print(f"| {label} | {r['seconds']} | {r['mean_de00']} |")
panels = [(m, f"{m}: {rows[m]['seconds']} s, mean dE00 {rows[m]['mean_de00']}") for m in
          ("naive", "gaussian", "gaussian-exact", "exact")]
panels.append(("reference", f"reference: {rows['reference']['seconds']} s (another seed: {rows['reference']['mean_de00']})"))
panels.append(("reference.shaded", "reference, fully shaded (micro-normals)"))
with open(f"{work}/height-figure.gp", "w") as g:
    g.write(f'set terminal pngcairo size 1200,900 font ",11"\nset output "{work}/height-figure.png"\n'
            'set multiplot layout 2,3 title "Height-correlated colour on a Gaussian microsurface (sand-snow map)"\n'
            'unset border\nunset tics\nunset key\nset size ratio -1\nset lmargin 1\nset rmargin 1\n')
    for name, title in panels:
        g.write(f'set title "{title}"\nplot "{work}/{name}.png" binary filetype=png with rgbimage\n')
    g.write("unset multiplot\n")
EOF
gnuplot "$work/height-figure.gp"
echo "wrote $work/height-figure.png and $work/height-figure.csv" >&2
