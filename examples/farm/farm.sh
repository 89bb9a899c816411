#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The farm example (docs/farm.md), on Slurm or on this machine alone:
#  1. splits a frame of a scene into tiles, one `cmfilter render --region`
#     command line per tile (plan_tiles.sh), runs them as one job array
#     (submit_slurm.sh: sbatch --array, --wait) or one after another here
#     (run_local.sh), stitches the tiles with oiiotool (stitch.sh) and checks
#     the frame against the same render made on this machine in one piece
#     (same_pixels.sh: bit for bit), with every core;
#  2. bakes a folder of colour maps, one `cmfilter bake-colormap` command
#     line per map (plan_bakes.sh), as a second job array (or here), and
#     checks each table against the same bake made here, byte for byte.
# Writes under OUTDIR: tiles.tasks, tiles/, frame.exr (stitched),
# one-machine.exr, bakes.tasks, bakes/, local-bakes/, logs/ and summary.txt
# (the times). Exits 0 only when every check holds.
#   farm.sh [--slurm | --local] [--scene FILE] [--size WxH] [--tiles CxR]
#           [--method M] [--spp N] [--task-threads N] [--jobs N] [--maps DIR]
#           CMFILTER OUTDIR
# Defaults: --local, the bundled far sphere (examples/scenes/sphere-fbm-far.json)
# at its 480x480, 4x4 tiles, --method reference (--spp 1024, the least a
# reference takes), 1 thread per task, one task at a time with --local
# (--jobs N: N at a time), the bundled luts/.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
scheduler=local scene=$root/examples/scenes/sphere-fbm-far.json size=480x480 tiles=4x4
method=reference spp=1024 task_threads=1 jobs=1 maps=$root/luts
usage="usage: farm.sh [--slurm | --local] [--scene FILE] [--size WxH] [--tiles CxR] [--method M] [--spp N] [--task-threads N] [--jobs N] [--maps DIR] CMFILTER OUTDIR"
while [ $# -gt 0 ]; do
  case "$1" in
    --slurm) scheduler=slurm; shift ;;
    --local) scheduler=local; shift ;;
    --scene) scene=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --tiles) tiles=$2; shift 2 ;;
    --method) method=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    --task-threads) task_threads=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --maps) maps=$2; shift 2 ;;
    -*) echo "$usage" >&2; exit 1 ;;
    *) break ;;
  esac
done
[ $# = 2 ] || { echo "$usage" >&2; exit 1; }
cmfilter=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
out=$2
mkdir -p "$out"
out=$(cd "$out" && pwd)
scene=$(cd "$(dirname "$scene")" && pwd)/$(basename "$scene")
maps=$(cd "$maps" && pwd)
# A new run starts from empty folders: the stitch takes every tile there.
rm -rf "$out/tiles" "$out/bakes" "$out/local-bakes" "$out/logs"
mkdir -p "$out/tiles" "$out/bakes" "$out/local-bakes" "$out/logs"

now() { date +%s.%N; }
since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.2f", b - a }'; }
# run_tasks NAME: the tasks of OUTDIR/NAME.tasks on the scheduler chosen.
run_tasks() {
  if [ "$scheduler" = slurm ]; then
    bash "$here/submit_slurm.sh" "$out/$1.tasks" "$out/logs/$1" "$task_threads" > /dev/null
  else
    bash "$here/run_local.sh" "$out/$1.tasks" "$out/logs/$1" "$jobs"
  fi
}
# The sum of the tasks' own times, from their logs (run_task.sh).
task_seconds() {
  cat "$out/logs/$1"/task-*.out | awk '/^task [0-9]+: done in/ { s += $5 } END { printf "%.2f", s }'
}

render_options=(--method "$method" --spp "$spp")
bash "$here/plan_tiles.sh" "$cmfilter" "$scene" "$size" "$tiles" "$out/tiles" "${render_options[@]}" \
  --threads "$task_threads" > "$out/tiles.tasks"
echo "farm: $(wc -l < "$out/tiles.tasks") tiles of $(basename "$scene") at $size, $method, on $scheduler"
start=$(now)
run_tasks tiles
tiles_wall=$(since "$start")
tiles_sum=$(task_seconds tiles)
bash "$here/stitch.sh" "$out/frame.exr" "$out"/tiles/tile-*.exr
start=$(now)
# The same frame in one piece, with every core of this machine.
"$cmfilter" render "$scene" --size "$size" -o "$out/one-machine.exr" -q "${render_options[@]}" --threads 0
whole=$(since "$start")
bash "$here/same_pixels.sh" "$out/frame.exr" "$out/one-machine.exr"
echo "farm: the stitched frame is the one-machine render, bit for bit"

bash "$here/plan_bakes.sh" "$cmfilter" "$maps" "$out/bakes" --threads "$task_threads" > "$out/bakes.tasks"
echo "farm: $(wc -l < "$out/bakes.tasks") colour maps of $maps to bake, on $scheduler"
start=$(now)
run_tasks bakes
bakes_wall=$(since "$start")
bakes_sum=$(task_seconds bakes)
start=$(now)
for table in "$out"/bakes/*.exr; do
  name=$(basename "$table" .exr)
  "$cmfilter" bake-colormap "$maps/$name.png" -o "$out/local-bakes/$name.exr" -q --threads "$task_threads"
  cmp "$table" "$out/local-bakes/$name.exr"
done
bakes_local=$(since "$start")
[ "$(ls "$out"/bakes/*.exr | wc -l)" = "$(wc -l < "$out/bakes.tasks")" ] ||
  { echo "farm: the bakes wrote $(ls "$out"/bakes/*.exr | wc -l) tables for $(wc -l < "$out/bakes.tasks") tasks" >&2; exit 1; }
echo "farm: every table baked by the array is the local bake, byte for byte"

{
  echo "scheduler: $scheduler"
  echo "tiles: $(wc -l < "$out/tiles.tasks") of $(basename "$scene") at $size, $method, $spp rays (at least), $task_threads thread(s) each"
  echo "tiles wall time (submitted to all done): $tiles_wall s"
  echo "tiles' own times, summed: $tiles_sum s"
  echo "one-machine render, all $(nproc) cores: $whole s"
  echo "bakes: $(wc -l < "$out/bakes.tasks") maps; wall time $bakes_wall s; their own times summed $bakes_sum s; local bakes $bakes_local s"
} > "$out/summary.txt"
cat "$out/summary.txt"
