#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Checks cmfilter compare's RMSE against OpenImageIO's own (oiiotool --diff,
# "RMS error": the root mean square over every channel of every pixel). The
# two agree only for images whose values cmfilter does not convert (float
# files, linear by default) and that have exactly R, G, B channels.
#   check_rmse_vs_oiiotool.sh CMFILTER OIIOTOOL A B
set -u
cmfilter=$1; oiiotool=$2; a=$3; b=$4
ours=$("$cmfilter" compare "$a" "$b" --json | sed -n 's/^  "rmse": \([-0-9.e+]*\),*$/\1/p')
theirs=$("$oiiotool" --diff "$a" "$b" | sed -n 's/^ *RMS error = \([-0-9.e+]*\)$/\1/p')
echo "cmfilter compare rmse: $ours"
echo "oiiotool --diff RMS error: $theirs"
if [ -z "$ours" ] || [ -z "$theirs" ]; then echo "FAIL: could not read both values"; exit 1; fi
# Tolerance: oiiotool prints 6 significant digits (rounding <= 5e-6 relative);
# both sum float32 differences, in double here, which adds far less. 1e-5
# relative still catches a wrong denominator (3 vs 4 channels: 15%) or any
# clipping of the HDR and negative fixture values.
awk -v o="$ours" -v t="$theirs" 'BEGIN {
  d = o - t; if (d < 0) d = -d;
  if (t > 0 && d <= 1e-5 * t) { print "OK"; exit 0 }
  print "FAIL: differ by " d; exit 1 }'
