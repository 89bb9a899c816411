#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Whether two images hold the same pixels, bit for bit: idiff with no
# tolerance (every channel of every pixel equal, the windows alike), then the
# pixel data byte for byte: each image rewritten as an uncompressed float
# TIFF with every attribute dropped and one fixed date, and the two compared
# with cmp (so a -0 against a 0, or two different NaNs, differ too).
#   same_pixels.sh A B
set -euo pipefail
[ $# = 2 ] || { echo "usage: same_pixels.sh A B" >&2; exit 1; }
if ! idiff -q -fail 0 -failpercent 0 -warn 0 "$1" "$2" > /dev/null 2>&1; then
  echo "same_pixels.sh: '$1' and '$2' differ:" >&2
  idiff -fail 0 -failpercent 0 -warn 0 "$1" "$2" >&2 || true
  exit 1
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
bare=(--eraseattrib ".*" --attrib DateTime "2000:01:01 00:00:00" -d float --compression none)
oiiotool --nosoftwareattrib "$1" "${bare[@]}" -o "$work/1.tif" "$2" "${bare[@]}" -o "$work/2.tif"
cmp -s "$work/1.tif" "$work/2.tif" || { echo "same_pixels.sh: '$1' and '$2' differ in their pixel bytes" >&2; exit 1; }
