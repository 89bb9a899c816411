#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Rebuilds the seed corpora under tests/fuzz/corpus/ from the bundled files
# and from what the command-line tests read and write (bad inputs included):
#   bash tests/fuzz/make_corpus.sh CHECKED_BUILD
# CHECKED_BUILD: a build with CMFILTER_FUZZ=ON whose tests have run (the
# files its tests/cli/out and fixtures hold). Candidates are merged by each
# harness (libFuzzer -merge=1), so a corpus keeps only inputs that reach
# code the others do not.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/../.." && pwd)
checked=$(cd "$1" && pwd)

cli_out=$checked/tests/cli/out
cli_fix=$checked/tests/cli/fixtures
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cand() { mkdir -p "$work/$1"; echo "$work/$1"; }

# Text inputs: every file of the kind the tests and examples have.
for f in "$src"/examples/scenes/*.json "$src"/tests/cli/scenes/*.json "$checked"/tests/cli/scenes/*.json; do
  [ -f "$f" ] && cp "$f" "$(cand scene_json)/$(basename "$f")"
done
find "$cli_out" "$cli_fix" "$src/examples" -name '*.lp' -size -64k | while read -r f; do
  cp "$f" "$(cand light_file)/$(echo "$f" | sha1sum | cut -c1-12).lp"; done
find "$cli_out" "$cli_fix" -name '*.ptm' -size -64k | while read -r f; do
  cp "$f" "$(cand ptm)/$(echo "$f" | sha1sum | cut -c1-12).ptm"; done
find "$cli_out" "$cli_fix" -name '*.rti' -size -64k | while read -r f; do
  cp "$f" "$(cand rti)/$(echo "$f" | sha1sum | cut -c1-12).rti"; done
find "$cli_out" "$cli_fix" "$src/examples" -name '*.json' -size -64k | while read -r f; do
  if grep -q '"views"' "$f"; then cp "$f" "$(cand btf_manifest)/$(echo "$f" | sha1sum | cut -c1-12).json"; fi
  if grep -q '"dome"' "$f"; then cp "$f" "$(cand stack_record)/$(echo "$f" | sha1sum | cut -c1-12).json"; fi
done
# Noise specs and option values as the tests and scenes write them.
grep -rhoE '"noise": *"[^"]*"' "$src/examples" "$src/tests/cli" | sed -E 's/.*: *"(.*)"/\1/' |
  cat - <(grep -rhoE -- '--noise [^ )]*' "$src/tests/cli" | cut -d' ' -f2) | sort -u | while read -r s; do
  printf '%s' "$s" > "$(cand noise_spec)/$(echo "$s" | sha1sum | cut -c1-12)"; done
option() {  # selector byte (fuzz_option_strings.cpp), then the values a flag takes in the tests
  local sel=$1 re=$2
  grep -rhoE -- "$re [^ )\"]+" "$src/tests/cli" "$src/README.md" "$src/docs" | awk '{print $2}' | sort -u |
    while read -r v; do
      printf "\\x$(printf %02x "$sel")%s" "$v" > "$(cand option_strings)/$sel-$(echo "$v" | sha1sum | cut -c1-12)"
    done
}
option 0 '--size'
option 1 '--range|--domain|--sigma-range'
option 2 '--light|--view'
option 3 '--dome'
option 4 '--specular'
option 5 '--method'
option 6 '--sigma-spacing'
option 7 '--wrap'
option 8 '--wrap'
option 9 '--lod-method'

# Images: the EXRs the tests write or read (the smallest 32 of each
# cmfilter:kind, which the encoder prints), and the colour maps, turned into
# the in-memory encoding.
encode=$checked/tests/fuzz/cmfilter_fuzz_encode_image
find "$cli_out" "$cli_fix" -name '*.exr' -size -1024k -printf '%s %p\n' | sort -n | cut -d' ' -f2- |
  while read -r f; do
    out=$work/$(echo "$f" | sha1sum | cut -c1-12).cmfuzz
    kind=$("$encode" "$f" "$out" 1024 2>/dev/null) || { rm -f "$out"; continue; }
    case "$kind" in
      gaussian-color-table|moment-pyramid|histogram-pyramid|noise-sigma-table|linear-fit|lafortune-fit|coordinate-map|synthesis-analysis)
        h=${kind//-/_} ;;
      *) h=color_map ;;
    esac
    dir=$(cand "$h")
    if [ "$(ls "$dir" | wc -l)" -lt 32 ]; then mv "$out" "$dir/"; else rm -f "$out"; fi
  done
for f in "$src"/luts/*.png "$cli_fix"/*.png; do
  "$encode" "$f" "$(cand color_map)/$(echo "$f" | sha1sum | cut -c1-12).cmfuzz" 1024 > /dev/null || true
done

for dir in "$work"/*/; do
  name=$(basename "$dir")
  mkdir -p "$here/corpus/$name"
  rm -f "$here/corpus/$name"/*
  (cd "$work" && "$checked/tests/fuzz/fuzz_$name" -merge=1 "$here/corpus/$name" "$dir" > "$work/$name.log" 2>&1) ||
    { echo "merging $name failed:"; tail -20 "$work/$name.log"; exit 1; }
  kept=$(ls "$here/corpus/$name" | wc -l)
  echo "corpus/$name: $kept inputs of $(ls "$dir" | wc -l) candidates"
  [ "$kept" -gt 0 ] || { echo "merging $name kept nothing:"; tail -20 "$work/$name.log"; }
done
