// SPDX-License-Identifier: Apache-2.0
// Which colour space an image's pixels are in, and their conversion to the
// config's scene_linear role. One rule for every colour image cmfilter reads
// (colour maps, compared images): an explicit name if the caller gives one,
// else the file's own metadata (colorInteropID, else oiio:ColorSpace, with a
// PNG gAMA chunk mapped to the matching power law), else linear for float
// files and sRGB for integer ones.
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/util/error.h"
#include "cmfilter/io/image_reading.h"

#include <string>
#include <vector>

namespace cmfilter {

struct ImageColorSpace {
    std::string colorspace;  // canonical OpenColorIO name the pixels are in
    std::string rule;        // why: the options field, "file metadata", "default for float files", ...
};

// Decides and resolves the colour space of `img`, read from `path`.
// `requested` is the caller's explicit choice (empty: decide from the file);
// `option` is the options field that holds that choice
// ("ColorMapLoadOptions::colorspace"): it is the rule when `requested` is
// used, and the field errors about the file's metadata name.
Expected<ImageColorSpace> decide_image_colorspace(const ImageData& img, const std::string& path,
                                                  const std::string& requested, const std::string& option,
                                                  const ColorConfig& config);

// Converts interleaved RGB floats in place from `space` to scene_linear (data
// colour spaces are left as they are).
Status image_rgb_to_scene_linear(std::vector<float>& rgb, const ImageColorSpace& space, const ColorConfig& config);

}  // namespace cmfilter
