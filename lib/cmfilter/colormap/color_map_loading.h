// SPDX-License-Identifier: Apache-2.0
// Loading a colour map from an image: pick the gradient (a W x 1 or 1 x H
// image, or one row or column of a larger one), decide its colour space
// (--colorspace, else the file's own metadata, else linear for float files and
// sRGB for integer ones), convert it to scene-linear with OpenColorIO, and lay
// it over the driver domain as a ColorMap. Provenance is kept for metadata.
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/colormap/color_map.h"
#include "cmfilter/util/error.h"
#include "cmfilter/io/image_colorspace.h"
#include "cmfilter/io/image_reading.h"

#include <optional>
#include <string>
#include <vector>

namespace cmfilter {

struct ColorMapLoadOptions {
    std::string path;
    std::optional<int> row;     // which row of a taller image
    std::optional<int> column;  // or which column (a vertical gradient)
    std::string colorspace;     // empty: decided from the file
    double vmin = 0.0;
    double vmax = 1.0;
    WrapMode wrap = WrapMode::Clamp;
};

struct ColorMapProvenance {
    std::string path;
    std::string sha256;  // of the file's bytes
    int image_width = 0;
    int image_height = 0;
    std::string selection;   // "row 0", "column 3"
    std::string colorspace;  // canonical OCIO name the texels were converted from
    std::string
        colorspace_rule;       // "ColorMapLoadOptions::colorspace", "file metadata", "default for integer files", ...
    std::string linear_space;  // the config's scene_linear colour space
    std::string linear_interop_id;  // its colour interop ID ("lin_ap1_scene"), or empty (ColorConfig::interop_id)
    std::string ocio_config;        // "built-in" or a path
};

struct LoadedColorMap {
    ColorMap map;
    ColorMapProvenance provenance;
};

// Shared by the map loaders (slope_color_map_loading.h too):
// `count` texels of `img` (within img.window) from (start_x, start_y) in steps of (step_x,
// step_y) as interleaved RGB (grey replicated), BadInput for a non-finite
// one;
Expected<std::vector<float>> image_rgb_texels(const ImageData& img, const std::string& path, int start_x, int start_y,
                                              int step_x, int step_y, int count);
// and the provenance of a map read from `img` at `path` (hashing the file).
Expected<ColorMapProvenance> image_map_provenance(const std::string& path, const ImageData& img,
                                                  const std::string& selection, const ImageColorSpace& space,
                                                  const ColorConfig& config);

Expected<LoadedColorMap> load_color_map(const ColorMapLoadOptions& options, const ColorConfig& config);

}  // namespace cmfilter
