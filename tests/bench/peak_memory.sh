#!/usr/bin/env bash
# Peak resident memory of every cmfilter command at several input sizes, and a
# least-squares fit peak = a + b * (size measure) per series.
#   tests/bench/peak_memory.sh CMFILTER OUTDIR [SOURCE_TREE]
# CMFILTER: the cmfilter binary; OUTDIR: scratch and results (peaks.csv, fits.md);
# SOURCE_TREE: a cmfilter checkout for its luts/ and examples/ (default: this one).
# Needs GNU time (/usr/bin/time), oiiotool, python3 (standard library only).
# Runs one measurement at a time: about 15 minutes on 2 busy cores, 2.5 GB of disk in OUTDIR,
# 1.4 GB of memory at most (compare at 4096 x 4096).
# With ONLY set (space-separated groups: baseline bake-colormap bake-moments
# bake-moments-histograms bake-noise noise-image apply apply-png apply-beyond-cache render make-stack
# fit relight normals compare synth-analyse synth synth-apply info; "none" only refits),
# only those groups run and their rows are appended to OUTDIR/peaks.csv. fit needs
# make-stack's stacks, relight and normals fit's fits, synth-apply synth's maps.
set -euo pipefail
B=$(realpath "$1")
O=$(mkdir -p "$2" && realpath "$2")
SRC=$(realpath "${3:-$(dirname "$0")/../..}")
S=$SRC/examples/scenes
L=$SRC/luts
cd "$O"
CSV=$O/peaks.csv
if [ -z "${ONLY:-}" ] || [ ! -f "$CSV" ]; then echo "series,measure,units,label,threads,maxrss_kb,wall_s" > "$CSV"; fi

want() { [ -z "${ONLY:-}" ] || [[ " $ONLY " == *" $1 "* ]]; }

# m SERIES MEASURE UNITS LABEL THREADS CMD...: run CMD once under GNU time, append a row
# (UNITS: the size in MEASURE's unit; LABEL: the input in words, e.g. 512x512).
m() {
  local series=$1 measure=$2 units=$3 label=$4 threads=$5
  shift 5
  if ! /usr/bin/time -f "%M %e" -o "$O/.time" "$@" > "$O/.log" 2>&1; then
    echo "FAILED: $*" >&2
    cat "$O/.log" >&2
    exit 1
  fi
  read -r kb secs < <(tail -1 "$O/.time")
  echo "$series,$measure,$units,$label,$threads,$kb,$secs" >> "$CSV"
  printf '%-30s %-16s %12s %-10s t%s %8s KB %6s s\n' "$series" "$measure" "$units" "$label" "$threads" "$kb" "$secs"
}

# scene SRC W H OUT: a copy of a scene at another resolution, its paths made absolute.
scene() {
  python3 - "$@" <<'EOF'
import json, os, sys
src, w, h, out = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
d = os.path.dirname(os.path.abspath(src))
s = json.load(open(src))
s["camera"]["resolution"] = [w, h]
def fix(o):
    if isinstance(o, dict):
        for k, v in o.items():
            if k in ("image", "sigma_table") and isinstance(v, str):
                o[k] = os.path.normpath(os.path.join(d, v))
            else:
                fix(v)
    elif isinstance(o, list):
        for x in o:
            fix(x)
fix(s)
json.dump(s, open(out, "w"))
EOF
}

# quantized N BINS OUT: an N x N 8-bit driver with exactly BINS distinct values (uniform random).
quantized() {
  python3 - "$1" "$2" "$O/q.pgm" <<'EOF'
import random, sys
n, bins, out = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
rng = random.Random(1)
step = 255 // (bins - 1) if bins > 1 else 0
px = bytes(rng.randrange(bins) * step for _ in range(n * n))
open(out, "wb").write(b"P5 %d %d 255\n" % (n, n) + px)
EOF
  oiiotool "$O/q.pgm" -o "$3"
}

# Process start alone: the floor under every command.
if want baseline; then
  m baseline none 0 --version - "$B" --version
  m baseline none 0 info-sigma-table - "$B" info "$S/fbm-gradient-6.exr"
fi

# Inputs shared by several series.
for n in 512 1024 2048 4096; do
  [ -f drv$n.exr ] || oiiotool --pattern noise ${n}x${n} 1 -d float -o drv$n.exr
  [ -f img$n.exr ] || oiiotool --pattern noise:seed=1 ${n}x${n} 3 -d float -o img$n.exr
  [ -f imgb$n.exr ] || oiiotool --pattern noise:seed=2 ${n}x${n} 3 -d float -o imgb$n.exr
