// SPDX-License-Identifier: Apache-2.0
// Writing a filtered image (filtered_image.h): OpenEXR holds the float RGB
// values as they are, in scene-linear, with how they were made as cmfilter:*
// metadata; PNG and JPEG hold 8-bit sRGB display codes, converted from
// scene-linear with OpenColorIO (the config's sRGB encoding), clipped to
// [0, 1] (never NaN). Written atomically.
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/util/error.h"
#include "cmfilter/ops/filtered_image.h"

#include <string>

namespace cmfilter {

inline constexpr const char* kFilteredImageKind = "filtered-image";

// Checks, before any work, that `path` can be written (its directory exists)
// and ends in .exr, .png, .jpg or .jpeg.
Status check_filtered_image_output(const std::string& path);

Status write_filtered_image(const std::string& path, const FilteredImage& image, const ColorConfig& config);

}  // namespace cmfilter
