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

// The four texels bilinear interpolation at (s, t) reads and its weights:
// columns x[0], x[1] and rows y[0], y[1] (after the wrap; -1 for a black
// neighbour), and the fractions a along s and b along t. The interpolant is
// lerp(lerp(T(x0, y0), T(x1, y0), a), lerp(T(x0, y1), T(x1, y1), a), b), the
// second texel of a pair read only where its fraction is > 0.
struct BilinearTaps {
    int x[2] = {0, 0}, y[2] = {0, 0};
    double a = 0, b = 0;
};

inline BilinearTaps bilinear_taps(double s, double t, int w, int h, TextureWrap wrap)
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
    BilinearTaps taps;
    taps.a = u - fx;
    taps.b = v - fy;
    for (int i = 0; i < 2; ++i) {
        taps.x[i] = wrap_texel(x0 + i, w, wrap);
        taps.y[i] = wrap_texel(y0 + i, h, wrap);
    }
    return taps;
}

// texel(x, y) returns the Value of texel (x, y), 0 <= x < w, 0 <= y < h;
// Value needs Value + Value, Value - Value and double * Value.
template <typename Value, typename Texel>
Value bilinear_texels(double s, double t, int w, int h, TextureWrap wrap, const Value& outside, const Texel& texel)
{
    const BilinearTaps taps = bilinear_taps(s, t, w, h, wrap);
    const auto at = [&](int i, int j) -> Value {
        return taps.x[i] < 0 || taps.y[j] < 0 ? outside : texel(taps.x[i], taps.y[j]);
    };
    const auto row = [&](int j) -> Value {
        const Value left = at(0, j);
        return taps.a > 0 ? left + taps.a * (at(1, j) - left) : left;
    };
    const Value top = row(0);
    return taps.b > 0 ? top + taps.b * (row(1) - top) : top;
}

}  // namespace cmfilter
