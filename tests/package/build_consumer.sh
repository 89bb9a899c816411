#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Configures and builds tests/package/consumer against an install prefix,
# with CMAKE_PREFIX_PATH the only way to cmfilter.
#   build_consumer.sh CONSUMER_SOURCE BUILD PREFIX CXX EXAMPLE_CPP [LAUNCHER]
set -euo pipefail
source=$1 build=$2 prefix=$3 cxx=$4 example=$5 launcher=${6:-}
rm -rf "$build"
args=(-S "$source" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$cxx"
      -DCMAKE_PREFIX_PATH="$prefix" -DCMFILTER_EXPECTED_PREFIX="$prefix"
      -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DCMFILTER_EXAMPLE="$example")
[ -z "$launcher" ] || args+=(-DCMAKE_CXX_COMPILER_LAUNCHER="$launcher")
cmake "${args[@]}"
cmake --build "$build" --parallel 2
