// SPDX-License-Identifier: Apache-2.0
// The colour layers a microsurface's filtering reads (Heitz et al. 2013,
// secs. 5-6): C_h over its heights with its Gaussian table (color_layer.h),
// C_s over its slopes (slope_color_map.h), and how they combine with each
// other and with a base layer C0 (color_combination.h). The base layer is
// filtered as a driver's and comes in as a colour (microsurface_albedo.h).
#pragma once

#include "cmfilter/colormap/slope_color_map.h"
#include "cmfilter/microsurface/color_combination.h"
#include "cmfilter/tables/color_layer.h"

#include <optional>

namespace cmfilter {

struct MicrosurfaceColors {
    std::optional<ColorLayer> height;  // C_h and its table; none: no height map
    std::optional<SlopeMap> slope;     // C_s; none: no slope map
    ColorCombination combine;
};

}  // namespace cmfilter
