// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/microsurface/max_mipmap.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <utility>

namespace cmfilter {

namespace {
// The nearest float at or above x.
float float_at_or_above(double x)
{
    float f = static_cast<float>(x);
    if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
}
}  // namespace

MaxMipmap::MaxMipmap(const double* nodes, int n) : n_(n)
{
    assert(n >= 1 && (n & (n - 1)) == 0);
    const std::size_t stride = static_cast<std::size_t>(n) + 1;
    for (int size = n / 2; size >= 1; size /= 2) {
        std::vector<float> level(static_cast<std::size_t>(size) * size);
        if (levels_.empty()) {
            // Level 1: the 3 x 3 nodes of each block of 2 x 2 texels.
            for (int by = 0; by < size; ++by)
                for (int bx = 0; bx < size; ++bx) {
                    double m = -std::numeric_limits<double>::infinity();
                    for (int j = 2 * by; j <= 2 * by + 2; ++j)
                        for (int i = 2 * bx; i <= 2 * bx + 2; ++i) m = std::max(m, nodes[j * stride + i]);
                    level[static_cast<std::size_t>(by) * size + bx] = float_at_or_above(m);
                }
        } else {
            const std::vector<float>& below = levels_.back();
            const int w = 2 * size;
            for (int by = 0; by < size; ++by)
                for (int bx = 0; bx < size; ++bx) {
                    const std::size_t c = static_cast<std::size_t>(2 * by) * w + 2 * bx;
                    level[static_cast<std::size_t>(by) * size + bx] =
                        std::max({below[c], below[c + 1], below[c + w], below[c + w + 1]});
                }
        }
        levels_.push_back(std::move(level));
    }
}

}  // namespace cmfilter
