// SPDX-License-Identifier: Apache-2.0
// Comparing two colour images of the same size: both are brought to the
// config's scene-linear space with OpenColorIO (the same colour-space rules as
// colour maps, lib/cmfilter/io/image_colorspace.h), then measured per pixel.
//   - RMSE over the R, G, B samples of every pixel, in scene-linear values as
//     they are (not clipped), and per channel.
//   - CIEDE2000 (lib/cmfilter/color/ciede2000.h: linear Rec.709 clipped to [0, 1],
//     white Y = 1 -> L* = 100) per pixel, summarised as mean, nearest-rank p95
//     and max (lib/cmfilter/color/error_summary.h), and optionally drawn as a heat
//     map (lib/cmfilter/ops/error_heatmap.h).
// One- and two-channel images are grey (the first channel replicated to RGB);
// of three or more channels the first three are R, G, B and the rest (alpha)
// are ignored. Non-finite texels are an error: they never enter the statistics.
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/util/error.h"
#include "cmfilter/color/error_summary.h"

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace cmfilter {

struct ImageComparisonOptions {
    std::string path_a;
    std::string path_b;
    std::string colorspace_a;  // empty: decided from the file (metadata, else float/integer default)
    std::string colorspace_b;
    std::string heatmap_path;   // empty: no heat map; else a .png to write
    double heatmap_max = 10.0;  // Delta E00 drawn as white; larger errors saturate
    int threads = 0;            // 0: every hardware thread
};

struct ComparedImage {
    std::string path;
    int channels = 0;        // in the file (1-2: grey, >= 3: RGB first, the rest ignored)
    std::string pixel_type;  // as stored ("uint8", "half", "float", ...)
    std::string colorspace;  // canonical OpenColorIO name the pixels were converted from
    std::string
        colorspace_rule;  // "ImageComparisonOptions::colorspace_a", "file metadata", "default for float files", ...
};

struct ImageComparison {
    int width = 0;
    int height = 0;
    std::size_t pixels = 0;     // width * height
    int channels_compared = 3;  // R, G, B
    ComparedImage a, b;
    std::string linear_space;          // the config's scene_linear colour space
    std::string ocio_config;           // "built-in" or a path
    double rmse = 0;                   // over all R, G, B samples, scene-linear
    std::array<double, 3> rmse_rgb{};  // per channel
    ErrorSummary de2000;               // per-pixel CIEDE2000
    std::string heatmap_path;          // written, or empty
    double heatmap_max = 0;            // its scale (Delta E00 drawn as white)
};

Expected<ImageComparison> compare_images(const ImageComparisonOptions& options, const ColorConfig& config);

// What compare_images measures, of two scene-linear RGB images already in
// memory: width x height pixels each, R, G, B interleaved, top row first.
// Squared differences are summed per row in double, then across rows in row
// order, so the result does not depend on the thread count.
struct RgbDifference {
    double rmse = 0;                   // over all R, G, B samples
    std::array<double, 3> rmse_rgb{};  // per channel
    std::vector<double> de2000;        // per pixel, CIEDE2000
};
RgbDifference measure_rgb_difference(const float* a, const float* b, int width, int height, int threads);

}  // namespace cmfilter
