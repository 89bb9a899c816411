#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Lists the C++ sources that clang-format, with the repository's .clang-format,
# would change, and exits 1 if there are any (0 if there are none). Without
# clang-format it changes nothing and exits 77, the code ctest's
# SKIP_RETURN_CODE can take for "skipped".
#   check_format.sh [FILE...]
# With no FILE: every *.cpp and *.h under lib/, tools/, python/, tests/, examples/ and
# luts/. CLANG_FORMAT names the program (default clang-format); the style is
# measured with clang-format 14, and other versions may format differently.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
clang_format=${CLANG_FORMAT:-clang-format}

if ! command -v "$clang_format" >/dev/null 2>&1; then
  echo "check_format.sh: $clang_format not found; skipped" >&2
  exit 77
fi
version=$("$clang_format" --version | grep -o '[0-9][0-9]*\.[0-9][0-9]*\.[0-9][0-9]*' | head -1)
if [ "${version%%.*}" != 14 ]; then
  echo "check_format.sh: warning: the style is measured with clang-format 14; $clang_format is ${version:-unknown}" >&2
fi

cd "$root" || exit 2
if [ $# -gt 0 ]; then
  files=("$@")
else
  mapfile -t files < <(find lib tools python tests examples luts -type f \( -name '*.cpp' -o -name '*.h' \) | LC_ALL=C sort)
fi

for f in "${files[@]}"; do
  if [ ! -f "$f" ]; then
    echo "check_format.sh: $f: no such file" >&2
    exit 2
  fi
done

# One clang-format process for all the files (each process takes a tenth of
# a second to start): --dry-run reports every place it would change, as
# "FILE:LINE:COLUMN: error: code should be clang-formatted", and --style=file
# reads the .clang-format nearest each file: the repository's.
report=$(mktemp)
trap 'rm -f "$report"' EXIT
printf '%s\0' "${files[@]}" | xargs -0 "$clang_format" --style=file --dry-run --Werror >"$report" 2>&1
status=$?
mapfile -t changed < <(sed -nE 's/^(.*):[0-9]+:[0-9]+: (error|warning): code should be clang-formatted.*/\1/p' "$report" |
                       LC_ALL=C sort -u)
if [ "$status" -ne 0 ] && [ ${#changed[@]} -eq 0 ]; then
  cat "$report" >&2
  echo "check_format.sh: $clang_format failed" >&2
  exit 2
fi
if [ ${#changed[@]} -gt 0 ]; then
  printf '%s\n' "${changed[@]}"
  echo "check_format.sh: ${#changed[@]} of ${#files[@]} files are not formatted; clang-format -i FILE formats one" >&2
  exit 1
fi
echo "check_format.sh: ${#files[@]} files formatted"
