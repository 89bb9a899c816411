#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Checks `cmfilter apply --method reference` (the box mean of C0(f) over each
# footprint) and the baked colour pyramid (`bake-moments --method
# color-pyramid`, every MIP level of its file, and `apply --method
# color-pyramid`) and the segment pyramid (`bake-moments --segments`, `apply
# --method segments`) against OpenImageIO's own tools: `oiiotool --colormap` maps the
# driver through the same piecewise-linear map, `maketx --filter box` box-mips
# the result, and each level is compared with apply at that integer LOD; a
# fractional LOD is compared with the two levels blended (oiiotool
# --resample:interp=1 reads the coarser level bilinearly at the finer level's
# texel centres, as TextureSystem does).
#   check_apply_vs_oiiotool.sh CMFILTER OIIOTOOL MAKETX FIXTURES OUTDIR
# The driver is a 32 x 32 float image (power of two: maketx's means of means
# equal the exact box means there) and the map a float EXR of n = 8 texels,
# which cmfilter reads as linear, so no colour conversion differs; its values
# are the --colormap knots in FIXTURES/apply-map-knots.txt.
set -eu
cmf=$1; oiiotool=$2; maketx=$3; fix=$4; out=$5/apply-vs-oiiotool
rm -rf "$out"
mkdir -p "$out"
n=8
"$cmf" bake-colormap "$fix/apply-map.exr" -o "$out/table.exr" -q
"$cmf" bake-moments "$fix/apply-driver.exr" -o "$out/moments.exr" -q
# cmfilter puts texel i of n at (i + 0.5) / n over the domain [0, 1];
# oiiotool puts knot j at j / (n - 1), clamped: f' = (f n - 0.5) / (n - 1).
"$oiiotool" "$fix/apply-driver.exr" --mulc $n --subc 0.5 --divc $((n - 1)) \
    --colormap "$(cat "$fix/apply-map-knots.txt")" -d float -o "$out/mapped.exr"
"$maketx" --filter box -d float "$out/mapped.exr" -o "$out/mapped.tx" > /dev/null
# Tolerance 1e-4 absolute (values up to 2.5): both sides compute in float32
# at some step (oiiotool's remap and map, maketx's sums); the differences seen
# are about 1e-6, while a wrong knot convention or a means-of-means level
# differs by 1e-2 or more.
diff_images() {
  "$oiiotool" --warn 1e-4 --fail 1e-4 --hardfail 1e-4 "$1" "$2" --diff
}
fail=0
for k in 0 1 2 3 4 5; do
  "$oiiotool" "$out/mapped.tx" --selectmip $k -o "$out/maketx-$k.exr"
done
"$cmf" bake-moments "$fix/apply-driver.exr" --method color-pyramid --table "$out/table.exr" -o "$out/colors.exr" -q
"$cmf" bake-moments "$fix/apply-driver.exr" --segments "$out/table.exr" -o "$out/segments.exr" -q
for k in 0 1 2 3 4 5; do
  "$oiiotool" "$out/colors.exr" --selectmip $k -o "$out/colors-$k.exr"
  diff_images "$out/colors-$k.exr" "$out/maketx-$k.exr" || { echo "FAIL: colour pyramid level $k"; fail=1; }
  "$cmf" apply --moments "$out/colors.exr" --table "$out/table.exr" --lod $k \
      --method color-pyramid -o "$out/color-pyramid-$k.exr" -q 2> /dev/null
  diff_images "$out/color-pyramid-$k.exr" "$out/maketx-$k.exr" || { echo "FAIL: apply color-pyramid at lod $k"; fail=1; }
  "$cmf" apply --moments "$out/segments.exr" --table "$out/table.exr" --lod $k \
      --method segments -o "$out/segments-$k.exr" -q 2> /dev/null
  diff_images "$out/segments-$k.exr" "$out/maketx-$k.exr" || { echo "FAIL: apply segments at lod $k"; fail=1; }
done
for k in 0 1 2 3 4 5; do
  "$cmf" apply --moments "$out/moments.exr" --table "$out/table.exr" --lod $k \
      --method reference -o "$out/reference-$k.exr" -q 2> /dev/null
  diff_images "$out/reference-$k.exr" "$out/maketx-$k.exr" || { echo "FAIL at lod $k"; fail=1; }
done
"$cmf" apply --moments "$out/moments.exr" --table "$out/table.exr" --lod 1.5 \
    --method reference -o "$out/reference-1.5.exr" -q 2> /dev/null
"$oiiotool" "$out/maketx-1.exr" "$out/maketx-2.exr" --resample:interp=1 16x16 --add --mulc 0.5 \
    -o "$out/maketx-1.5.exr"
diff_images "$out/reference-1.5.exr" "$out/maketx-1.5.exr" || { echo "FAIL at lod 1.5"; fail=1; }
[ $fail = 0 ] && echo OK
exit $fail
