#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# A studio's OpenColorIO config, end to end: an ACES-style config written
# here (reference ACES2065-1, working space ACEScg as scene_linear, sRGB
# textures as "sRGB - Texture" and color_picking, Raw as data, a file rule for
# linear Rec.709 maps) given as --colorconfig (OpenImageIO's spelling):
# - bake-colormap decodes the sRGB PNG map through the config's own sRGB
#   texture space and bakes in ACEScg: the table equals the built-in config's
#   table converted to ACEScg by oiiotool under the same config;
# - the table records ACEScg where OpenImageIO and OpenEXR look for it
#   (colorInteropID lin_ap1_scene, chromaticities of AP1), and cmfilter's
#   own files read back under either config: compare of the two tables
#   (the same colours in two spaces) finds no difference under both;
# - a plain float map named *_rec709.exr takes the config's file rule;
# - apply and render under the studio config give the colours the built-in
#   config gives (compared under the studio config), and PNG outputs encode
#   with the config's sRGB texture space.
#   check_studio_config.sh CMFILTER MAP DRIVER SCENE WORKDIR
set -uo pipefail
cmf=$1 map=$2 driver=$3 scene=$4 work=$5
fail=0
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
cat > studio.ocio <<'OCIO'
ocio_profile_version: 2.1
name: studio-test
description: ACES-style studio config (reference ACES2065-1), written by cmfilter's tests
search_path: ""
strictparsing: true
luma: [0.2126, 0.7152, 0.0722]
roles:
  aces_interchange: ACES2065-1
  color_picking: sRGB - Texture
  color_timing: ACEScg
  compositing_log: ACEScg
  data: Raw
  default: ACES2065-1
  matte_paint: sRGB - Texture
  scene_linear: ACEScg
  texture_paint: sRGB - Texture
file_rules:
  - !<Rule> {name: Linear Rec.709 maps, colorspace: Linear Rec.709 (sRGB), pattern: "*_rec709", extension: "exr"}
  - !<Rule> {name: Default, colorspace: default}
displays:
  sRGB - Display:
    - !<View> {name: Raw, colorspace: Raw}
active_displays: [sRGB - Display]
active_views: [Raw]
colorspaces:
  - !<ColorSpace>
    name: ACES2065-1
    aliases: [aces2065_1, ACES - ACES2065-1, lin_ap0]
    family: ACES
    encoding: scene-linear
    isdata: false
  - !<ColorSpace>
    name: ACEScg
    aliases: [ACES - ACEScg, lin_ap1]
    family: ACES
    encoding: scene-linear
    isdata: false
    to_scene_reference: !<MatrixTransform> {matrix: [0.6954522414, 0.1406786965, 0.1638690622, 0, 0.0447945634, 0.8596711185, 0.0955343182, 0, -0.0055258826, 0.0040252103, 1.0015006723, 0, 0, 0, 0, 1]}
  - !<ColorSpace>
    name: Linear Rec.709 (sRGB)
    aliases: [lin_rec709_srgb, Utility - Linear - sRGB, lin_rec709]
    family: Utility
    encoding: scene-linear
    isdata: false
    to_scene_reference: !<MatrixTransform> {matrix: [0.4396329819, 0.3829886982, 0.1773783199, 0, 0.0897764430, 0.8134394287, 0.0967841283, 0, 0.0175411704, 0.1115465533, 0.8709122763, 0, 0, 0, 0, 1]}
  - !<ColorSpace>
    name: sRGB - Texture
    aliases: [srgb_tx, Utility - sRGB - Texture, srgb_texture, Input - Generic - sRGB - Texture]
    family: Utility
    encoding: sdr-video
    isdata: false
    to_scene_reference: !<GroupTransform>
      children:
        - !<ExponentWithLinearTransform> {gamma: 2.4, offset: 0.055}
        - !<MatrixTransform> {matrix: [0.4396329819, 0.3829886982, 0.1773783199, 0, 0.0897764430, 0.8134394287, 0.0967841283, 0, 0.0175411704, 0.1115465533, 0.8709122763, 0, 0, 0, 0, 1]}
  - !<ColorSpace>
    name: Raw
    aliases: [Utility - Raw]
    family: Utility
    encoding: data
    isdata: true
OCIO
studio=(--colorconfig "$work/studio.ocio")
check() {  # check DESCRIPTION COMMAND...: the command must succeed
  local what=$1; shift
  "$@" > "$work/last.out" 2> "$work/last.err" || { echo "FAIL: $what: $*"; cat "$work/last.err"; fail=1; return 1; }
}
# The mean and max CIEDE2000 of compare's --json on stdout, as "mean max".
de() { python3 -c "import json,sys; d=json.load(sys.stdin)['ciede2000']; print(d['mean'], d['max'])"; }
below() {  # below WHAT VALUE LIMIT
  python3 -c "import sys; sys.exit(0 if float('$2') < $3 else 1)" || { echo "FAIL: $1 is $2, expected < $3"; fail=1; }
}

# Tables: the same map baked under each config.
check "bake under the built-in config" "$cmf" bake-colormap "$map" -o rec709.exr
check "bake under the studio config" "$cmf" bake-colormap "$map" "${studio[@]}" -o acescg.exr &&
  { grep -qF "sRGB - Texture -> ACEScg (file metadata)" last.out ||
      { echo "FAIL: the studio bake did not decode sRGB - Texture into ACEScg:"; cat last.out; fail=1; }; }
