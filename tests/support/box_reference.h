// SPDX-License-Identifier: Apache-2.0
// Test-only reference for the level geometry of cmfilter's pyramids, straight
// from docs/moments-format.md: texel (x, y) of a w x h level over a W x H
// level 0 is the mean over the level-0 rectangle
// [x W / w, (x+1) W / w) x [y H / h, (y+1) H / h), each level-0 texel
// weighted by the area of it inside, computed by brute force in double.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace cmfilter_test {

struct BoxWeight {
    int i = 0, j = 0;   // level-0 texel
    double weight = 0;  // its share of the output texel's area (the shares sum to 1)
};

inline double box_overlap(double a, double b, int i)
{
    return std::max(0.0, std::min(b, i + 1.0) - std::max(a, double(i)));
}

inline std::vector<BoxWeight> box_weights(int W, int H, int w, int h, int x, int y)
{
    const double x0 = double(x) * W / w, x1 = double(x + 1) * W / w;
    const double y0 = double(y) * H / h, y1 = double(y + 1) * H / h;
    std::vector<BoxWeight> out;
    double area = 0;
    for (int j = int(std::floor(y0)); j < std::min(H, int(std::ceil(y1))); ++j)
        for (int i = int(std::floor(x0)); i < std::min(W, int(std::ceil(x1))); ++i) {
            const double a = box_overlap(x0, x1, i) * box_overlap(y0, y1, j);
            out.push_back({i, j, a});
            area += a;
        }
    for (BoxWeight& b : out) b.weight /= area;
    return out;
}

}  // namespace cmfilter_test
