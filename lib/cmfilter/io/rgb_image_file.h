// SPDX-License-Identifier: Apache-2.0
// Writing a float image to disk, the one way every command does it: OpenEXR
// keeps the scene-linear floats (any channel count) with cmfilter:* metadata;
// PNG and JPEG (3 channels) hold 8-bit sRGB display codes, converted from
// scene-linear with OpenColorIO (the config's sRGB encoding), clipped to
// [0, 1], NaN as 0. Written atomically (atomic_output.h).
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/util/error.h"

#include <string>
#include <utility>
#include <vector>

namespace cmfilter {

struct ImageAttributes {
    std::vector<std::pair<std::string, std::string>> text;
    std::vector<std::pair<std::string, double>> numbers;  // stored as text, shortest round-trip
};

// BadInput unless `path` ends in .exr, .png, .jpg or .jpeg (.exr only when
// `exr_only`) and its folder exists.
Status check_rgb_image_output(const std::string& path, bool exr_only = false);

// `pixels` holds width * height * channels floats, top row first. PNG/JPEG
// need 3 channels. `linear_space` names the colour space of the floats in
// the EXR (empty for data such as AOVs).
Status write_rgb_image(const std::string& path, int width, int height, int channels, const std::vector<float>& pixels,
                       const std::string& linear_space, const ImageAttributes& attributes, const ColorConfig& config);

}  // namespace cmfilter
