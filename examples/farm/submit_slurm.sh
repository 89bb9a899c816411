#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Runs every task of a task file as one Slurm job array (sbatch --array), one
# array task per line, and waits for the array (sbatch --wait); each array
# task runs run_task.sh with its SLURM_ARRAY_TASK_ID and writes its output
# to LOGDIR/task-<index>.out. The tasks must see the same paths as this
# machine (a shared file system, or one machine). Exits as sbatch --wait
# does: 0 when every task succeeded. SBATCH_OPTIONS adds options to sbatch
# (a partition, a time limit, an account), word-split.
#   submit_slurm.sh TASKS LOGDIR [CPUS_PER_TASK]
set -euo pipefail
tasks=${1:?usage: submit_slurm.sh TASKS LOGDIR [CPUS_PER_TASK]}
logs=${2:?usage: submit_slurm.sh TASKS LOGDIR [CPUS_PER_TASK]}
cpus=${3:-1}
here=$(cd "$(dirname "$0")" && pwd)
tasks=$(cd "$(dirname "$tasks")" && pwd)/$(basename "$tasks")
count=$(grep -c . "$tasks" || true)
[ "$count" -gt 0 ] || { echo "submit_slurm.sh: '$tasks' holds no task" >&2; exit 1; }
mkdir -p "$logs"
logs=$(cd "$logs" && pwd)
# shellcheck disable=SC2086
sbatch --wait --parsable --array="0-$((count - 1))" --cpus-per-task="$cpus" \
       --job-name="cmfilter-$(basename "$tasks" .tasks)" --chdir="$(pwd)" \
       --output="$logs/task-%a.out" ${SBATCH_OPTIONS:-} "$here/run_task.sh" "$tasks"
