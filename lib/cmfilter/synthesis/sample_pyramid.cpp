// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/synthesis/sample_pyramid.h"

#include <algorithm>

namespace cmfilter {

int pyramid_level_extent(int extent, int level)
{
    for (int l = 0; l < level; ++l) extent = (extent + 1) / 2;
    return extent;
}

std::vector<float> halve_features(const float* features, int width, int height, int dims)
{
    const int half_width = (width + 1) / 2, half_height = (height + 1) / 2;
    std::vector<float> half(static_cast<std::size_t>(half_width) * half_height * dims);
    std::vector<double> sum(static_cast<std::size_t>(dims));
    for (int y = 0; y < half_height; ++y)
        for (int x = 0; x < half_width; ++x) {
            std::fill(sum.begin(), sum.end(), 0.0);
            for (int dy = 0; dy < 2; ++dy)
                for (int dx = 0; dx < 2; ++dx) {
                    const int sx = std::min(2 * x + dx, width - 1), sy = std::min(2 * y + dy, height - 1);
                    const float* f = features + (static_cast<std::size_t>(sy) * width + sx) * dims;
                    for (int d = 0; d < dims; ++d) sum[static_cast<std::size_t>(d)] += f[d];
                }
            float* out = half.data() + (static_cast<std::size_t>(y) * half_width + x) * dims;
            for (int d = 0; d < dims; ++d) out[d] = static_cast<float>(0.25 * sum[static_cast<std::size_t>(d)]);
        }
    return half;
}

Status check_pyramid_levels(const std::string& what, int width, int height, int levels)
{
    if (width < 2 || height < 2)
        return bad_input(what + " is " + std::to_string(width) + " x " + std::to_string(height) +
                         "; a synthesis sample needs at least 2 x 2 texels");
    if (levels < 1)
        return bad_input("SampleOptions::levels " + std::to_string(levels) + " is invalid: expected >= 1",
                         "SampleOptions::levels");
    const int w = pyramid_level_extent(width, levels - 1), h = pyramid_level_extent(height, levels - 1);
    if (w < 2 || h < 2)
        return bad_input("SampleOptions::levels " + std::to_string(levels) + " is too many for " + what + " (" +
                             std::to_string(width) + " x " + std::to_string(height) +
                             "): its coarsest level would be " + std::to_string(w) + " x " + std::to_string(h) +
                             ", expected at least 2 x 2",
                         "SampleOptions::levels");
    return ok();
}

}  // namespace cmfilter
