#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Runs every task of a task file on this machine, JOBS at a time (default
# 1), each through run_task.sh as a farm runs it; each task's output goes to
# LOGDIR/task-<index>.out. Exits 1 if any task failed, naming them.
#   run_local.sh TASKS LOGDIR [JOBS]
set -euo pipefail
tasks=${1:?usage: run_local.sh TASKS LOGDIR [JOBS]}
logs=${2:?usage: run_local.sh TASKS LOGDIR [JOBS]}
jobs=${3:-1}
here=$(cd "$(dirname "$0")" && pwd)
count=$(grep -c . "$tasks" || true)
[ "$count" -gt 0 ] || { echo "run_local.sh: '$tasks' holds no task" >&2; exit 1; }
mkdir -p "$logs"
seq 0 $((count - 1)) |
  xargs -P "$jobs" -I{} bash -c 'bash "$0/run_task.sh" "$1" {} > "$2/task-{}.out" 2>&1' "$here" "$tasks" "$logs" ||
  true
failed=$(grep -L "^task [0-9]*: done in" "$logs"/task-*.out || true)
[ -z "$failed" ] || { echo "run_local.sh: failed: $failed" >&2; exit 1; }
