#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Speed against accuracy of every render method on the bundled scenes
# (docs/render.md): runs `cmfilter bench` on examples/scenes/*.json at their
# own resolution, copies the CSV to docs/data/render-bench.csv and the charts
# to docs/images/render-bench-SCENE.png, and prints the summary table of the
# docs (python3).
#   bash tests/bench/render_bench.sh BUILD_DIR WORK_DIR [THREADS]
set -euo pipefail
build=$(cd "$1" && pwd)
mkdir -p "$2"
work=$(cd "$2" && pwd)
threads=${3:-0}
root=$(cd "$(dirname "$0")/../.." && pwd)
(cd "$root" && "$build/tools/cmfilter" bench examples/scenes/*.json --csv "$work/render-bench.csv" \
    --charts "$work" --threads "$threads")
cp "$work/render-bench.csv" "$root/docs/data/render-bench.csv"
for png in "$work"/*.png; do
  cp "$png" "$root/docs/images/render-bench-$(basename "$png")"
done
python3 "$root/tests/bench/render_bench_summary.py" "$work/render-bench.csv"
