// SPDX-License-Identifier: Apache-2.0
// The pyramid of one sample image that level-of-detail lookups read
// (coordinate_lookup.h): level l + 1 halves level l with a 2 x 2 box, an odd
// edge repeating its last texel, as the synthesis sample's pyramid is built
// (synthesis_sample.h; Bosserhoff & Nicoll sec. 4.2, figure 4), so that a
// hierarchical level's coordinates index the same texels. Level l's texel
// (i, j) covers level 0's [i 2^l, (i + 1) 2^l) x [j 2^l, (j + 1) 2^l).
#pragma once

#include "cmfilter/synthesis/sample_image.h"

#include <vector>

namespace cmfilter {

// Levels 0 .. until 1 x 1, or `max_levels` of them when > 0 (level 0 a copy
// of `image`).
std::vector<SampleImage> sample_image_pyramid(const SampleImage& image, int max_levels = 0);

}  // namespace cmfilter
