// SPDX-License-Identifier: Apache-2.0
// k-coherence synthesis (Tong et al. 2002; Bosserhoff & Nicoll sec. 4.2)
// in scan-line order from a sample analysis, one level or hierarchically
// (figure 4). Each output texel takes, among the candidates, the sample
// texel whose neighbourhood is nearest its synthesised neighbourhood, by
// texton distances (sample_analysis.h). Candidates (figure 3): for each
// neighbour p_i already synthesised at offset o_i, the sample texel
// s(p_i) - o_i (k = 1, Ashikhmin 2001) and its k - 1 most similar texels.
// On a sample that does not tile, a copy that would leave it ends (no
// candidate); with no candidate a fresh copy starts at a random texel. On a
// tie the earlier candidate wins: continuing copies, nearest neighbour
// first, before their similar texels.
// The first pass sees the causal half of the (2n + 1)^2 window (the rows
// above, the texels to the left) plus any texel seeded from the coarser
// level; each seeded texel is then synthesised again with its whole window.
// A toroidal output wraps its neighbourhoods and tiles seamlessly: it starts
// from random texels and resynthesises, with whole windows, the first n rows
// and columns, whose first pass saw them. Random choices come from a hash of
// (seed, level, texel), so the result is the same for any thread count.
#pragma once

#include "cmfilter/synthesis/coordinate_map.h"
#include "cmfilter/synthesis/sample_analysis.h"
#include "cmfilter/util/error.h"

#include <cstdint>

namespace cmfilter {

// The largest output side synthesised (documented in docs/synthesis.md).
constexpr int kMaxSynthesisSize = 16384;

struct SynthesisOptions {
    int width = 256, height = 256;  // 1 .. kMaxSynthesisSize
    int k = 3;              // 1 .. m + 1: the texel itself and its k - 1 most similar (m: the analysis.s candidates)
    int neighbourhood = 2;  // n: (2n + 1)^2 window, 1 .. what the coarsest level used allows
    int levels = 1;         // 1 .. the analysis's levels; the finest `levels` are used
    bool toroidal = false;
    std::uint64_t seed = 1;
    int threads = 0;  // used for whole-level passes that do not depend on order
};

// BadInput naming the field and value: SynthesisOptions::width/height < 1
// or > kMaxSynthesisSize, k < 1 or > the candidates, neighbourhood < 1 or
// (2n + 1) above the coarsest level's width or height used, levels < 1 or
// more than the analysis holds, an output level smaller than 1 x 1.
Expected<CoordinateMap> synthesise(const SampleAnalysis& analysis, const SynthesisOptions& options);

}  // namespace cmfilter
