// SPDX-License-Identifier: Apache-2.0
// Baking a colour pyramid (texture/color_pyramid_file.h) through the colour
// map a Gaussian colour table records (tables/table_color_map.h): what
// `bake-moments --method color-pyramid --table T.exr` writes, so that the
// pyramid names the same map that `apply --table T.exr` checks it against.
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/texture/color_pyramid_file.h"
#include "cmfilter/util/error.h"

#include <string>
#include <vector>

namespace cmfilter {

struct TableColorPyramidOptions {
    ColorPyramidBakeOptions bake;  // its map, map_source and linear space are set from the table's
    std::string table_path;        // the Gaussian colour table (bake-colormap)
    std::string map_path;          // overrides the table's cmfilter:source (hash-checked, a warning)
};

struct TableColorPyramid {
    ColorPyramidBakeResult result;
    std::string map_path;               // the colour map read
    std::vector<std::string> warnings;  // for the caller to report
};

// The errors of reading the table and its map (Io naming
// TableColorMapOptions::map_override when the recorded map is gone) and of
// bake_color_pyramid.
Expected<TableColorPyramid> bake_table_color_pyramid(const TableColorPyramidOptions& options,
                                                     const ColorConfig& config);

}  // namespace cmfilter
