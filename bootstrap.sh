#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Sets cmfilter up on a Debian machine and runs one of its two jobs:
#   bash bootstrap.sh example   install what is missing, build, bake the bundled example into out/example/
#   bash bootstrap.sh test      install what is missing, build, run the whole test suite
set -euo pipefail
mode=${1:-}
case "$mode" in
  example|test) ;;
  *) echo "usage: bash bootstrap.sh example|test" >&2; exit 1 ;;
esac
cd "$(dirname "$0")"

packages=(g++ make cmake pkg-config
          libopenimageio-dev openimageio-tools libopencolorio-dev libopenexr-dev libimath-dev
          libcli11-dev doctest-dev nlohmann-json3-dev libeigen3-dev libceres-dev gnuplot-nox python3 python3-skimage
          clang-format)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "bootstrap: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" = 0 ] || sudo=sudo
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$jobs"

if [ "$mode" = example ]; then
  bash examples/run.sh build/tools/cmfilter out/example
else
  cd build
  ctest --output-on-failure -j"$jobs"
fi
