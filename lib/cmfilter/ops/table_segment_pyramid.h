// SPDX-License-Identifier: Apache-2.0
// Baking a segment pyramid (texture/segment_pyramid_file.h) for the
// breakpoints of the colour maps that one or several Gaussian colour tables
// record (tables/table_color_map.h): what `bake-moments --segments
// T.exr[,T2.exr,...]` writes, so that `apply --table T3.exr --method segments`
// later checks T3's map against the same breakpoints.
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/texture/segment_pyramid_file.h"
#include "cmfilter/util/error.h"

#include <string>
#include <vector>

namespace cmfilter {

struct TableSegmentPyramidOptions {
    SegmentPyramidBakeOptions bake;        // its maps and map_sources are set from the tables'
    std::vector<std::string> table_paths;  // at least one
};

struct TableSegmentPyramid {
    SegmentPyramidBakeResult result;
    std::vector<std::string> map_paths;  // the colour maps read, one per table
    std::vector<std::string> warnings;   // for the caller to report
};

// BadInput naming TableSegmentPyramidOptions::table_paths when none is
// given; the errors of reading each table and its map, and of
// bake_segment_pyramid.
Expected<TableSegmentPyramid> bake_table_segment_pyramid(const TableSegmentPyramidOptions& options,
                                                         const ColorConfig& config);

}  // namespace cmfilter
