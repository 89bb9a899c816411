#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Prints one command line per asset: `cmfilter bake-colormap` of every
# one-row colour map image in a folder (a 2-D slope-vector map has no table
# to bake: docs/slope.md), each writing OUTDIR/<name>.exr. As for tiles, each
# line is a whole, idempotent task with no state shared with the others:
# outputs are reproducible (no time stamp; the source recorded relative to
# the output), so a bake run again, or on another machine, gives the same
# bytes.
#   plan_bakes.sh CMFILTER ASSET_DIR OUTDIR [BAKE_OPTION...] > bakes.tasks
set -euo pipefail
[ $# -ge 3 ] || { echo "usage: plan_bakes.sh CMFILTER ASSET_DIR OUTDIR [BAKE_OPTION...]" >&2; exit 1; }
cmfilter=$1 assets=$2 outdir=$3
shift 3
. "$(dirname "$0")/task_line.sh"
found=0
for map in "$assets"/*.png; do
  [ -f "$map" ] || continue
  [ "$(oiiotool "$map" --echo "{TOP.height}" | tail -n 1)" = 1 ] || continue
  name=$(basename "$map" .png)
  task_line "$cmfilter" bake-colormap "$map" -o "$outdir/$name.exr" -q "$@"
  found=1
done
[ "$found" = 1 ] || { echo "plan_bakes.sh: no one-row colour map (*.png) in '$assets'" >&2; exit 1; }