done
[ -f table.exr ] || "$B" bake-colormap "$L/terrain.png" -o table.exr -q
[ -f smp64.png ] || oiiotool --pattern noise:type=uniform:min=0.1:max=0.9:seed=3 64x64 3 -d uint8 -o smp64.png

if want bake-colormap; then
  for v in 256 512 1024 2048; do
    m bake-colormap table_texels $((v * v)) ${v}x$v 2 "$B" bake-colormap "$L/terrain.png" -o bc.exr --values $v --sigmas $v --threads 2
  done
  m bake-colormap table_texels $((2048 * 2048)) 2048x2048 1 "$B" bake-colormap "$L/terrain.png" -o bc.exr --values 2048 --sigmas 2048 --threads 1
fi

if want bake-moments; then
  [ -f drv8192.exr ] || oiiotool --pattern noise 8192x8192 1 -d float -o drv8192.exr
  for n in 512 1024 2048 4096 8192; do
    m bake-moments driver_texels $((n * n)) ${n}x$n 2 "$B" bake-moments drv$n.exr -o mom$n.exr --threads 2
  done
  m bake-moments driver_texels $((4096 * 4096)) 4096x4096 1 "$B" bake-moments drv4096.exr -o mom4096.exr --threads 1
fi

if want bake-moments-histograms; then
  # 64 distinct values, the driver growing; then 512 x 512, the values growing.
  for n in 256 512 1024 2048; do
    quantized $n 64 q$n-64.png
    m bake-moments-histograms-64values texels_x_values $((n * n * 64)) ${n}x$n/64v 2 \
      "$B" bake-moments q$n-64.png -o qm.exr --histograms qh.exr --threads 2
  done
  m bake-moments-histograms-64values texels_x_values $((2048 * 2048 * 64)) 2048x2048/64v 1 \
    "$B" bake-moments q2048-64.png -o qm.exr --histograms qh.exr --threads 1
  for v in 16 64 128 256; do
    [ -f q512-$v.png ] || quantized 512 $v q512-$v.png
    m bake-moments-histograms-512x512 texels_x_values $((512 * 512 * v)) 512x512/${v}v 2 \
      "$B" bake-moments q512-$v.png -o qm.exr --histograms qh.exr --threads 2
  done
fi

if want bake-noise; then
  for f in 1024 4096 16384; do
    m bake-noise max_footprints $f $f 2 "$B" bake-noise --noise fbm:base=gradient,octaves=6 -o bn.exr --max-footprints $f --threads 2
  done
  m bake-noise max_footprints 16384 16384 1 "$B" bake-noise --noise fbm:base=gradient,octaves=6 -o bn.exr --max-footprints 16384 --threads 1
fi

if want noise-image; then
  for n in 512 1024 2048 4096; do
    m noise-image output_pixels $((n * n)) ${n}x$n 2 "$B" noise-image --noise fbm:base=gradient,octaves=6 --size ${n}x${n} -o ni.exr --threads 2
  done
  m noise-image output_pixels $((4096 * 4096)) 4096x4096 1 "$B" noise-image --noise fbm:base=gradient,octaves=6 --size 4096x4096 -o ni.exr --threads 1
fi

if want apply; then
  for n in 512 1024 2048 4096; do
    [ -f mom$n.exr ] || "$B" bake-moments drv$n.exr -o mom$n.exr -q
    m apply-gaussian output_pixels $((n * n)) ${n}x$n 2 "$B" apply --moments mom$n.exr --table table.exr --lod 0 -o ap.exr --threads 2
  done
  m apply-gaussian output_pixels $((4096 * 4096)) 4096x4096 1 "$B" apply --moments mom4096.exr --table table.exr --lod 0 -o ap.exr --threads 1
  # The output fixed at 512 x 512, the pyramid growing.
  for n in 512 1024 2048 4096; do
    m apply-gaussian-512x512-out pyramid_level0_texels $((n * n)) ${n}x$n 2 \
      "$B" apply --moments mom$n.exr --table table.exr --lod 0 --size 512x512 -o ap.exr --threads 2
  done
  for n in 512 1024 2048 4096; do
    m apply-reference output_pixels $((n * n)) ${n}x$n 2 "$B" apply --moments mom$n.exr --table table.exr --lod 0 --method reference \
      --driver drv$n.exr --map "$L/terrain.png" -o ap.exr --threads 2
  done
fi

