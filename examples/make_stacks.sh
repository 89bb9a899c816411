#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The bundled synthetic stacks (cmfilter make-stack, docs/stacks.md), each in
# a second or two:
#   near-diffuse/stack.lp   a gentle Gaussian microsurface coloured by height
#                           (sand-snow), Lambertian facets, Fibonacci 64
#                           lights, 64 x 64;
#   shiny/stack.lp          a strong relief (slope sigma about 0.8) coloured by
#                           height and slope, a GGX coat (F0 0.04, alpha
#                           0.15), hard shadows, Fibonacci 64 lights, 64 x 64,
#                           with its albedo;
#   shiny-held/stack.lp     the shiny surface's ground truth at 16 held-out
#                           lights (a regular dome from 20 degrees up), from
#                           its record;
#   stage/stack.lp          the near-diffuse surface under the uneven
#                           stage:64 dome (half the lights on a low +x arc);
#   multiview/btf.json      the snake's scales (a textured displacement) from
#                           7 views (the zenith and six at 60 degrees) x 40
#                           lights, 48 x 48: a BTF for texture synthesis.
#   bash examples/make_stacks.sh CMFILTER_BINARY OUTPUT_DIR
set -euo pipefail
cmfilter=${1:?usage: make_stacks.sh CMFILTER_BINARY OUTPUT_DIR}
out=${2:?usage: make_stacks.sh CMFILTER_BINARY OUTPUT_DIR}
scenes=$(cd "$(dirname "$0")" && pwd)/scenes
mkdir -p "$out/near-diffuse" "$out/shiny" "$out/shiny-held" "$out/stage" "$out/multiview"
TIMEFORMAT='  %R s wall'
time "$cmfilter" make-stack "$scenes/stack-near-diffuse.json" -o "$out/near-diffuse/stack.lp" \
  --size 64 --spp 16 --dome fibonacci:64
time "$cmfilter" make-stack "$scenes/stack-shiny-shadows.json" -o "$out/shiny/stack.lp" \
  --size 64 --spp 16 --dome fibonacci:64 --specular ggx:ks=0.04,alpha=0.15 --albedo
time "$cmfilter" make-stack --from "$out/shiny/stack.json" -o "$out/shiny-held/stack.lp" \
  --dome regular:16 --min-elevation 20
time "$cmfilter" make-stack "$scenes/stack-near-diffuse.json" -o "$out/stage/stack.lp" \
  --size 64 --spp 16 --dome stage:64
time "$cmfilter" make-stack "$scenes/stack-multiview.json" -o "$out/multiview/btf.json" \
  --size 48 --spp 9 --dome fibonacci:40 \
  --view 0,0,1 --view 0.5,0,0.866 --view -0.5,0,0.866 --view 0.25,0.433,0.866 \
  --view -0.25,0.433,0.866 --view 0.25,-0.433,0.866 --view -0.25,-0.433,0.866
