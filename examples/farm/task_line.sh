# SPDX-License-Identifier: Apache-2.0
# Sourced by the planners (plan_tiles.sh, plan_bakes.sh):
#   task_line WORD...   prints the words as one command line of a task file,
#                       each as it is where that is safe, else quoted so that
#                       the shell reads it back as the same word.
task_word() {
  if [[ $1 =~ ^[A-Za-z0-9_./,:=+@%-]+$ ]]; then printf '%s' "$1"; else printf '%q' "$1"; fi
}
task_line() {
  local out=() w
  for w in "$@"; do out+=("$(task_word "$w")"); done
  echo "${out[*]}"
}
