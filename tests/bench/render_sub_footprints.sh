#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Speed against accuracy of mixture's sub-footprints for a noise in renders
# (docs/render.md, "Noise in the transition: sub-footprints"): the bundled
# terrain ground plane with its fBm made 1, 4, 16 and 64 times finer
# (scaled_scene.py, as render_scale_sweep.sh scales it), gaussian (256 x 256
# sqrt table) and mixture with up to 2 x 2, 4 x 4, 8 x 8 and 16 x 16 squares per footprint
# (--sub-footprints), one thread, fastest of 3 runs, against a reference
# grown until repeatable (cmfilter bench). Writes WORK_DIR/sub-footprints.csv
# (scale, sub_footprints, then bench's columns), copies it to
# docs/data/render-sub-footprints.csv, draws
# docs/images/render-sub-footprints.png (mean CIEDE2000 against seconds) and
# prints the table of the docs.
#   bash tests/bench/render_sub_footprints.sh BUILD_DIR WORK_DIR [WxH]
set -euo pipefail
build=$(cd "$1" && pwd)
mkdir -p "$2/references"
work=$(cd "$2" && pwd)
size=${3:-160x90}
root=$(cd "$(dirname "$0")/../.." && pwd)
cmfilter="$build/tools/cmfilter"
runs=()
for scale in 1 4 16 64; do
  scene="$work/plane-x$scale.json"
  python3 "$root/tests/bench/scaled_scene.py" "$root/examples/scenes/plane-fbm-terrain.json" "$scene" "$scale"
  for n in 2 4 8 16; do
    "$cmfilter" bench "$scene" --csv "$work/x$scale-n$n.csv" --only "gaussian 256x256 sqrt,mixture" \
                --resolution "$size" --repeats 3 --threads 1 --sub-footprints "$n" \
                --references "$work/references" -q
    runs+=("$scale" "$n" "$work/x$scale-n$n.csv")
  done
done
python3 - "$work/sub-footprints.csv" "$root/docs/data/render-sub-footprints.csv" "$work" "$root/docs/images/render-sub-footprints.png" "${runs[@]}" <<'PY'
import csv, os, shutil, subprocess, sys
out, docs, work, png, runs = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5:]
rows = []
for i in range(0, len(runs), 3):
    scale, n, path = runs[i:i + 3]
    for row in csv.DictReader(open(path)):
        rows.append({"scale": scale, "sub_footprints": n, **row})
with open(out + ".tmp", "w", newline="") as f:
    w = csv.DictWriter(f, list(rows[0]))
    w.writeheader()
    w.writerows(rows)
os.replace(out + ".tmp", out)
shutil.copy(out, docs)
print("| scale | reference rays (repeat) | gaussian: mean (near / middle / horizon), s | mixture 2 x 2 | mixture 4 x 4 | mixture 8 x 8 | mixture 16 x 16 |")
print("|---:|---|---|---|---|---|---|")
f = lambda r, k="mean": float(r[k])
series = {}
for scale in dict.fromkeys(r["scale"] for r in rows):
    by = {(r["sub_footprints"], r["configuration"]): r for r in rows if r["scale"] == scale}
    g = by[("2", "gaussian 256x256 sqrt")]
    rep = by[("2", "reference-repeat")]
    cell = lambda r: (f"{f(r):.2f} ({f(r,'near_mean'):.2f} / {f(r,'middle_mean'):.2f} / {f(r,'horizon_mean'):.2f}), "
                      f"{f(r,'seconds'):.3f} s")
    cells = []
    series.setdefault(("gaussian", scale), []).append((f(g, "seconds"), f(g)))
    for n in ("2", "4", "8", "16"):
        m = by[(n, "mixture")]
        cells.append(cell(m) + f" ({f(m,'seconds') / f(g,'seconds'):.0f}x)")
        series.setdefault(("mixture", scale), []).append((f(m, "seconds"), f(m)))
    print(f"| {scale} | {rep['spp']} ({f(rep):.2f}) | {cell(g)} | " + " | ".join(cells) + " |")
with open(f"{work}/sub.dat", "w") as d:
    for (name, scale), points in series.items():
        d.write(f"# {name} x{scale}\n")
        for x, y in points:
            d.write(f"{x} {y}\n")
        d.write("\n\n")
plots = []
for i, (name, scale) in enumerate(series):
    style = "pt 7 ps 1.8" if name == "gaussian" else "with linespoints lw 2 pt 5"
    plots.append(f'"{work}/sub.dat" index {i} {"with points " + style if name == "gaussian" else style} '
                 f'lc {list(dict.fromkeys(s for _, s in series)).index(scale) + 1} title "{name}, noise x{scale}"')
gp = (f'set terminal pngcairo size 900,560 font ",11"\nset output "{png}"\n'
      'set title "Terrain plane, fBm made finer: mixture (2, 4, 8, 16 squares per axis) against gaussian"\n'
      'set logscale xy\nset grid\nset key outside right\nset xlabel "seconds (one thread, fastest of 3)"\n'
      'set ylabel "mean CIEDE2000 against the reference"\n'
      'set arrow 1 from graph 0, first 1 to graph 1, first 1 nohead dt 2 lc rgb "black"\n'
      "plot " + ", \\\n     ".join(plots) + "\n")
open(f"{work}/sub.gp", "w").write(gp)
subprocess.run(["gnuplot", f"{work}/sub.gp"], check=True)
PY
echo "wrote $work/sub-footprints.csv and docs/images/render-sub-footprints.png" >&2
