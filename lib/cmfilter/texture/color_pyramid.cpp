// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/texture/color_pyramid.h"

#include "cmfilter/math/bilinear_texels.h"
#include "cmfilter/texture/box_pyramid.h"

#include <cmath>

namespace cmfilter {

ColorPyramid ColorPyramid::build(const ColorPyramidOptions& options)
{
    const int W = options.width, H = options.height;
    const std::vector<float>& f = *options.driver;
    const ColorMap& map = *options.map;
    ColorPyramid out;
    out.wrap_ = options.wrap;
    out.outside_ = map.evaluate(options.reference);
    Level level0{W, H, std::vector<float>(static_cast<std::size_t>(W) * H * 3)};

    // C0(f) per level-0 texel in double: level 0 (as float), and the three
    // channel planes every upper level is box-averaged from.
    BoxPyramidAccumulator upper(W, H, 3, options.threads);
    upper.add_rows(0, H, [&](int y, int, double* planes) {
        for (int x = 0; x < W; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * W + x;
            const Rgb c = map.evaluate(f[i]);
            for (int ch = 0; ch < 3; ++ch) {
                planes[static_cast<std::size_t>(ch) * W + x] = c[ch];
                level0.rgb[3 * i + ch] = static_cast<float>(c[ch]);
            }
        }
    });
    out.levels_.push_back(std::move(level0));
    for (int k = 1; k < upper.levels(); ++k)
        out.levels_.push_back({upper.level_width(k), upper.level_height(k), upper.take_level(k)});
    return out;
}

Rgb ColorPyramid::stored(int k, int x, int y) const
{
    const Level& L = levels_[k];
    const float* p = L.rgb.data() + (static_cast<std::size_t>(y) * L.w + x) * 3;
    return {p[0], p[1], p[2]};
}

Rgb ColorPyramid::texel(int k, int x, int y) const
{
    const Level& L = levels_[k];
    x = wrap_texel(x, L.w, wrap_);
    y = wrap_texel(y, L.h, wrap_);
    return x < 0 || y < 0 ? outside_ : stored(k, x, y);
}

Rgb ColorPyramid::bilinear(int k, double s, double t) const
{
    const Level& L = levels_[k];
    return bilinear_texels(s, t, L.w, L.h, wrap_, outside_, [&](int x, int y) { return stored(k, x, y); });
}

Rgb ColorPyramid::lookup(double s, double t, double lod) const
{
    const int k = static_cast<int>(std::floor(lod));
    const double frac = lod - k;
    const Rgb lo = bilinear(k, s, t);
    if (frac <= 0 || k + 1 >= levels()) return lo;
    // Linear in lod, as the moments are blended before they are mapped.
    return (1 - frac) * lo + frac * bilinear(k + 1, s, t);
}

}  // namespace cmfilter
