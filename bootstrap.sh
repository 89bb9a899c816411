#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Sets cmfilter up on a Debian machine and runs one of its jobs:
#   bash bootstrap.sh example   install what is missing, build, bake the bundled example into out/example/
#   bash bootstrap.sh test      install what is missing, build, run the test suite: the whole
#                               suite built with AddressSanitizer and UndefinedBehaviorSanitizer,
#                               the library shared, with the fuzz harnesses (build-checked/);
#                               the threaded tests under ThreadSanitizer (build-thread/)
#   bash bootstrap.sh test-release  the whole suite in the release build
#   bash bootstrap.sh test-checked | test-thread   one of the sanitized stages alone
set -euo pipefail
mode=${1:-}
case "$mode" in
  example|test|test-release|test-checked|test-thread) ;;
  *) echo "usage: bash bootstrap.sh example|test|test-release|test-checked|test-thread" >&2; exit 1 ;;
esac
cd "$(dirname "$0")"

packages=(g++ make cmake pkg-config
          libopenimageio-dev openimageio-tools libopencolorio-dev libopenexr-dev libimath-dev
          libcli11-dev doctest-dev nlohmann-json3-dev libeigen3-dev libceres-dev gnuplot-nox python3 python3-skimage
          clang-format)
# The tests: python3-jsonschema validates every command's --json against docs/cmfilter.schema.json;
# the Python module (pybind11) and its tests against NumPy, SciPy and matplotlib (docs/python.md).
[ "$mode" = example ] || packages+=(python3-jsonschema pybind11-dev python3-dev python3-numpy python3-scipy
                                   python3-matplotlib python3-pytest python3-tifffile)
# The checked builds: clang with its sanitizer and libFuzzer runtimes, and
# llvm-symbolizer for their reports; munge and Slurm for the farm example's
# test, which stands up a single-node cluster of its own (docs/farm.md).
[ "$mode" = example ] || packages+=(clang libclang-rt-14-dev llvm munge slurm-wlm)
# The shaders' checks (docs/shaders.md): glslangValidator and spirv-cross,
# and OpenGL through EGL on Mesa's software rasteriser, llvmpipe (headless).
[ "$mode" = example ] || packages+=(glslang-tools spirv-cross libegl-dev libopengl-dev libgl-dev libegl-mesa0
                                   libgl1-mesa-dri)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "bootstrap: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" = 0 ] || sudo=sudo
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

jobs=$(nproc 2>/dev/null || echo 2)
# Tests two a core: most of a command-line test is starting the command
# (about 260 shared libraries), which leaves a core idle part of the time
# (docs/reliability.md).
test_jobs=$((2 * jobs))
# Sanitized code runs at -O1 with line tables: fast enough to run the whole
# suite, and reports name file and line.
checked_flags=(-DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -gline-tables-only")
# new_delete_type_mismatch=0: OpenImageIO 2.4's TextureSystem::destroy
# deletes its implementation through the base class, which AddressSanitizer
# reports inside libOpenImageIO (docs/reliability.md).
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:check_initialization_order=1:strict_init_order=1:new_delete_type_mismatch=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
# detect_deadlocks=0: its lock-order detector fails an internal check (and
# hangs) on OpenEXR's thread pool, which holds more locks at once than it
# tracks; races are still detected.
export TSAN_OPTIONS=${TSAN_OPTIONS:-halt_on_error=1:detect_deadlocks=0:suppressions=$PWD/tests/sanitizers/tsan.supp}

# Precompiled headers make every build here faster (a plain cmake build
# goes without them).
release() {
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCMFILTER_PRECOMPILE_HEADERS=ON
  cmake --build build -j"$jobs"
}

case "$mode" in
  example)
    release
    bash examples/run.sh build/tools/cmfilter out/example
    ;;
  test|test-release|test-checked|test-thread)
    if [ "$mode" = test-release ]; then
      release
      (cd build && ctest --output-on-failure -j"$jobs")
    fi
    if [ "$mode" = test ] || [ "$mode" = test-checked ]; then
      echo "bootstrap: the whole suite under AddressSanitizer + UndefinedBehaviorSanitizer, and the fuzzers"
      # Shared, as a renderer's plugin links it: the package tests check the
      # installed shared library (its SONAME, find_package, pkg-config,
      # dlopen) without building the library a second time.
      cmake -S . -B build-checked "${checked_flags[@]}" -DCMFILTER_PRECOMPILE_HEADERS=ON \
            "-DCMFILTER_SANITIZE=address;undefined" -DCMFILTER_FUZZ=ON -DCMFILTER_FUZZ_LIBRARY_COVERAGE=OFF \
            -DBUILD_SHARED_LIBS=ON
      cmake --build build-checked -j"$jobs"
      (cd build-checked && ctest --output-on-failure -j"$test_jobs")
    fi
    if [ "$mode" = test ] || [ "$mode" = test-thread ]; then
      echo "bootstrap: the threaded tests under ThreadSanitizer"
      cmake -S . -B build-thread "${checked_flags[@]}" -DCMFILTER_PRECOMPILE_HEADERS=ON -DCMFILTER_SANITIZE=thread
      cmake --build build-thread -j"$jobs" --target cmfilter_cli cmfilter_thread_tests cmfilter_make_fixtures
      (cd build-thread && ctest --output-on-failure -j"$test_jobs" -L threads)
    fi
    ;;
esac
