#include "cmfilter/color_pyramid.h"

#include "cmfilter/box_pyramid.h"

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

Rgb ColorPyramid::texel(int k, int x, int y) const
{
    const Level& L = levels_[k];
    const auto wrap = [&](int i, int n, bool& inside) {
        if (i >= 0 && i < n) return i;
        if (wrap_ == TextureWrap::Periodic) return ((i % n) + n) % n;
        if (wrap_ == TextureWrap::Black) inside = false;
        return i < 0 ? 0 : n - 1;
    };
    bool inside = true;
    x = wrap(x, L.w, inside);
    y = wrap(y, L.h, inside);
    if (!inside) return outside_;
    const float* p = L.rgb.data() + (static_cast<std::size_t>(y) * L.w + x) * 3;
    return {p[0], p[1], p[2]};
}

Rgb ColorPyramid::bilinear(int k, double s, double t) const
{
    const Level& L = levels_[k];
    // Texel centres at (x + 0.5) / w: continuous texel coordinates.
    const double u = s * L.w - 0.5, v = t * L.h - 0.5;
    const double fx = std::floor(u), fy = std::floor(v);
    const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
    const double a = u - fx, b = v - fy;
    Rgb out = ((1 - a) * (1 - b)) * texel(k, x0, y0);
    if (a > 0) out += (a * (1 - b)) * texel(k, x0 + 1, y0);
    if (b > 0) out += ((1 - a) * b) * texel(k, x0, y0 + 1);
    if (a > 0 && b > 0) out += (a * b) * texel(k, x0 + 1, y0 + 1);
    return out;
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
