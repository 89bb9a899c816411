// SPDX-License-Identifier: Apache-2.0
// An image rendered through a coordinate map, written as every command
// writes images (rgb_image_file.h): EXR keeps any channel count; PNG and
// JPEG take RGB, so one channel is written as grey RGB and a fourth dropped.
#include "command.h"

#include "cmfilter/util/atomic_output.h"

#include <cmath>

namespace cmfilter::cli {

Status write_output_image(const std::string& path, int width, int height, int channels, std::vector<float> values,
                          const std::string& linear_space, const ImageAttributes& attributes, const ColorConfig& config)
{
    for (float& v : values)
        if (!std::isfinite(v)) v = 0;
    if (lowercase_extension(path) != ".exr" && channels != 3) {
        const std::size_t texels = static_cast<std::size_t>(width) * height;
        std::vector<float> rgb(texels * 3);
        for (std::size_t t = 0; t < texels; ++t)
            for (int c = 0; c < 3; ++c) rgb[3 * t + c] = values[t * channels + (channels >= 3 ? c : 0)];
        values.swap(rgb);
        channels = 3;
    }
    return write_rgb_image(path, width, height, channels, values, linear_space, attributes, config);
}

}  // namespace cmfilter::cli
