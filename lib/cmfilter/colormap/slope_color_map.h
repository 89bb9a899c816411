// SPDX-License-Identifier: Apache-2.0
// Colour maps driven by a heightfield's slope s = grad h = (s_x, s_y) (Heitz
// et al. 2013, sec. 5.2: C_s(n) of eq. 20, the normal n = (-s_x, -s_y, 1) /
// sqrt(1 + |s|^2) and the slope being the same information).
//
// SteepnessColorMap: a 1-D ColorMap (color_map.h) over the slope angle
// atan(|s|) in DEGREES, from 0 (flat) towards 90 (vertical): its driver
// domain [vmin, vmax] is in degrees (0..90 covers every slope), continued
// by its wrap mode beyond. Grass on the flat, rock on the steep. A gradient
// image becomes one through load_color_map (color_map_loading.h) with
// vmin = 0 and vmax = 90.
//
// SlopeVectorColorMap: a width x height image over the slope plane,
// (s_x, s_y) in [-s_max, s_max]^2, row 0 at the top (s_y = +s_max) and
// column 0 at the left (s_x = -s_max), like a plot of the plane: texel (i, j)
// has its centre at s_x = -s_max + (i + 0.5) 2 s_max / width,
// s_y = s_max - (j + 0.5) 2 s_max / height. Bilinear between the texel
// centres (bilinear_texels.h), clamped beyond: outside the centres' square
// the nearest edge texels hold, so every slope steeper than s_max along an
// axis takes the edge colour. A hue wheel over the slope's direction.
//
// Both are plain data: scene-linear texels and an evaluate(s_x, s_y);
// SlopeMap is either (a microsurface material's C_s).
#pragma once

#include "cmfilter/color/color.h"
#include "cmfilter/colormap/color_map.h"
#include "cmfilter/util/error.h"

#include <string>
#include <variant>
#include <vector>

namespace cmfilter {

struct SteepnessColorMap {
    ColorMap by_angle;  // driver: atan(|s|) in degrees

    Rgb evaluate(double sx, double sy) const;
};

struct SlopeVectorColorMap {
    int width = 0, height = 0;
    std::vector<Rgb> texels;  // scene-linear, row-major, row 0 at s_y = +s_max
    double s_max = 1;         // > 0

    Rgb evaluate(double sx, double sy) const;
};

// A slope colour map C_s (sec. 5.2) of either kind.
using SlopeMap = std::variant<SteepnessColorMap, SlopeVectorColorMap>;

// The invariants evaluate relies on (ColorMap's validate for the steepness
// map; at least one texel, width x height of them, all finite, and a finite
// s_max > 0 for the vector map); `what` names the map in messages.
Status validate(const SteepnessColorMap& map, const std::string& what);
Status validate(const SlopeVectorColorMap& map, const std::string& what);

}  // namespace cmfilter
