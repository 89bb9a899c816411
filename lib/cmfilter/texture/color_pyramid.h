// SPDX-License-Identifier: Apache-2.0
// The ground truth for a box footprint (the `reference` method of `apply`):
// the colour-mapped driver C0(f) per level-0 texel, in double, box-mipped with
// the level geometry of the moment pyramid (box_pyramid.h,
// docs/moments-format.md), so that each level-k texel is the exact mean of
// C0(f) over the same footprint whose mean and variance of f the moment
// pyramid stores: mean C0(f), which the paper's filtering aims at (sec. 3,
// eq. 1 with a box kernel), not C0(mean f).
//
// Lookups mirror MomentTexture::lookup, i.e. OpenImageIO's TextureSystem with
// bilinear interpolation and trilinear blending: texel x of level k has its
// centre at s = (x + 0.5) / w_k; integer lod reads level lod alone, fractional
// lod blends levels floor(lod) and floor(lod) + 1 linearly in lod; texels
// beyond the edge follow the moment pyramid's wrap (black, whose moments
// m1 = m2 = 0 are a point mass at f = c, reads C0(c) here).
#pragma once

#include "cmfilter/color/color.h"
#include "cmfilter/colormap/color_map.h"
#include "cmfilter/math/texture_wrap.h"

#include <vector>

namespace cmfilter {

struct ColorPyramidOptions {
    const std::vector<float>* driver = nullptr;  // W * H values, row-major, top row first
    int width = 0, height = 0;
    const ColorMap* map = nullptr;
    TextureWrap wrap = TextureWrap::Clamp;
    double reference = 0;  // c: what a black border stands for
    int threads = 0;
};

class ColorPyramid {
public:
    static ColorPyramid build(const ColorPyramidOptions& options);

    int levels() const { return static_cast<int>(levels_.size()); }
    int level_width(int k) const { return levels_[k].w; }
    int level_height(int k) const { return levels_[k].h; }
    // Texel (x, y) of level k, with the wrap applied to indices outside.
    Rgb texel(int k, int x, int y) const;
    // Bilinear within levels, linear in lod between them; lod must lie in
    // [0, levels() - 1].
    Rgb lookup(double s, double t, double lod) const;

private:
    struct Level {
        int w = 0, h = 0;
        std::vector<float> rgb;
    };
    Rgb stored(int k, int x, int y) const;  // inside the level
    Rgb bilinear(int k, double s, double t) const;
    std::vector<Level> levels_;
    TextureWrap wrap_ = TextureWrap::Clamp;
    Rgb outside_;
};

}  // namespace cmfilter
