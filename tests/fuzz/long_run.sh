#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The long fuzz run of docs/reliability.md: every harness's ctest test
# (fuzz.<harness>) with RUNS inputs each instead of CI's few, two at a time,
# then one table row a harness from the logs the tests keep:
#   bash tests/fuzz/long_run.sh CHECKED_BUILD [RUNS]   (RUNS: 1000000)
# CHECKED_BUILD: a build with CMFILTER_FUZZ=ON. Any crash, leak, timeout or
# failed check fails its test, and the run exits non-zero. Harnesses: a
# ctest regular expression in CMFILTER_FUZZ_ONLY (default: all). The image
# harnesses spend their time in proportion to the sizes the fuzzer declares,
# up to what the library may allocate: CMFILTER_FUZZ_MEMORY_LIMIT (default
# 16M, as in CI) lowers that cap for a run. An input fails the run after
# CMFILTER_FUZZ_TIMEOUT seconds (default 60: libFuzzer's clock is the wall
# clock, and a long run shares the machine); the table gives each harness's
# slowest input, to be timed alone.
# The build must instrument the library for coverage
# (CMFILTER_FUZZ_LIBRARY_COVERAGE, on by default; bootstrap.sh's CI tree
# turns it off), or the fuzzer is blind inside it:
#   cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug \
#         "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -gline-tables-only" "-DCMFILTER_SANITIZE=address;undefined" \
#         -DCMFILTER_FUZZ=ON -DBUILD_SHARED_LIBS=ON -DCMFILTER_PRECOMPILE_HEADERS=ON
set -uo pipefail
build=$(cd "$1" && pwd)
if grep -q '^CMFILTER_FUZZ_LIBRARY_COVERAGE:BOOL=OFF' "$build/CMakeCache.txt" 2>/dev/null; then
  echo "long_run.sh: $build does not instrument the library for coverage (CMFILTER_FUZZ_LIBRARY_COVERAGE=OFF)" >&2
  exit 2
fi
runs=${2:-1000000}
export CMFILTER_FUZZ_RUNS=$runs
export CMFILTER_FUZZ_TIMEOUT=${CMFILTER_FUZZ_TIMEOUT:-60}
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:new_delete_type_mismatch=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
start=$(date +%s)
(cd "$build" && ctest -L fuzz -R "${CMFILTER_FUZZ_ONLY:-.}" -j"$(nproc)" --timeout 0 --output-on-failure)
status=$?
echo
echo "$runs inputs a harness, memory cap ${CMFILTER_FUZZ_MEMORY_LIMIT:-16M}, timeout $CMFILTER_FUZZ_TIMEOUT s, $(( $(date +%s) - start )) s in all; $(clang++ --version | head -1)"
echo
echo "| harness | inputs run | seconds | inputs/s | edges covered | of instrumented | features | corpus at end | slowest input (s) | peak RSS (MB) |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for log in "$build"/tests/fuzz/found/*.log; do
  name=$(basename "$log" .log)
  [[ "fuzz.$name" =~ ${CMFILTER_FUZZ_ONLY:-.} ]] || continue
  units=$(sed -nE 's/^stat::number_of_executed_units: *([0-9]+)/\1/p' "$log" | tail -1)
  rate=$(sed -nE 's/^stat::average_exec_per_sec: *([0-9]+)/\1/p' "$log" | tail -1)
  rss=$(sed -nE 's/^stat::peak_rss_mb: *([0-9]+)/\1/p' "$log" | tail -1)
  total=$(sed -nE 's/.*Loaded [0-9]+ modules +\(([0-9]+) inline 8-bit counters\).*/\1/p' "$log" | head -1)
  slowest=$(sed -nE 's/^stat::slowest_unit_time_sec: *([0-9]+)/\1/p' "$log" | tail -1)
  done_line=$(grep -E '^#[0-9]+[[:space:]]+DONE' "$log" | tail -1)
  cov=$(sed -nE 's/.* cov: ([0-9]+).*/\1/p' <<< "$done_line")
  ft=$(sed -nE 's/.* ft: ([0-9]+).*/\1/p' <<< "$done_line")
  corp=$(sed -nE 's/.* corp: ([0-9]+)\/.*/\1/p' <<< "$done_line")
  seconds=$(( ${units:-0} / (${rate:-1} > 0 ? ${rate:-1} : 1) ))
  pct=""
  [ -n "$cov" ] && [ -n "$total" ] && pct=" ($(( 100 * cov / total ))%)"
  echo "| \`$name\` | ${units:-failed} | $seconds | ${rate:-} | ${cov:-}$pct | ${total:-} | ${ft:-} | ${corp:-} | ${slowest:-} | ${rss:-} |"
done
exit $status
