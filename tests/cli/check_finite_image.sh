#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# An image a command-line test wrote: it exists, OpenImageIO reads it as
# WIDTH x HEIGHT, and every channel of every pixel is finite (oiiotool
# --stats: no NaN, no infinity, WIDTH * HEIGHT finite values), and with
# --nonnegative >= 0 too (no negative minimum: colours, not AOVs).
#   check_finite_image.sh OIIOTOOL IMAGE WIDTH HEIGHT [--nonnegative]
set -u
oiiotool=$1; image=$2; width=$3; height=$4; nonnegative=${5:-}
if [ ! -f "$image" ]; then echo "FAIL: $image was not written"; exit 1; fi
stats=$("$oiiotool" --info --stats "$image" 2>&1) || { echo "$stats"; echo "FAIL: oiiotool cannot read $image"; exit 1; }
echo "$stats"
fail=0
if ! echo "$stats" | head -1 | grep -Eq ": +$width x +$height, "; then echo "FAIL: not $width x $height"; fail=1; fi
pixels=$((width * height))
keys="NanCount InfCount FiniteCount"
[ "$nonnegative" = --nonnegative ] && keys="$keys Min"
for key in $keys; do
  line=$(echo "$stats" | grep -E "Stats $key:" | head -1)
  if [ -z "$line" ]; then echo "FAIL: no 'Stats $key' line"; fail=1; continue; fi
  values=$(echo "$line" | sed -e "s/.*$key://" -e 's/(float)//')
  for v in $values; do
    case $key in
      NanCount|InfCount) [ "$v" = 0 ] || { echo "FAIL: $key $v"; fail=1; } ;;
      FiniteCount) [ "$v" = "$pixels" ] || { echo "FAIL: $key $v, expected $pixels"; fail=1; } ;;
      Min) case $v in -*) echo "FAIL: a negative value, min $v"; fail=1 ;; esac ;;
    esac
  done
done
exit $fail
