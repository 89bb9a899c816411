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

# With clang, OpenImageIO's imageio.h (most of the time a header takes) is
# parsed once, into a precompiled header, and used for the headers that
# include it anyway, directly or not (their dependencies, -M, name it): for
# them it declares nothing they would not see without it. The others, and
# every header with another compiler, are compiled as they are.
pch=""
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if $cxx --version 2>/dev/null | grep -q clang; then
    echo '#include <OpenImageIO/imageio.h>' > "$work/oiio.h"
    if $cxx -std=c++17 -Wall -Wextra $cflags -x c++-header "$work/oiio.h" -o "$work/oiio.pch" 2>/dev/null; then
        pch=$work/oiio.pch
    fi
fi

compile_one() {
    local header=$1
    local log use_pch=()
    if [ -n "$pch" ] &&
       printf '#include "%s"\n' "$header" | $cxx -std=c++17 $cflags -M -x c++ - 2>/dev/null |
           grep -q 'OpenImageIO/imageio\.h'; then
        use_pch=(-include-pch "$pch")
    fi
    if ! log=$(printf '#include "%s"\n#include "%s"\n' "$header" "$header" |
               $cxx -std=c++17 -fsyntax-only -Wall -Wextra $cflags "${use_pch[@]}" -x c++ - 2>&1); then
        printf '%s does not compile on its own:\n%s\n' "$header" "$log" >&2
        return 1
    fi
}
export -f compile_one
export cxx cflags pch
jobs=$(nproc 2>/dev/null || echo 2)
[ "$jobs" -le 4 ] || jobs=4
if ! printf '%s\n' $headers | xargs -P "$jobs" -I{} bash -c 'compile_one "$1"' _ {}; then
    echo "check_headers: some installed headers do not compile on their own" >&2
    exit 1
fi
echo "$(echo "$headers" | wc -l) installed headers compile on their own against $prefix"
