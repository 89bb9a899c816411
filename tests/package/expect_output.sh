#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Runs a command and checks it exits 0 and that its standard output matches
# an extended regular expression.
#   expect_output.sh ERE -- COMMAND...
set -uo pipefail
pattern=$1
shift 2
out=$("$@")
status=$?
printf '%s\n' "$out"
[ "$status" -eq 0 ] || { echo "expect_output: '$*' exited $status" >&2; exit 1; }
[[ "$out" =~ $pattern ]] || { echo "expect_output: the output does not match '$pattern'" >&2; exit 1; }
