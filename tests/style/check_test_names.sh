#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Every doctest case becomes a ctest test named after it, and ctest splits a
# name at ';' (a CMake list separator): the pieces match no case and run
# nothing, yet pass. This check fails on any TEST_CASE name with a ';'.
#   check_test_names.sh SOURCE_DIR
set -u
found=$(grep -rn --include='*.cpp' -E 'TEST_CASE\("[^"]*;' "$1/tests" || true)
if [ -n "$found" ]; then
  echo "TEST_CASE names with ';' (ctest would run none of them):"
  echo "$found"
  exit 1
fi
echo "no TEST_CASE name holds a ';'"