# The same as an 8-bit sRGB .png: the output converted from scene-linear.
if want apply-png; then
  for n in 512 1024 2048 4096; do
    [ -f mom$n.exr ] || "$B" bake-moments drv$n.exr -o mom$n.exr -q
    m apply-gaussian-png output_pixels $((n * n)) ${n}x$n 2 "$B" apply --moments mom$n.exr --table table.exr --lod 0 -o ap.png --threads 2
  done
fi

# The output fixed at 512 x 512, the pyramid's level 0 (8192 x 8192 x 2 float32, 537 MB)
# larger than OpenImageIO's tile cache (256 MB by default).
if want apply-beyond-cache; then
  [ -f drv8192.exr ] || oiiotool --pattern noise 8192x8192 1 -d float -o drv8192.exr
  [ -f mom8192.exr ] || "$B" bake-moments drv8192.exr -o mom8192.exr -q
  m apply-gaussian-512x512-out-8192 pyramid_level0_texels $((8192 * 8192)) 8192x8192 2 \
    "$B" apply --moments mom8192.exr --table table.exr --lod 0 --size 512x512 -o ap.exr --threads 2
fi

if want render; then
  for w in 256 512 1024 2048; do
    h=$((w * 9 / 16))
    scene "$S/plane-fbm-terrain.json" $w $h terrain-$w.json
    m render-gaussian output_pixels $((w * h)) ${w}x$h 2 "$B" render terrain-$w.json -o rn.exr --threads 2
    m render-supersample output_pixels $((w * h)) ${w}x$h 2 "$B" render terrain-$w.json -o rn.exr --method supersample --threads 2
  done
  m render-gaussian output_pixels $((2048 * 1152)) 2048x1152 1 "$B" render terrain-2048.json -o rn.exr --threads 1
  m render-supersample output_pixels $((2048 * 1152)) 2048x1152 1 "$B" render terrain-2048.json -o rn.exr --method supersample --threads 1
  for w in 64 128 256 512; do
    h=$((w * 9 / 16))
    scene "$S/plane-fbm-terrain.json" $w $h terrain-$w.json
    m render-reference output_pixels $((w * h)) ${w}x$h 2 "$B" render terrain-$w.json -o rn.exr --method reference --spp 1024 --threads 2
  done
  m render-reference output_pixels $((256 * 144)) 256x144 1 "$B" render terrain-256.json -o rn.exr --method reference --spp 1024 --threads 1
  # A microsurface coloured by slope.
  for w in 64 128 256; do
    scene "$S/plane-microsurface-grass-rock.json" $w $w grass-$w.json
    m render-gaussian-microsurface output_pixels $((w * w)) ${w}x$w 2 "$B" render grass-$w.json -o rn.exr --threads 2
  done
fi

# Stacks: 16 lights at 64..512 pixels a side; 12, 32, 64 and 128 lights at 256 x 256
# (hsh3 needs 9 lights or more).
stack() { # SIZE LIGHTS THREADS
  mkdir -p st$1-$2
  m make-stack lights_x_pixels $(($2 * $1 * $1)) $1x$1/$2L $3 "$B" make-stack "$S/stack-near-diffuse.json" -o st$1-$2/s.lp \
    --size $1 --spp 1 --dome fibonacci:$2 --threads $3
}
if want make-stack; then
  for n in 64 128 256 512; do stack $n 16 2; done
  for l in 12 32 64 128; do stack 256 $l 2; done
  stack 512 16 1
fi

if want fit; then
  for model in ptm-rgb hsh3 lafortune; do
    for n in 64 128 256 512; do
      m fit-$model texels $((n * n)) ${n}x$n/16L 2 "$B" fit st$n-16/s.lp --model $model -o fit-$model-$n-16.exr --threads 2
    done
    m fit-$model texels $((512 * 512)) 512x512/16L 1 "$B" fit st512-16/s.lp --model $model -o fit.exr --threads 1
    for l in 12 16 32 64 128; do
      m fit-$model-lights images_x_texels $((l * 256 * 256)) 256x256/${l}L 2 "$B" fit st256-$l/s.lp --model $model -o fit-$model-256-$l.exr --threads 2
    done
  done
  for n in 64 128 256 512; do
    m fit-ptm-rgb-no-error texels $((n * n)) ${n}x$n/16L 2 "$B" fit st$n-16/s.lp --model ptm-rgb --no-error -o fit.exr --threads 2
  done
  for l in 12 32 64 128; do
    m fit-ptm-rgb-no-error-lights images_x_texels $((l * 256 * 256)) 256x256/${l}L 2 "$B" fit st256-$l/s.lp --model ptm-rgb --no-error -o fit.exr --threads 2
  done
fi

