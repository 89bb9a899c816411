// SPDX-License-Identifier: Apache-2.0
// The continuous colour map C0 of the paper (section 4): the piecewise-linear
// interpolant through the texel centres of a scene-linear RGB gradient, laid
// over the driver domain [vmin, vmax] and continued outside it by a WrapMode.
//
// Texel i (0-based, n texels) sits at v_i = vmin + (i + 0.5) h, h = (vmax - vmin) / n.
// The node grid continues over the whole real line: node k stands for texel
// wrap_texel_index(k, n, wrap), so clamp holds the end colours, repeat is
// periodic and mirror reflects.
#pragma once

#include "cmfilter/color/color.h"
#include "cmfilter/util/error.h"
#include "cmfilter/math/wrap_mode.h"

#include <string>
#include <vector>

namespace cmfilter {

struct ColorMap {
    std::vector<Rgb> texels;  // scene-linear
    double vmin = 0.0;
    double vmax = 1.0;
    WrapMode wrap = WrapMode::Clamp;

    long size() const { return static_cast<long>(texels.size()); }
    double texel_width() const { return (vmax - vmin) / static_cast<double>(texels.size()); }
    // Driver value -> continuous node coordinate (node k at coordinate k).
    double node_coordinate(double v) const { return (v - vmin) / texel_width() - 0.5; }
    const Rgb& node(long k) const { return texels[wrap_texel_index(k, size(), wrap)]; }

    // C0(v): linear interpolation between the two nodes around v.
    Rgb evaluate(double v) const;
};

// Checks the invariants every consumer relies on: at least one texel, finite
// texels, finite vmin < vmax. `what` names the map in messages.
Status validate(const ColorMap& map, const std::string& what);

}  // namespace cmfilter
