// SPDX-License-Identifier: Apache-2.0
// Bilinear interpolation over a w x h grid of texels, as OpenImageIO's
// TextureSystem does it inside a level (InterpBilinear): texel (x, y) has its
// centre at s = (x + 0.5) / w, t = (y + 0.5) / h, (0, 0) being the top-left
// corner of the image and t growing downwards; the neighbours of an edge texel
// follow the texture's wrap (texture_wrap.h), black ones reading `outside`.
// Two lerps along s, then one along t, so that a constant grid gives its
// constant exactly.
#pragma once

#include "cmfilter/math/texture_wrap.h"

#include <algorithm>
#include <cmath>

namespace cmfilter {

// texel(x, y) returns the Value of texel (x, y), 0 <= x < w, 0 <= y < h;
// Value needs Value + Value, Value - Value and double * Value.
template <typename Value, typename Texel>
Value bilinear_texels(double s, double t, int w, int h, TextureWrap wrap, const Value& outside, const Texel& texel)
{
    // Far coordinates come near the texture first, where texel indices fit an
    // int: by whole repeats (periodic), else to [-1, 2], beyond which every
    // neighbour reads the same edge texel (clamp) or nothing (black).
    const auto near = [wrap](double x) {
        if (!std::isfinite(x)) return 0.0;
        return wrap == TextureWrap::Periodic ? x - std::floor(x) : std::clamp(x, -1.0, 2.0);
    };
    const double u = near(s) * w - 0.5, v = near(t) * h - 0.5;
    const double fx = std::floor(u), fy = std::floor(v);
    const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
    const double a = u - fx, b = v - fy;
    const auto at = [&](int x, int y) -> Value {
        const int i = wrap_texel(x, w, wrap), j = wrap_texel(y, h, wrap);
        return i < 0 || j < 0 ? outside : texel(i, j);
    };
    const auto row = [&](int y) -> Value {
        const Value left = at(x0, y);
        return a > 0 ? left + a * (at(x0 + 1, y) - left) : left;
    };
    const Value top = row(y0);
    return b > 0 ? top + b * (row(y0 + 1) - top) : top;
}

}  // namespace cmfilter