if want relight; then
  for n in 64 128 256 512; do
    m relight fit_texels $((n * n)) ${n}x$n 2 "$B" relight fit-ptm-rgb-$n-16.exr --light 0.3,0.2,0.9 -o rl.exr --threads 2
  done
  m relight fit_texels $((512 * 512)) 512x512 1 "$B" relight fit-ptm-rgb-512-16.exr --light 0.3,0.2,0.9 -o rl.exr --threads 1
  for n in 64 128 256 512; do
    m relight-reference texels $((n * n)) ${n}x$n/16L 2 "$B" relight fit-ptm-rgb-$n-16.exr --reference st$n-16/s.lp --threads 2
  done
  for l in 12 16 32 64 128; do
    m relight-reference-lights images_x_texels $((l * 256 * 256)) 256x256/${l}L 2 "$B" relight fit-ptm-rgb-256-$l.exr --reference st256-$l/s.lp --threads 2
  done
fi

if want normals; then
  for n in 64 128 256 512; do
    m normals fit_texels $((n * n)) ${n}x$n 2 "$B" normals fit-ptm-rgb-$n-16.exr -o nr.exr --threads 2
  done
  m normals fit_texels $((512 * 512)) 512x512 1 "$B" normals fit-ptm-rgb-512-16.exr -o nr.exr --threads 1
fi

if want compare; then
  for n in 512 1024 2048 4096; do
    m compare-heatmap pixels $((n * n)) ${n}x$n 2 "$B" compare img$n.exr imgb$n.exr --heatmap hm.png --threads 2
  done
  m compare-heatmap pixels $((4096 * 4096)) 4096x4096 1 "$B" compare img4096.exr imgb4096.exr --heatmap hm.png --threads 1
fi

if want synth-analyse; then
  # Default textons, min(2000, texels / 4): the sample growing.
  for n in 32 48 64 96 128; do
    [ -f smp$n.png ] || oiiotool --pattern noise:type=uniform:min=0.1:max=0.9:seed=3 ${n}x${n} 3 -d uint8 -o smp$n.png
    k=$((n * n / 4)); [ $k -le 2000 ] || k=2000
    m synth-analyse textons_squared $((k * k)) ${n}x$n/${k}t 2 "$B" synth-analyse smp$n.png -o an$n.exr --threads 2
  done
  m synth-analyse textons_squared $((2000 * 2000)) 128x128/2000t 1 "$B" synth-analyse smp128.png -o an.exr --threads 1
  # 64 x 64, the textons given.
  for k in 250 500 1000 2000; do
    m synth-analyse-64x64 textons_squared $((k * k)) 64x64/${k}t 2 "$B" synth-analyse smp64.png --textons $k -o an.exr --threads 2
  done
  # 200 textons, the sample growing.
  for n in 32 64 128; do
    m synth-analyse-200-textons sample_texels $((n * n)) ${n}x$n/200t 2 "$B" synth-analyse smp$n.png --textons 200 -o an.exr --threads 2
  done
fi

if want synth; then
  [ -f an64.exr ] || "$B" synth-analyse smp64.png -o an64.exr -q
  for n in 256 512 1024 2048; do
    m synth output_pixels $((n * n)) ${n}x$n 2 "$B" synth smp64.png --analysis an64.exr --size ${n}x${n} -o map$n.exr --threads 2
  done
  m synth output_pixels $((2048 * 2048)) 2048x2048 1 "$B" synth smp64.png --analysis an64.exr --size 2048x2048 -o map.exr --threads 1
fi

if want synth-apply; then
  for lod in 0 2; do
    for n in 256 512 1024 2048; do
      m synth-apply-lod$lod map_pixels $((n * n)) ${n}x$n 2 "$B" synth-apply map$n.exr --source smp64.png --lod $lod -o sy.exr --threads 2
    done
    m synth-apply-lod$lod map_pixels $((2048 * 2048)) 2048x2048 1 "$B" synth-apply map2048.exr --source smp64.png --lod $lod -o sy.exr --threads 1
  done
fi

if want info; then
  for n in 512 1024 2048 4096; do
    [ -f mom$n.exr ] || "$B" bake-moments drv$n.exr -o mom$n.exr -q
    m info-moments pyramid_level0_texels $((n * n)) ${n}x$n - "$B" info mom$n.exr
  done
fi

# Fit peak = a + b * units per series over its --threads 2 rows (or '-' where
# threads do not apply); MB = 10^6 bytes; the --threads 1 run beside its
# --threads 2 twin.
python3 - "$CSV" > "$O/fits.md" <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
series = []
for r in rows:
    if r["series"] not in series:
        series.append(r["series"])
