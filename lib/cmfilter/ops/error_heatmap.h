// SPDX-License-Identifier: Apache-2.0
// Per-pixel colour-error heat maps: an error image drawn through a
// perceptually ordered ramp (luminance rises monotonically) and written as an
// 8-bit sRGB PNG. The ramp runs in sRGB code values over [0, max]:
//   0 -> black (0,0,0), max/3 -> red (255,0,0), 2 max/3 -> yellow (255,255,0),
//   max and above -> white (255,255,255),
// linearly in between: with t = min(e / max, 1), the codes are
// round(255 clamp(3t - k, 0, 1)) for k = 0 (R), 1 (G), 2 (B).
#pragma once

#include "cmfilter/util/error.h"

#include <array>
#include <string>
#include <vector>

namespace cmfilter {

using Rgb8 = std::array<unsigned char, 3>;

// The ramp colour of error `e` on the scale [0, max] (max > 0). Negative
// errors draw as 0; NaN draws as 0 too (callers keep NaN out).
Rgb8 heatmap_color(double e, double max);

struct HeatmapImage {
    int width = 0;
    int height = 0;
    const std::vector<double>* errors = nullptr;  // width * height, row-major, top row first
    double max = 10.0;                            // error drawn as white
    std::string description;                      // stored as the PNG's ImageDescription
};

// Writes the heat map atomically (temporary file, then rename) to `path`, a
// .png file.
Status write_heatmap_png(const std::string& path, const HeatmapImage& image);

}  // namespace cmfilter
