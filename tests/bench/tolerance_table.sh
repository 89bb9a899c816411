#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The smallest table for a tolerance (`bake-colormap --tolerance`), per bundled
# colour map, laid over the example scenes' domain [-0.68, 0.68] (clamp, as in
# examples/scenes/*.json), at each tolerance, with
#   default  sigma_max = (vmax - vmin) / 4 = 0.34
#   --for    the bundled noise sigma table examples/scenes/fbm-gradient-6.exr
#   scene    the example scene that uses the map (examples/scenes/plane-fbm-MAP.json)
# Prints a Markdown table (docs/bake-colormap.md, "Smallest table for a
# tolerance"): the size chosen, its bytes against the 256 x 256 default
# (786432 bytes), the error statistic it reaches at the verification points,
# the max of the usual 20000-point measurement, the candidates measured and the
# wall time of search + bake.
#
#   [PERCENTILE=P] bash tests/bench/tolerance_table.sh BUILD_DIR [THREADS] [TOLERANCES...]
# PERCENTILE is --tolerance-percentile (default 99.9; 100: the maximum).
# (docs/bake-colormap.md shows `... build 2 1.0 0.5`, and
# `PERCENTILE=100 ... build 2 1.0`).
set -euo pipefail
build=$(cd "$1" && pwd)
threads=${2:-0}
shift $(( $# >= 2 ? 2 : $# ))
tolerances=("$@")
[ ${#tolerances[@]} -gt 0 ] || tolerances=(1.0 0.5)
percentile=${PERCENTILE:-99.9}
root=$(cd "$(dirname "$0")/../.." && pwd)
cmf="$build/tools/cmfilter"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export OCIO=

echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), --threads $threads"
echo
echo "| map | DE | sigma_max from | sigma_max | chosen | bytes | of 256 x 256 | $([ "$percentile" = 100 ] && echo max || echo "p$percentile") reached | max (20000) | candidates | time s |"
echo "|---|---:|---|---:|---|---:|---:|---:|---:|---:|---:|"
for map in terrain stripes step narrow-band hue-ramp; do
  for de in "${tolerances[@]}"; do
    for source in default for scene; do
      args=()
      case $source in
        for) args=(--for "$root/examples/scenes/fbm-gradient-6.exr") ;;
        scene) args=(--for "$root/examples/scenes/plane-fbm-$map.json") ;;
      esac
      if "$cmf" bake-colormap "$root/luts/$map.png" -o "$tmp/t.exr" --domain=-0.68:0.68 --tolerance "$de" \
           --tolerance-percentile "$percentile" --threads "$threads" --json "${args[@]+"${args[@]}"}" > "$tmp/out.json" 2> "$tmp/err.txt"; then
        python3 - "$tmp/out.json" "$map" "$de" "$source" <<'EOF'
import json, sys
j = json.load(open(sys.argv[1]))
t = j["tolerance"]
print(f"| {sys.argv[2]} | {sys.argv[3]} | {sys.argv[4]} | {j['sigma_max']:.4g} "
      f"| {j['values']} x {j['sigmas']} {j['sigma_spacing']} | {j['bytes']} "
      f"| {100 * j['bytes'] / t['default_bytes']:.2f}% | {t['error']:.3f} | {j['lookup_error']['max']:.3g} "
      f"| {len(t['candidates'])} | {j['bake_ms'] / 1000:.2f} |")
EOF
      else
        echo "| $map | $de | $source | | none: $(sed 's/^cmfilter bake-colormap: error: //' "$tmp/err.txt") | | | | | | |"
      fi
    done
  done
done
