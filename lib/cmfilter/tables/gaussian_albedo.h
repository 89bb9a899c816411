// SPDX-License-Identifier: Apache-2.0
// The gaussian method's colour for one filtered footprint (a pixel, or one
// probe of it) with driver mean and standard deviation sigma (sec. 4.2):
// T(mean, sigma), the bilinear lookup of the colour layer's table (eq. 10),
// or, where sigma < layer.plain.below(mean), C0(mean) itself (the small-sigma
// shortcut: there T equals C0 within the shortcut's bound, plain_lookup.h).
#pragma once

#include "cmfilter/color/color.h"
#include "cmfilter/tables/color_layer.h"

#include <cstddef>

namespace cmfilter {

// Footprints coloured, and how many of them took C0(mean) directly.
struct AlbedoCounts {
    std::size_t footprints = 0;
    std::size_t plain = 0;
};

inline Rgb gaussian_albedo(const ColorLayer& layer, double mean, double sigma, AlbedoCounts& counts)
{
    ++counts.footprints;
    if (sigma < layer.plain.below(mean)) {
        ++counts.plain;
        return layer.map.evaluate(mean);
    }
    return layer.table.lookup(mean, sigma);
}

}  // namespace cmfilter
