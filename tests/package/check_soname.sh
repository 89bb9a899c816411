#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Checks an installed shared libcmfilter: its SONAME is libcmfilter.so.SOVERSION
# and the development link libcmfilter.so points at it.
#   check_soname.sh LIBDIR_PATH SOVERSION
set -euo pipefail
libdir=$1 soversion=$2
fail() { echo "check_soname: $*" >&2; exit 1; }
[ -L "$libdir/libcmfilter.so" ] || fail "$libdir/libcmfilter.so is not a link"
soname=$(readelf -d "$libdir/libcmfilter.so" | sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')
echo "SONAME $soname"
[ "$soname" = "libcmfilter.so.$soversion" ] || fail "SONAME is '$soname', not libcmfilter.so.$soversion"
[ -e "$libdir/$soname" ] || fail "$libdir/$soname is not installed"
