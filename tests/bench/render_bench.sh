#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Speed against accuracy of every render method on the bundled noise and
# image scenes (docs/render.md): runs `cmfilter bench` on
# examples/scenes/{plane-fbm-*,plane-image-terrain,sphere-fbm-*}.json at their
# own resolution (the microsurface and stack scenes have benches of their
# own), copies the CSV to docs/data/render-bench.csv and the charts (error
# against time, and against bytes) to docs/images/render-bench-SCENE.png and
# render-bench-SCENE-bytes.png, and prints the summary table of the docs
# (python3).
#   bash tests/bench/render_bench.sh BUILD_DIR WORK_DIR [THREADS]
set -euo pipefail
build=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
threads=${3:-0}
root=$(cd "$(dirname "$0")/../.." && pwd)
(cd "$root" && "$build/tools/cmfilter" bench examples/scenes/plane-fbm-*.json examples/scenes/plane-image-terrain.json \
    examples/scenes/sphere-fbm-*.json --csv "$work/render-bench.csv" \
    --charts "$work" --threads "$threads")
cp "$work/render-bench.csv" "$root/docs/data/render-bench.csv"
for png in "$work"/*.png; do
  cp "$png" "$root/docs/images/render-bench-$(basename "$png")"
done
python3 "$root/tests/bench/render_bench_summary.py" "$work/render-bench.csv"
