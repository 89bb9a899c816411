#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# A second, shared (BUILD_SHARED_LIBS=ON) build of the library alone, installed
# into its own prefix: its SONAME, then examples/lookup_table.cpp and the
# plugin built against it by find_package and pkg-config, each run on TABLE.
#   check_shared.sh SOURCE WORK CXX VERSION SOVERSION LIBDIR TABLE ERE [LAUNCHER]
set -euo pipefail
source=$1 work=$2 cxx=$3 version=$4 soversion=$5 libdir=$6 table=$7 pattern=$8 launcher=${9:-}
here=$(cd "$(dirname "$0")" && pwd)
build=$work/build prefix=$work/prefix
rm -rf "$work"
mkdir -p "$work"
# quietly LOG COMMAND...: the command's output goes to LOG, shown if it fails.
quietly() {
    local log=$1
    shift
    "$@" > "$log" 2>&1 || { cat "$log" >&2; echo "check_shared: '$*' failed" >&2; exit 1; }
}
args=(-S "$source" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$cxx" -DBUILD_SHARED_LIBS=ON
      -DCMFILTER_BUILD_TOOLS=OFF -DCMFILTER_BUILD_EXAMPLES=OFF -DCMFILTER_BUILD_TESTS=OFF -DCMFILTER_PYTHON=OFF
      -DCMAKE_INSTALL_LIBDIR="$libdir")
[ -z "$launcher" ] || args+=(-DCMAKE_CXX_COMPILER_LAUNCHER="$launcher")
quietly "$work/configure.log" cmake "${args[@]}"
quietly "$work/build.log" cmake --build "$build" --parallel 2 --target cmfilter
quietly "$work/install.log" cmake --install "$build" --prefix "$prefix"
bash "$here/check_soname.sh" "$prefix/$libdir" "$soversion"

example=$source/examples/lookup_table.cpp
quietly "$work/consumer.log" \
    bash "$here/build_consumer.sh" "$here/consumer" "$work/consumer" "$prefix" "$cxx" "$example" "$launcher"
bash "$here/expect_output.sh" "$pattern" -- "$work/consumer/lookup_table" "$table" 0.5 0
bash "$here/expect_output.sh" "$pattern" -- \
    "$work/consumer/plugin_host" "$work/consumer/liblookup_plugin.so" "$table" 0.5 0
bash "$here/expect_output.sh" "$pattern" -- \
    bash "$here/check_pkg_config.sh" "$prefix" "$libdir" "$cxx" "$version" "$example" "$work/pkg-config" SHARED \
    "$table" 0.5 0
