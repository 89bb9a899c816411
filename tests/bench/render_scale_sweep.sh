#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Where each render method breaks down (docs/render.md, "Noise scale"): the
# bundled terrain ground plane and far sphere with their fBm made finer and
# finer (the texture mapping's scale times 1, 2, 4, ... 128 for the plane,
# 1/128, 1/64, ... 1 for the sphere, whose bundled noise is already far
# below its pixels), naive, gaussian
# (256 x 256 sqrt table), mixture (noise: the same table over up to 8 x 8
# sub-footprints in the transition) and supersample 16 each against a reference grown
# until repeatable (cmfilter bench). Writes WORK_DIR/scale-sweep.csv
# (scene, scale, then bench's columns) and WORK_DIR/scale-sweep.png (mean
# CIEDE2000 against the scale, gnuplot), and prints the table of the docs.
#   bash tests/bench/render_scale_sweep.sh BUILD_DIR WORK_DIR [THREADS] [PLANE_WxH] [SPHERE_WxH]
set -euo pipefail
build=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
threads=${3:-0}
plane_size=${4:-320x180}
sphere_size=${5:-480x480}
root=$(cd "$(dirname "$0")/../.." && pwd)
scenes="$root/examples/scenes"
cmfilter="$build/tools/cmfilter"
configurations="naive,gaussian 256x256 sqrt,mixture,supersample 16"
plane_scales="1 2 4 8 16 32 64 128"
sphere_scales="0.0078125 0.015625 0.03125 0.0625 0.125 0.25 0.5 1"


out="$work/scale-sweep.csv"
runs=()
for base in plane-fbm-terrain sphere-fbm-far; do
  size=$plane_size scales=$plane_scales
  [[ $base == sphere-* ]] && size=$sphere_size scales=$sphere_scales
  for scale in $scales; do
    scene="$work/$base-x$scale.json"
    python3 "$root/tests/bench/scaled_scene.py" "$scenes/$base.json" "$scene" "$scale"
    "$cmfilter" bench "$scene" --csv "$work/$base-x$scale.csv" --only "$configurations" --resolution "$size" \
                --repeats 1 --threads "$threads" -q
    runs+=("$base" "$scale" "$work/$base-x$scale.csv")
  done
done
# One CSV: the scene and scale, then bench's columns.
python3 - "$out" "${runs[@]}" <<'EOF'
import csv, os, sys
out, runs = sys.argv[1], sys.argv[2:]
with open(out + ".tmp", "w", newline="") as f:
    w = None
    for i in range(0, len(runs), 3):
        base, scale, path = runs[i:i + 3]
        for row in csv.DictReader(open(path)):
            if w is None:
                w = csv.DictWriter(f, ["base", "scale"] + list(row))
                w.writeheader()
            w.writerow({"base": base, "scale": scale, **row})
os.replace(out + ".tmp", out)
EOF

python3 - "$out" "$work" <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
work = sys.argv[2]
print("| scene | scale | reference rays (repeat) | naive | gaussian (near / middle / horizon) | mixture (near / middle / horizon) | supersample 16 | naive / gaussian | mixture time / gaussian time |")
print("|---|---:|---|---:|---|---|---:|---:|---:|")
series = {}
for base in dict.fromkeys(r["base"] for r in rows):
    for scale in dict.fromkeys(r["scale"] for r in rows if r["base"] == base):
        by = {r["configuration"]: r for r in rows if r["base"] == base and r["scale"] == scale}
        rep, nv, ga, mx, ss = (by["reference-repeat"], by["naive"], by["gaussian 256x256 sqrt"], by["mixture"],
                               by["supersample 16"])
        f = lambda r, k="mean": float(r[k])
        bands = lambda r: f"{f(r):.2f} ({f(r,'near_mean'):.2f} / {f(r,'middle_mean'):.2f} / {f(r,'horizon_mean'):.2f})"
        print(f"| {base} | {scale} | {rep['spp']} ({f(rep):.2f}) | {f(nv):.2f} | {bands(ga)} | {bands(mx)} | {f(ss):.2f} | "
              f"{f(nv) / f(ga):.1f} | {f(mx, 'seconds') / f(ga, 'seconds'):.1f} |")
        for name, r in (("naive", nv), ("gaussian", ga), ("mixture", mx), ("supersample 16", ss)):
            series.setdefault((base, name), []).append((float(scale), f(r)))
with open(f"{work}/scale-sweep.dat", "w") as d:
    for (base, name), points in series.items():
        d.write(f'# {base} {name}\n')
        for x, y in points:
            d.write(f"{x} {y}\n")
        d.write("\n\n")
with open(f"{work}/scale-sweep.gp", "w") as g:
    # One panel per scene: its own x axis, the mapping's scale as a multiple
    # of the bundled scene's.
    g.write(f'set terminal pngcairo size 1100,500 font ",11"\nset output "{work}/scale-sweep.png"\n'
            'set multiplot layout 1,2 title "Where each method breaks down: the driver made finer (mean CIEDE2000 against the reference)"\n'
            'set logscale xy 2\nset format x "2^{%L}"\nset grid\nset key top left\nset yrange [0.25:32]\n'
            'set xlabel "mapping scale, x the bundled scene\'s (finer noise to the right)"\n'
            'set ylabel "mean CIEDE2000"\n'
            'set arrow 1 from graph 0, first 1 to graph 1, first 1 nohead dt 2 lc rgb "black"\n')
    styles = {"naive": 'pt 9 lc rgb "red"', "gaussian": 'pt 7 lc rgb "blue"', "mixture": 'pt 5 lc rgb "brown"', "supersample 16": 'pt 13 lc rgb "dark-green"'}
    names = list(dict.fromkeys(base for base, _ in series))
    for base in names:
        g.write(f'set title "{base}"\n')
        plots = [f'"{work}/scale-sweep.dat" index {i} with linespoints lw 2 ps 1.3 {styles[name]} title "{name}"'
                 for i, (b, name) in enumerate(series) if b == base]
        g.write("plot " + ", \\\n     ".join(plots) + "\n")
    g.write("unset multiplot\n")
EOF
gnuplot "$work/scale-sweep.gp"
echo "wrote $out and $work/scale-sweep.png" >&2
