// SPDX-License-Identifier: Apache-2.0
// One image of a synthesis sample (or a fit relit at one light) as the
// lookups through a coordinate map read it (coordinate_lookup.h).
#pragma once

#include <vector>

namespace cmfilter {

// One image of the sample (or a fit relit at one light), level 0.
struct SampleImage {
    int width = 0, height = 0, channels = 0;
    std::vector<float> pixels;  // width * height * channels, row-major, top row first
    bool periodic = false;      // reads beyond the edge wrap (else clamp)
};

}  // namespace cmfilter
