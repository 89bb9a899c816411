#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Compiles every installed header on its own (twice in one file, for its
# include guard) against the install prefix only, with the flags pkg-config
# gives for cmfilter: a public header that includes an internal one, or that
# lacks an include of its own, fails here.
#   check_headers.sh PREFIX LIBDIR CXX
set -euo pipefail
prefix=$1 libdir=$2 cxx=$3
export PKG_CONFIG_PATH="$prefix/$libdir/pkgconfig"
cflags=$(pkg-config --cflags cmfilter)
cd "$prefix/include"
headers=$(find cmfilter -name '*.h' | sort)
[ -n "$headers" ] || { echo "check_headers: no headers under $prefix/include/cmfilter" >&2; exit 1; }

compile_one() {
    local header=$1
    local log
    if ! log=$(printf '#include "%s"\n#include "%s"\n' "$header" "$header" |
               $cxx -std=c++17 -fsyntax-only -Wall -Wextra $cflags -x c++ - 2>&1); then
        printf '%s does not compile on its own:\n%s\n' "$header" "$log" >&2
        return 1
    fi
}
export -f compile_one
export cxx cflags
jobs=$(nproc 2>/dev/null || echo 2)
[ "$jobs" -le 4 ] || jobs=4
if ! printf '%s\n' $headers | xargs -P "$jobs" -I{} bash -c 'compile_one "$1"' _ {}; then
    echo "check_headers: some installed headers do not compile on their own" >&2
    exit 1
fi
echo "$(echo "$headers" | wc -l) installed headers compile on their own against $prefix"
