#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# One fuzz test: run_fuzzer.sh HARNESS FOUND_DIR RUNS CORPUS REGRESSIONS [-dict=FILE]
# Runs every seed and regression input once, then RUNS further inputs the
# fuzzer makes from them (new ones are kept in FOUND_DIR, in the build tree).
# Fails on a crash, a leak, a timeout (10 s an input), a sanitizer report or
# an input over libFuzzer's 2 GB memory limit. CMFILTER_FUZZ_RUNS in the
# environment replaces RUNS, CMFILTER_FUZZ_TIMEOUT the 10 s (long_run.sh).
# The output is also kept in FOUND_DIR.log.
set -euo pipefail
harness=$1 found=$2 runs=${CMFILTER_FUZZ_RUNS:-$3} corpus=$4 regressions=$5
shift 5
mkdir -p "$found"
inputs=("$found")
for dir in "$corpus" "$regressions"; do
  [ -d "$dir" ] && inputs+=("$dir")
done
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
cd "$found/.."
timeout=${CMFILTER_FUZZ_TIMEOUT:-10}
"$harness" "$@" -runs="$runs" -seed=1 -timeout="$timeout" -rss_limit_mb=2048 -max_len=65536 \
  -print_final_stats=1 -artifact_prefix="$found.crash-" "${inputs[@]}" 2>&1 | tee "$found.log"
