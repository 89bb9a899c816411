// SPDX-License-Identifier: Apache-2.0
// Loading a slope-vector colour map (slope_color_map.h) from an image, by the
// conventions of color_map_loading.h: the colour space from `colorspace`,
// else the file's own metadata, else linear for float files and sRGB for
// integer ones, converted to scene-linear with OpenColorIO; provenance kept.
// The whole image is the map, laid over [-s_max, s_max]^2 with its top row at
// s_y = +s_max and its left column at s_x = -s_max. (A steepness map is a
// 1-D gradient: load_color_map with vmin = 0 and vmax = 90 degrees.)
#pragma once

#include "cmfilter/colormap/color_map_loading.h"
#include "cmfilter/colormap/slope_color_map.h"

#include <string>

namespace cmfilter {

struct SlopeVectorColorMapLoadOptions {
    std::string path;
    std::string colorspace;  // empty: decided from the file
    double s_max = 1;        // > 0
};

struct LoadedSlopeVectorColorMap {
    SlopeVectorColorMap map;
    ColorMapProvenance provenance;  // selection "whole image"
};

// BadInput for an s_max that is not finite and > 0, a non-finite texel or an
// unknown colour space; Io for an unreadable file.
Expected<LoadedSlopeVectorColorMap> load_slope_vector_color_map(const SlopeVectorColorMapLoadOptions& options,
                                                                const ColorConfig& config);

}  // namespace cmfilter
