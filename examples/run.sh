#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The main job on the bundled example:
#  1. bake a prefiltered table (eq. 10) for every colour map in luts/, describe
#     each, and write an sRGB preview of each table (sigma grows downwards);
#  2. bake the moment pyramid of the bundled driver (examples/noise-driver.png:
#     512 x 512 blurred noise, 16-bit), and filter it with every map at LOD 0,
#     3 and 6 by each method (naive, the paper's gaussian, and the box-filtered
#     reference), writing sRGB images and how far each method is from the
#     reference (CIEDE2000) for a person to look at;
#  3. render the bundled ground-plane scene (fBm through the terrain map, to
#     the horizon) by the naive and gaussian methods, and time every method
#     against a reference of at least 1024 rays per pixel at 160 x 90
#     (cmfilter bench: CSV + chart);
#  4. render the bundled microsurface scene (colour by height: sand in the
#     hollows, snow on the crests, masked and shadowed) by naive,
#     gaussian-exact and the ray-traced reference, with each one's error;
#  5. render the slope-coloured scene (grass on the flat, rock on the steep),
#     the combined one (base + height + slope) and the snake (a textured
#     displacement) by gaussian;
#  6. make the bundled synthetic image stacks (examples/make_stacks.sh), fit
#     the near-diffuse and the shiny one with a PTM and HSH of order 3 (to
#     cmfilter's EXR and to the .ptm / .rti RTI viewers open), relight each
#     at a light none of them was made under, and measure the fits against
#     the exact images there and their normals against the true ones;
#  7. synthesise 256 x 256 surfaces from the bundled samples (a photograph of
#     gravel, the procedural terrain texture and the 7-view BTF;
#     examples/synth_samples.sh) by hierarchical k-coherence synthesis into
#     coordinate maps, render them at full size and, through the BTF's PTM,
#     at LOD 2 by the seam-aware patch lookup and the naive mip of the
#     coordinates, each against the box-filtered reference.
#   bash examples/run.sh CMFILTER_BINARY OUTPUT_DIR
set -euo pipefail
cmfilter=${1:?usage: run.sh CMFILTER_BINARY OUTPUT_DIR}
out=${2:?usage: run.sh CMFILTER_BINARY OUTPUT_DIR}
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out/tables" "$out/previews" "$out/filtered"
for map in "$root"/luts/*.png; do
  name=$(basename "$map" .png)
  # A 2-D slope-vector map (slope-wheel.png) has no table: it is filtered over
  # slopes when rendering (docs/slope.md).
  [ "$(oiiotool "$map" --echo "{TOP.height}")" = 1 ] || continue
  "$cmfilter" bake-colormap "$map" -o "$out/tables/$name.exr"
  "$cmfilter" info "$out/tables/$name.exr" > "$out/tables/$name.txt"
  oiiotool "$out/tables/$name.exr" --resize 512x256 --colorconvert linear sRGB -d uint8 \
           -o "$out/previews/$name.png"
done

driver="$root/examples/noise-driver.png"
"$cmfilter" bake-moments "$driver" -o "$out/filtered/noise-moments.exr"
summary="$out/filtered/summary.txt"
printf '%-12s %4s %14s %14s\n' map LOD "naive dE00" "gaussian dE00" > "$summary"
for table in "$out"/tables/*.exr; do
  name=$(basename "$table" .exr)
  for lod in 0 3 6; do
    for method in reference naive gaussian; do
      # Texels of the driver beyond the map's domain take its end colours in
      # every method alike; the warning that says so is not repeated here.
      "$cmfilter" apply --moments "$out/filtered/noise-moments.exr" --table "$out/tables/$name.exr" \
                  --lod "$lod" --method "$method" -o "$out/filtered/$name-lod$lod-$method.png" -q \
                  2> >(grep -v "lie outside the domain" >&2)
    done
    de() {
      "$cmfilter" compare "$out/filtered/$name-lod$lod-reference.png" "$out/filtered/$name-lod$lod-$1.png" \
        | awk '$1 == "dE2000" && $2 == "mean" { print $3 }'
    }
    printf '%-12s %4s %14.3f %14.3f\n' "$name" "$lod" "$(de naive)" "$(de gaussian)" >> "$summary"
  done
done
cat "$summary"

mkdir -p "$out/render"
scene="$root/examples/scenes/plane-fbm-terrain.json"
for method in naive gaussian; do
  "$cmfilter" render "$scene" --method "$method" -o "$out/render/plane-fbm-terrain-$method.png"
done
"$cmfilter" bench "$scene" --resolution 160x90 --repeats 1 --csv "$out/render/bench.csv" --charts "$out/render" -q
echo
echo "bench at 160 x 90 (mean CIEDE2000 against the reference, render seconds):"
awk -F, 'NR > 1 && $2 != "reference" { printf "  %-36s %8.3f dE00 %10.4f s\n", $2, $11, $10 }' "$out/render/bench.csv"

micro="$root/examples/scenes/plane-microsurface-sand-snow.json"
for method in naive gaussian-exact reference; do
  "$cmfilter" render "$micro" --method "$method" -o "$out/render/sand-snow-$method.exr" -q
  oiiotool "$out/render/sand-snow-$method.exr" --colorconvert linear sRGB -d uint8 -o "$out/render/sand-snow-$method.png"
done
echo
echo "microsurface scene (mean CIEDE2000 against the ray-traced reference):"
for method in naive gaussian-exact; do
  "$cmfilter" compare "$out/render/sand-snow-$method.exr" "$out/render/sand-snow-reference.exr" \
    | awk -v m="$method" '$1 == "dE2000" && $2 == "mean" { printf "  %-16s %8.3f dE00\n", m, $3 }'
done
for scene in plane-microsurface-grass-rock plane-microsurface-combined plane-snake; do
  "$cmfilter" render "$root/examples/scenes/$scene.json" --method gaussian -o "$out/render/$scene.exr" -q
  oiiotool "$out/render/$scene.exr" --colorconvert linear sRGB -d uint8 -o "$out/render/$scene.png"
done
echo
echo "image stacks (docs/stacks.md): error at held-out lights, normals against the true ones"
bash "$root/examples/make_stacks.sh" "$cmfilter" "$out/stacks" 2>/dev/null >/dev/null
mkdir -p "$out/stacks/near-diffuse-held"
"$cmfilter" make-stack --from "$out/stacks/near-diffuse/stack.json" --dome regular:16 --min-elevation 20 \
  -o "$out/stacks/near-diffuse-held/stack.lp" -q
for stack in near-diffuse shiny; do
  for fit in ptm-rgb.ptm hsh3.rti hsh3.exr; do
    file="$out/stacks/$stack-$fit"
    "$cmfilter" fit "$out/stacks/$stack/stack.lp" --model "${fit%.*}" -o "$file" -q
    "$cmfilter" relight "$file" --light -0.3,0.5,0.81 -o "$out/stacks/$stack-${fit/./-}-relit.png" -q
    "$cmfilter" relight "$file" --reference "$out/stacks/$stack-held/stack.lp" \
      | awk -v s="$stack" -v f="$fit" '/CIEDE2000/ { printf "  %-13s %-12s held-out dE00 mean %6.2f", s, f, $3 }'
    "$cmfilter" normals "$file" --reference "$out/stacks/$stack/stack.normals.exr" \
      | awk '/angle to/ { printf "   normals %5.1f degrees\n", $5 }'
  done
done

echo
echo "synthesis (docs/synthesis.md): 256 x 256 from small samples, quality against naive tiling"
bash "$root/examples/synth_samples.sh" "$cmfilter" "$out/synthesis" 2>/dev/null >/dev/null
syn=$out/synthesis
for sample in gravel.png terrain.png; do
  name=${sample%.png}
  # The samples were just made again: an analysis from an earlier run names
  # the earlier files' hash.
  rm -f "$syn/$name-analysis.exr"
  "$cmfilter" synth "$syn/$sample" --levels 3 -k 3 --size 256x256 --analysis "$syn/$name-analysis.exr" \
    -o "$syn/$name-coords.exr" --preview "$syn/$name-256.png" --quality \
    | awk -v s="$name" '/coherence/ { sub(/\),/, "", $4); sub(/\)/, "", $19);
        printf "  %-8s coherence %.3f (tiling %.3f), seams on %.1f%% of pairs at contrast %.2f (tiling %.1f%% at %.2f)\n",
               s, $2, $4, 100 * $10, $15, 100 * $17, $19 }'
done
"$cmfilter" synth "$out/stacks/multiview/btf.json" --levels 3 -k 3 --size 256x256 \
  -o "$syn/multiview-coords.exr" -q
"$cmfilter" fit "$out/stacks/multiview/view-00/stack.lp" --model ptm-rgb -o "$syn/multiview-view-00.exr" -q
for method in reference patches naive; do
  "$cmfilter" synth-apply "$syn/multiview-coords.exr" --source "$syn/multiview-view-00.exr" --light 0.4,0.3,0.87 \
    --lod 2 --lod-method $method -o "$syn/multiview-lod2-$method.exr" -q
done
for method in patches naive; do
  "$cmfilter" compare "$syn/multiview-lod2-reference.exr" "$syn/multiview-lod2-$method.exr" \
    | awk -v m="$method" '/dE2000 mean/ { printf "  BTF through its PTM at LOD 2, %-8s CIEDE2000 mean %.3f against the reference\n", m, $3 }'
done

echo
echo "example outputs in $out:"
echo "  tables/*.exr      prefiltered colour-map tables (open with oiiotool --info -v or cmfilter info)"
echo "  tables/*.txt      what cmfilter info says of each"
echo "  previews/*.png    each table in sRGB: value left to right, sigma 0 (top) to sigma-max (bottom)"
echo "  filtered/*.png    the bundled driver through each map at LOD 0, 3, 6 by each method (sRGB)"
echo "  filtered/summary.txt  mean CIEDE2000 of naive and gaussian against the reference"
echo "  render/*.png      the ground-plane scene by naive and gaussian; render/plane-fbm-terrain.png: error vs time"
echo "  render/bench.csv  every method's time and error against the reference (docs/render.md)"
echo "  render/sand-snow-*.png  the microsurface scene by naive, gaussian-exact and reference (docs/microsurface.md)"
echo "  render/plane-microsurface-grass-rock.png, plane-microsurface-combined.png, plane-snake.png"
echo "                    colour by slope, combined layers and the snake, by gaussian (docs/microsurface.md)"
echo "  stacks/           synthetic image stacks (docs/make-stack.md), their fits (.exr, .ptm, .rti) and relit PNGs"
echo "  synthesis/        samples, analyses, coordinate maps, 256 x 256 previews and LOD 2 renders (docs/synthesis.md)"
