// SPDX-License-Identifier: Apache-2.0
// Measures of a synthesised surface against its sample (docs/synthesis.md#quality),
// all from the analysis's texton distances at level 0:
// - coherence: the mean over output texels of the distance from the
//   texel's (2n + 1)^2 output neighbourhood to the nearest sample
//   neighbourhood (brute force over every sample texel; squared texton
//   distance per window texel, averaged, square-rooted), divided by the
//   same root-mean distance between random sample texels: 0 when every
//   output neighbourhood occurs in the sample;
// - coverage: the share of sample texels the output copies at least once,
//   and the share an output of that size copying uniformly would reach
//   (1 - (1 - 1/N)^M), to compare against;
// - seams: the share of adjacent output pairs that are not adjacent in the
//   sample (c(p + e) != c(p) + e), and their contrast: the mean squared
//   distance across those pairs over the mean across adjacent sample pairs
//   (1: a seam looks like the sample's own edges).
// Output neighbourhoods and adjacent pairs wrap when the map is toroidal
// (CoordinateMapInfo::toroidal), else offsets outside the output are
// skipped; sample neighbourhoods and adjacency wrap when the analysis is
// periodic, else they clamp. The random sample pairs are a fixed set (4096,
// from a fixed splitmix64 seed), so every measure is deterministic for any
// thread count. Each also for naive tiling of the sample at the same size,
// the baseline.
#pragma once

#include "cmfilter/synthesis/coordinate_map.h"
#include "cmfilter/synthesis/sample_analysis.h"
#include "cmfilter/util/error.h"

#include <cstdint>

namespace cmfilter {

struct SynthesisQuality {
    double coherence = 0;
    double coverage = 0, uniform_coverage = 0;
    double seam_share = 0, seam_contrast = 0;
};

struct QualityOptions {
    int neighbourhood = 2;  // n of the coherence windows
    // Output texels the coherence measures (0 or more than the output: all):
    // one at a fixed pseudo-random place in each cell of an even grid of
    // about this many cells, so that no tiling period aliases with it.
    int coherence_texels = 4096;
    int threads = 0;
};

// BadInput when the map's level 0 is not into the analysis's level 0 (its
// sample size) or a coordinate lies outside it (naming the texel), or naming
// the field: QualityOptions::neighbourhood < 1 or (2n + 1) above the
// sample's width or height, QualityOptions::coherence_texels < 0.
Expected<SynthesisQuality> measure_synthesis(const CoordinateMap& map, const SampleAnalysis& analysis,
                                             const QualityOptions& options);

// The coordinate map of naive tiling: output texel (x, y) copies sample
// texel (x mod W, y mod H).
CoordinateMap tiled_coordinate_map(int width, int height, int sample_width, int sample_height);

}  // namespace cmfilter
