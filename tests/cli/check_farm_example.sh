#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The farm example (examples/farm/farm.sh, docs/farm.md), run on this machine
# alone (--local) or on a single-node Slurm cluster this test stands up and
# takes down (--slurm; tests/cli/slurm_single_node.sh):
#   check_farm_example.sh --local|--slurm CMFILTER DIR [FARM_OPTION...]
# The example checks its own stitched frame against its one-machine render
# and each baked table against a local bake; this test checks again from the
# outside: the stitched frame against a render it makes itself (bit for bit),
# one task log per tile and per map (on Slurm: each from an array task of a
# job), and a task run a second time rewrites the same bytes (idempotent).
# On Slurm it fails, loudly, where the cluster cannot stand up (neither
# root nor a password-free sudo, munge or Slurm missing): Debian's munge
# and slurm-wlm (bootstrap.sh).
# Whatever happens, the daemons it started are stopped and its temporary
# folder removed.
set -euo pipefail
mode=$1 cmfilter=$2 dir=$3
# slurmd runs each job as its user, which takes root: a user who may sudo
# without a password (a CI runner) runs the Slurm check as root.
if [ "$mode" = --slurm ] && [ "$(id -u)" != 0 ] && command -v sudo > /dev/null && sudo -n true 2> /dev/null; then
  exec sudo -n -E bash "$0" "$@"
fi
shift 3
root=$(cd "$(dirname "$0")/../.." && pwd)
farm=$root/examples/farm
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$dir"
mkdir -p "$dir"
work=$(mktemp -d "${TMPDIR:-/tmp}/cmfilter-farm.XXXXXX")
if [ "$mode" = --slurm ]; then
  # shellcheck source=slurm_single_node.sh
  . "$(dirname "$0")/slurm_single_node.sh"
  trap 'slurm_stop; rm -rf "$work"' EXIT
  trap 'exit 1' INT TERM
  slurm_start "$work/cluster" || fail "the single-node Slurm cluster did not start"
  sinfo
else
  trap 'rm -rf "$work"' EXIT
fi

# Two of the bundled maps make the bake array (each task the same command
# line as for nine).
mkdir -p "$dir/maps"
cp "$root/luts/stripes.png" "$root/luts/terrain.png" "$dir/maps/"
bash "$farm/farm.sh" "$mode" --maps "$dir/maps" "$@" "$cmfilter" "$dir/out" || fail "examples/farm/farm.sh $mode failed"
out=$dir/out

# The frame again, rendered here from the command line the tiles share.
line=$(head -n 1 "$out/tiles.tasks")
eval "words=($line)"
whole=()
skip=0
for word in "${words[@]}"; do
  if [ "$skip" = 1 ]; then skip=0; continue; fi
  case "$word" in --region | -o) skip=1; continue ;; esac
  whole+=("$word")
done
"${whole[@]}" -o "$dir/whole.exr"
idiff -fail 0 -failpercent 0 -warn 0 "$out/frame.exr" "$dir/whole.exr" ||
  fail "the stitched frame differs from the one-machine render"

# Every task ran and said so; on Slurm, as an array task.
for kind in tiles bakes; do
  tasks=$(wc -l < "$out/$kind.tasks")
  logs=$(ls "$out/logs/$kind"/task-*.out | wc -l)
  done=$(cat "$out/logs/$kind"/task-*.out | grep -c "^task [0-9]*: done in" || true)
  [ "$logs" = "$tasks" ] && [ "$done" = "$tasks" ] ||
    fail "$kind: $tasks tasks, $logs logs, $done done"
  if [ "$mode" = --slurm ]; then
    slurm_tasks=$(cat "$out/logs/$kind"/task-*.out | grep -c "^task [0-9]* on .*(Slurm job [0-9]*_[0-9]*)" || true)
    [ "$slurm_tasks" = "$tasks" ] || fail "$kind: $slurm_tasks of $tasks tasks ran as Slurm array tasks"
  fi
done

# Idempotent: a task run again gives its file again, byte for byte.
cp "$out/tiles/tile-000-000.exr" "$dir/tile-before.exr"
if [ "$mode" = --slurm ]; then
  sbatch --wait --array=0 --output="$dir/rerun-%a.out" "$farm/run_task.sh" "$out/tiles.tasks" > /dev/null ||
    fail "tile 0 run again on Slurm failed"
else
  bash "$farm/run_task.sh" "$out/tiles.tasks" 0 > "$dir/rerun-0.out"
fi
cmp "$dir/tile-before.exr" "$out/tiles/tile-000-000.exr" || fail "tile 0 run again wrote other bytes"
echo "farm example ($mode): checked"
