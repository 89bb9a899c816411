#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds examples/lookup_table.cpp with nothing but `pkg-config --cflags --libs
# cmfilter` (--static for the static library) against the install prefix,
# and runs it on TABLE; the caller checks what it prints.
#   check_pkg_config.sh PREFIX LIBDIR CXX VERSION EXAMPLE_CPP WORK STATIC|SHARED TABLE MEAN SIGMA
set -euo pipefail
prefix=$1 libdir=$2 cxx=$3 version=$4 example=$5 work=$6 linkage=$7
shift 7
export PKG_CONFIG_PATH="$prefix/$libdir/pkgconfig"
fail() { echo "check_pkg_config: $*" >&2; exit 1; }

got=$(pkg-config --modversion cmfilter) || fail "pkg-config does not find cmfilter in $PKG_CONFIG_PATH"
[ "$got" = "$version" ] || fail "cmfilter.pc says version $got, the build $version"
[ "$(pkg-config --variable=includedir cmfilter)" -ef "$prefix/include" ] ||
    fail "cmfilter.pc's includedir is not $prefix/include"

mkdir -p "$work"
if [ "$linkage" = STATIC ]; then
    flags=$(pkg-config --cflags --libs --static cmfilter)
else
    flags="$(pkg-config --cflags --libs cmfilter) -Wl,-rpath,$prefix/$libdir"
fi
$cxx -std=c++17 -O1 "$example" -o "$work/lookup_table" $flags > "$work/build.log" 2>&1 ||
    { cat "$work/build.log" >&2; fail "$cxx $example $flags failed"; }
exec "$work/lookup_table" "$@"
