#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Runs one task of a task file (one command line per line): line INDEX + 1,
# INDEX counting from 0 as Slurm's array task ids do (default
# $SLURM_ARRAY_TASK_ID). Prints the task, then "task INDEX: done in S s" or
# "task INDEX: failed (exit N) after S s", and exits as the task did.
#   run_task.sh TASKS [INDEX]
set -uo pipefail
tasks=${1:?usage: run_task.sh TASKS [INDEX]}
index=${2:-${SLURM_ARRAY_TASK_ID:?usage: run_task.sh TASKS [INDEX] (or SLURM_ARRAY_TASK_ID set)}}
[[ $index =~ ^[0-9]+$ ]] || { echo "run_task.sh: task index '$index' is not an integer >= 0" >&2; exit 1; }
line=$(sed -n "$((index + 1))p" "$tasks")
[ -n "$line" ] || { echo "run_task.sh: '$tasks' has no task $index" >&2; exit 1; }
where=$(hostname -s)
[ -z "${SLURM_ARRAY_JOB_ID:-}" ] || where+=" (Slurm job ${SLURM_ARRAY_JOB_ID}_${SLURM_ARRAY_TASK_ID:-})"
echo "task $index on $where: $line"
start=$(date +%s.%N)
bash -c "$line"
code=$?
seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }')
if [ "$code" = 0 ]; then
  echo "task $index: done in $seconds s"
else
  echo "task $index: failed (exit $code) after $seconds s"
fi
exit "$code"