# The same with the option's other spelling, and with $OCIO.
check "--ocio-config spelling" "$cmf" bake-colormap "$map" --ocio-config "$work/studio.ocio" -o acescg-2.exr
check "\$OCIO" env OCIO="$work/studio.ocio" "$cmf" bake-colormap "$map" -o acescg-3.exr
cmp -s acescg.exr acescg-2.exr && cmp -s acescg.exr acescg-3.exr ||
  { echo "FAIL: --colorconfig, --ocio-config and \$OCIO gave different tables"; fail=1; }
# Independent: oiiotool converts the built-in table to ACEScg under the
# studio config; the Gaussian convolution is linear, so it commutes with the
# matrix.
check "oiiotool conversion" oiiotool --colorconfig "$work/studio.ocio" rec709.exr \
  --colorconvert "Linear Rec.709 (sRGB)" ACEScg -o expected.exr
check "the studio table against oiiotool's conversion" idiff -fail 2e-5 -failpercent 0 -warn 2e-5 acescg.exr expected.exr ||
  cat last.out
info=$(oiiotool --info -v acescg.exr)
for want in 'colorInteropID: "lin_ap1_scene"' 'cmfilter:linear_space: "ACEScg"' 'chromaticities: 0.713, 0.293, 0.165, 0.83, 0.128, 0.044, 0.32168, 0.33767'; do
  grep -qF "$want" <<< "$info" || { echo "FAIL: acescg.exr lacks $want"; grep -iE "interop|linear_space|chromatic" <<< "$info"; fail=1; }
done
grep -qF 'colorInteropID: "lin_rec709_scene"' < <(oiiotool --info -v rec709.exr) ||
  { echo "FAIL: rec709.exr lacks colorInteropID lin_rec709_scene"; fail=1; }

# cmfilter's own files under either config: the two tables hold the same
# colours, each read in the space it records.
for config in studio builtin; do
  opts=(); [ "$config" = studio ] && opts=("${studio[@]}")
  if check "compare the two tables under the $config config" "$cmf" compare rec709.exr acescg.exr "${opts[@]}" --json; then
    read -r mean max < <(de < last.out)
    below "max CIEDE2000 between the tables under the $config config" "$max" 0.01
  fi
done

# File rules: a float map with no colour metadata named *_rec709.exr.
check "a plain float map" oiiotool --pattern fill:left=0.05,0.1,0.2:right=0.9,0.6,0.1 64x1 3 -d float -o ramp_rec709.exr
check "bake a map the file rules name" "$cmf" bake-colormap ramp_rec709.exr "${studio[@]}" -o ramp.exr &&
  { grep -qF "Linear Rec.709 (sRGB) -> ACEScg (the config's file rules)" last.out ||
      { echo "FAIL: the file rule was not applied:"; cat last.out; fail=1; }; }
cp ramp_rec709.exr ramp_plain.exr
check "bake a map no rule names" "$cmf" bake-colormap ramp_plain.exr "${studio[@]}" -o ramp-plain.exr &&
  { grep -qF "ACEScg -> ACEScg (file metadata (linear: the scene_linear role))" last.out ||
      { echo "FAIL: a plain EXR map is not read as scene_linear:"; cat last.out; fail=1; }; }

# apply and render: the same colours under both configs.
check "bake-moments" "$cmf" bake-moments "$driver" -o moments.exr -q
check "apply (built-in)" "$cmf" apply --moments moments.exr --table rec709.exr --lod 2 -o apply-rec709.exr -q
check "apply (studio)" "$cmf" apply --moments moments.exr --table acescg.exr --lod 2 "${studio[@]}" -o apply-acescg.exr -q
if check "compare the applies" "$cmf" compare apply-rec709.exr apply-acescg.exr "${studio[@]}" --json; then
  read -r mean max < <(de < last.out)
  below "max CIEDE2000 between apply under the two configs" "$max" 0.01
fi
check "apply (studio) to PNG" "$cmf" apply --moments moments.exr --table acescg.exr --lod 2 "${studio[@]}" -o apply-acescg.png -q
check "apply (built-in) to PNG" "$cmf" apply --moments moments.exr --table rec709.exr --lod 2 -o apply-rec709.png -q
check "the PNGs' codes" idiff -fail 0.004 -failpercent 0 -warn 0.004 apply-rec709.png apply-acescg.png || cat last.out
# A scene's own colours are numbers in the config's scene_linear space: a
# grey background is the same colour in both (the conversion keeps white).
# (Paths in the copy made absolute: a scene's relative paths are relative to it.)
python3 - "$scene" <<'PY'
import json, os, sys
src = sys.argv[1]
def absolute(node):
    if isinstance(node, dict):
        return {k: (os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(src)), v))
                    if k in ("image", "sigma_table", "moments", "table", "map") and isinstance(v, str) else absolute(v))
                for k, v in node.items()}
    if isinstance(node, list):
        return [absolute(v) for v in node]
    return node
scene = absolute(json.load(open(src)))
scene["background"] = [0.5, 0.5, 0.5]
json.dump(scene, open("scene.json", "w"))
PY
check "render (built-in)" "$cmf" render scene.json --method gaussian -o render-rec709.exr -q
check "render (studio)" "$cmf" render scene.json --method gaussian "${studio[@]}" -o render-acescg.exr -q
if check "compare the renders" "$cmf" compare render-rec709.exr render-acescg.exr "${studio[@]}" --json; then
  read -r mean max < <(de < last.out)
  below "max CIEDE2000 between render under the two configs" "$max" 0.05
fi
[ "$fail" = 0 ] && echo "studio config: bake, apply, render and compare agree with the built-in config; files read back under both"
exit $fail
