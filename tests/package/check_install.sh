#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs a build into a fresh prefix and checks what lands there: the
# library, its CMake and pkg-config packages, exactly the public headers of
# lib/public_headers.txt, the cmfilter command and the data under
# share/cmfilter (the bundled scenes' relative paths resolving). Then bakes,
# with the installed command and colour map, the table the other package
# tests look up.
#   check_install.sh BUILD PREFIX LIBDIR PUBLIC_HEADERS_TXT TABLE_OUT
set -euo pipefail
build=$1 prefix=$2 libdir=$3 list=$4 table=$5
fail() { echo "check_install: $*" >&2; exit 1; }

rm -rf "$prefix" "$table"
cmake --install "$build" --prefix "$prefix" > "$prefix.install.log" || { cat "$prefix.install.log"; fail "cmake --install failed"; }

for f in bin/cmfilter \
         "$libdir"/cmake/cmfilter/cmfilterConfig.cmake \
         "$libdir"/cmake/cmfilter/cmfilterConfigVersion.cmake \
         "$libdir"/cmake/cmfilter/cmfilterTargets.cmake \
         "$libdir"/pkgconfig/cmfilter.pc \
         share/cmfilter/luts/README.md share/cmfilter/luts/terrain.png \
         share/cmfilter/ocio/config.ocio \
         share/cmfilter/shaders/cmfilter_color_table.glsl share/cmfilter/shaders/hlsl/cmfilter_color_table.hlsl \
         share/cmfilter/examples/scenes/plane-fbm-terrain.json \
         share/doc/cmfilter/LICENSE; do
    [ -f "$prefix/$f" ] || fail "$f is not installed"
done
[ -e "$prefix/$libdir/libcmfilter.a" ] || [ -e "$prefix/$libdir/libcmfilter.so" ] ||
    fail "neither $libdir/libcmfilter.a nor $libdir/libcmfilter.so is installed"

# Exactly the public headers, no internal one.
expected=$(sed 's/#.*//' "$list" | awk 'NF { print "cmfilter/" $1 }' | sort)
installed=$(cd "$prefix/include" && find cmfilter -type f | sort)
if [ "$expected" != "$installed" ]; then
    diff <(echo "$expected") <(echo "$installed") |
        sed -n 's/^</  listed, not installed:/p; s/^>/  installed, not listed:/p' >&2 || true
    fail "the installed headers are not lib/public_headers.txt's"
fi

# Every file a bundled scene names lies where the scene looks for it.
for scene in "$prefix"/share/cmfilter/examples/scenes/*.json; do
    dir=$(dirname "$scene")
    for name in $(grep -o '"[^"]*\.\(png\|exr\)"' "$scene" | tr -d '"'); do
        [ -f "$dir/$name" ] || fail "$(basename "$scene") names $name, not installed at $dir/$name"
    done
done

"$prefix/bin/cmfilter" bake-colormap "$prefix/share/cmfilter/luts/stripes.png" -o "$table" --quiet ||
    fail "the installed cmfilter could not bake the installed stripes.png"
[ -f "$table" ] || fail "no $table"
echo "installed into $prefix: $(echo "$installed" | wc -l) public headers, the packages, the command and the data"