print("| command (series) | size measure | fixed part a (MB) | per unit b (bytes) "
      "| measured points: input, peak MB | largest misfit (MB) | --threads 1 vs 2 (MB) |")
print("|---|---|---:|---:|---|---:|---|")
for s in series:
    mine = [r for r in rows if r["series"] == s]
    fitted = [r for r in mine if r["threads"] in ("2", "-")]
    pts = [(float(r["units"]), float(r["maxrss_kb"]) * 1024) for r in fitted]
    n = len(pts)
    mx = sum(x for x, _ in pts) / n
    my = sum(y for _, y in pts) / n
    sxx = sum((x - mx) ** 2 for x, _ in pts)
    b = sum((x - mx) * (y - my) for x, y in pts) / sxx if sxx > 0 else 0.0
    a = my - b * mx
    misfit = max(abs(y - (a + b * x)) for x, y in pts)
    listing = ", ".join("%s %.1f" % (r["label"], float(r["maxrss_kb"]) * 1024 / 1e6) for r in fitted)
    pairs = []
    for r in mine:
        if r["threads"] != "1":
            continue
        twin = [t for t in fitted if t["label"] == r["label"]]
        pairs.append("%s: %.1f vs %.1f" % (r["label"], float(r["maxrss_kb"]) * 1024 / 1e6,
                                          float(twin[-1]["maxrss_kb"]) * 1024 / 1e6 if twin else float("nan")))
    print("| %s | %s | %.1f | %.2f | %s | %.1f | %s |" % (s, mine[0]["measure"], a / 1e6, b, listing, misfit / 1e6,
                                                        "; ".join(pairs) or "-"))
EOF
# Two-term fits where one size measure does not carry the peak:
# peak = a + p * X1 + q * X2 over the --threads 2 rows of the series named.
python3 - "$CSV" >> "$O/fits.md" <<'EOF'
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["threads"] == "2"]
def size(label):  # "WxH/N<unit>" -> (W, H, N)
    wh, _, n = label.partition("/")
    w, h = (int(v) for v in wh.split("x"))
    return w, h, int(n[:-1]) if n else 0
def solve(xs, ys):  # least squares by the normal equations
    k = len(xs[0])
    m = [[sum(x[i] * x[j] for x in xs) for j in range(k)] + [sum(x[i] * y for x, y in zip(xs, ys))] for i in range(k)]
    for i in range(k):
        piv = max(range(i, k), key=lambda r: abs(m[r][i]))
        m[i], m[piv] = m[piv], m[i]
        for r in range(k):
            if r != i:
                f = m[r][i] / m[i][i]
                m[r] = [a - f * c for a, c in zip(m[r], m[i])]
    return [m[i][k] / m[i][i] for i in range(k)]
groups = [
    ("bake-moments --histograms", ["bake-moments-histograms-64values", "bake-moments-histograms-512x512"],
     "texels x values", "width x values", lambda w, h, n: (w * h * n, w * n)),
]
for model in ("ptm-rgb", "hsh3", "lafortune"):
    groups.append(("fit --model " + model, ["fit-" + model, "fit-" + model + "-lights"],
                   "texels", "images x texels", lambda w, h, n: (w * h, n * w * h)))
groups.append(("fit --model ptm-rgb --no-error", ["fit-ptm-rgb-no-error", "fit-ptm-rgb-no-error-lights"],
               "texels", "images x texels", lambda w, h, n: (w * h, n * w * h)))
groups.append(("relight --reference", ["relight-reference", "relight-reference-lights"],
               "texels", "images x texels", lambda w, h, n: (w * h, n * w * h)))
print()
print("| command | X1 | X2 | a (MB) | p (bytes per X1) | q (bytes per X2) | points | largest misfit (MB) |")
print("|---|---|---|---:|---:|---:|---:|---:|")
for name, series, x1, x2, feat in groups:
    mine = [r for r in rows if r["series"] in series]
    if not mine:
        continue
    xs = [(1.0,) + feat(*size(r["label"])) for r in mine]
    ys = [float(r["maxrss_kb"]) * 1024 for r in mine]
    a, p, q = solve(xs, ys)
    misfit = max(abs(y - (a + p * x[1] + q * x[2])) for x, y in zip(xs, ys))
    print("| %s | %s | %s | %.1f | %.2f | %.2f | %d | %.1f |" % (name, x1, x2, a / 1e6, p, q, len(mine), misfit / 1e6))
EOF
cat "$O/fits.md"
