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

// The colours C_0 .. C_K a shader weighs the ramp means of the segment
// pyramid at `pyramid_path` by for the map of the table at `table_path`
// (shaders/cmfilter_segments.glsl): the map's at the breakpoints, or for a
// pyramid of least-squares colours (a tolerance bake) the map's least-squares
// colours over the driver weights it records (breakpoint_colors.h), what
// apply --method segments uses. The map is checked as apply checks it.
struct SegmentColors {
    std::vector<double> breakpoints;
    std::vector<Rgb> colors;  // one per breakpoint
    double fit_de = 0;        // the map through them: the largest CIEDE2000
    double mean_fit_de = 0;   // a tolerance bake's: their mean over the driver's values (else 0)
    std::vector<std::string> warnings;
};
Expected<SegmentColors> segment_pyramid_colors(const std::string& pyramid_path, const std::string& table_path,
                                               const ColorConfig& config);

}  // namespace cmfilter
