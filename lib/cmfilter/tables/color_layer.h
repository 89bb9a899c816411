// SPDX-License-Identifier: Apache-2.0
// One colour layer of a material: a colour map over the values that drive it
// (C0 over a driver's values, or C_h over a microsurface's heights), its
// Gaussian table T(mean, sigma) (eq. 10), the small-sigma shortcut that takes
// the map itself where the table would equal it (plain_lookup.h), and the
// record of how the table was chosen (table_fit.h). gaussian_albedo.h colours
// a filtered footprint with it.
#pragma once

#include "cmfilter/colormap/color_map.h"
#include "cmfilter/tables/gaussian_color_table.h"
#include "cmfilter/tables/plain_lookup.h"
#include "cmfilter/tables/table_fit.h"

namespace cmfilter {

struct ColorLayer {
    ColorMap map;              // scene-linear
    GaussianColorTable table;  // T(mean, sigma)
    // The gaussian method takes map(mean) itself where sigma <
    // plain.below(mean); empty: never.
    PlainLookupSigma plain;
    TableFit fit;  // how the table was chosen (tolerance_tables.h)
};

}  // namespace cmfilter
