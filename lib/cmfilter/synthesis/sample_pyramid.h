// SPDX-License-Identifier: Apache-2.0
// The pyramid of a synthesis sample (sec. 4.2, hierarchical synthesis:
// "each layer has half the resolution of the previous layer"): level l + 1
// is level l under a 2 x 2 box, an odd edge repeating its last texel, so a
// w x h level has a ceil(w / 2) x ceil(h / 2) parent.
#pragma once

#include "cmfilter/util/error.h"

#include <string>
#include <vector>

namespace cmfilter {

// The size of level `level` of a width x height sample.
int pyramid_level_extent(int extent, int level);

// The 2 x 2 box of a width x height level of `dims` values per texel
// (row-major, top row first): pyramid_level_extent(width, 1) x
// pyramid_level_extent(height, 1) texels.
std::vector<float> halve_features(const float* features, int width, int height, int dims);

// BadInput when a width x height sample (named by `what`) is smaller than
// 2 x 2, or when `levels` (SampleOptions::levels) is < 1 or leaves the
// coarsest level smaller than 2 x 2 (naming its size).
Status check_pyramid_levels(const std::string& what, int width, int height, int levels);

}  // namespace cmfilter
