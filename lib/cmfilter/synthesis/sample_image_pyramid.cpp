// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/synthesis/sample_image_pyramid.h"

#include <algorithm>
#include <cstddef>

namespace cmfilter {

namespace {

SampleImage halved(const SampleImage& fine)
{
    SampleImage coarse;
    coarse.width = (fine.width + 1) / 2;
    coarse.height = (fine.height + 1) / 2;
    coarse.channels = fine.channels;
    coarse.periodic = fine.periodic;
    coarse.pixels.resize(static_cast<std::size_t>(coarse.width) * coarse.height * coarse.channels);
    const int c = fine.channels;
    const auto at = [&](int x, int y, int k) {
        return static_cast<double>(fine.pixels[(static_cast<std::size_t>(y) * fine.width + x) * c + k]);
    };
    for (int j = 0; j < coarse.height; ++j) {
        const int y0 = 2 * j, y1 = std::min(2 * j + 1, fine.height - 1);
        for (int i = 0; i < coarse.width; ++i) {
            const int x0 = 2 * i, x1 = std::min(2 * i + 1, fine.width - 1);
            for (int k = 0; k < c; ++k) {
                const double sum = at(x0, y0, k) + at(x1, y0, k) + at(x0, y1, k) + at(x1, y1, k);
                coarse.pixels[(static_cast<std::size_t>(j) * coarse.width + i) * c + k] = static_cast<float>(sum / 4);
            }
        }
    }
    return coarse;
}

}  // namespace

std::vector<SampleImage> sample_image_pyramid(const SampleImage& image, int max_levels)
{
    std::vector<SampleImage> levels{image};
    while ((max_levels <= 0 || static_cast<int>(levels.size()) < max_levels) &&
           (levels.back().width > 1 || levels.back().height > 1))
        levels.push_back(halved(levels.back()));
    return levels;
}

}  // namespace cmfilter
