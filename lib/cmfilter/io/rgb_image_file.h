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

// Where an image's pixels lie in a larger frame: width x height pixels from
// column x, row y of a full_width x full_height frame (OpenEXR's data window
// inside its display window; OpenImageIO's x, y, full_width, full_height).
// full_width 0: the image is the whole frame.
struct FramePlacement {
    int x = 0, y = 0;
    int full_width = 0, full_height = 0;
};

// `pixels` holds width * height * channels floats, top row first. PNG/JPEG
// need 3 channels. `linear_space` names the colour space of the floats in
// the EXR (empty for data such as AOVs). `window`: the frame the pixels lie
// in, written as the EXR's display window (its data window the pixels'
// own); BadInput for PNG/JPEG, which hold no data window, unless the image
// is the whole frame; Runtime for a frame that does not hold the image.
Status write_rgb_image(const std::string& path, int width, int height, int channels, const std::vector<float>& pixels,
                       const std::string& linear_space, const ImageAttributes& attributes, const ColorConfig& config,
                       const FramePlacement& window = {});

}  // namespace cmfilter
