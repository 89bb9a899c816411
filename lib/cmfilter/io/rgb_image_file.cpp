// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/io/rgb_image_file.h"

#include "cmfilter/io/linear_space_attributes.h"
#include "cmfilter/io/output_date.h"
#include "cmfilter/util/atomic_output.h"
#include "cmfilter/io/metadata.h"

#include <OpenImageIO/imageio.h>

#include <cmath>

namespace cmfilter {

Status check_rgb_image_output(const std::string& path, bool exr_only)
{
    const std::string ext = lowercase_extension(path);
    if (exr_only && ext != ".exr") return bad_input("output '" + path + "' has the wrong extension (expected .exr)");
    if (ext != ".exr" && ext != ".png" && ext != ".jpg" && ext != ".jpeg")
        return bad_input("output '" + path + "' has the wrong extension (expected .exr, .png, .jpg or .jpeg)");
    return check_output_path(path, "");
}

Status write_rgb_image(const std::string& path, int width, int height, int channels, const std::vector<float>& pixels,
                       const std::string& linear_space, const ImageAttributes& attributes, const ColorConfig& config,
                       const FramePlacement& window)
{
    if (auto st = check_rgb_image_output(path); !st) return st;
    const bool exr = lowercase_extension(path) == ".exr";
    if (!exr && channels != 3)
        return bad_input("output '" + path + "': PNG and JPEG need 3 channels, got " + std::to_string(channels));
    if (pixels.size() !=
        static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * static_cast<std::size_t>(channels))
        return runtime_error("image for '" + path + "' has " + std::to_string(pixels.size()) + " values, expected " +
                             std::to_string(static_cast<long long>(width) * height * channels));
    const bool framed = window.full_width > 0 &&
                        !(window.x == 0 && window.y == 0 && window.full_width == width && window.full_height == height);
    if (framed && !exr)
        return bad_input("output '" + path + "': a region of a larger frame needs OpenEXR (.exr), whose data window " +
                         "places it in the frame; PNG and JPEG hold whole images only");
    if (framed && (window.x < 0 || window.y < 0 || window.x + width > window.full_width ||
                   window.y + height > window.full_height))
        return runtime_error("image for '" + path + "': " + std::to_string(width) + " x " + std::to_string(height) +
                             " pixels at " + std::to_string(window.x) + "," + std::to_string(window.y) +
                             " do not lie in the " + std::to_string(window.full_width) + " x " +
                             std::to_string(window.full_height) + " frame");
    OIIO::ImageSpec spec(width, height, channels, exr ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    if (framed) {
        spec.x = window.x;
        spec.y = window.y;
        spec.full_x = 0;
        spec.full_y = 0;
        spec.full_width = window.full_width;
        spec.full_height = window.full_height;
    }
    if (channels == 1) spec.channelnames = {"Y"};
    for (const auto& [key, value] : attributes.text) spec.attribute(key, value);
    for (const auto& [key, value] : attributes.numbers) set_double_attribute(spec, key.c_str(), value);

    std::vector<unsigned char> codes;
    if (exr) {
        spec.attribute("compression", "zip");
        set_linear_space_attributes(spec, linear_space, config.interop_id(linear_space));
    } else {
        // Scene-linear -> sRGB encoding through OpenColorIO, then 8-bit codes.
        auto srgb = config.srgb_texture_name();
        if (!srgb) return srgb.error();
        std::vector<float> encoded = pixels;
        if (auto st = config.from_scene_linear(encoded, *srgb); !st) return st;
        codes.resize(encoded.size());
        for (std::size_t i = 0; i < encoded.size(); ++i) {
            float v = encoded[i];
            if (!(v > 0.0f)) v = 0.0f;  // also NaN
            if (v > 1.0f) v = 1.0f;
            codes[i] = static_cast<unsigned char>(std::lround(255.0f * v));
        }
        spec.attribute("oiio:ColorSpace", "sRGB");
        spec.attribute("cmfilter:encoding", *srgb);
    }

    auto out = AtomicOutput::begin(path);
    if (!out) return out.error();
    auto writer = OIIO::ImageOutput::create(out->temp_path());
    if (!writer) return runtime_error("OpenImageIO cannot write '" + path + "': " + OIIO::geterror());
    if (auto st = set_output_date(spec, *writer); !st) return st;
    if (!writer->open(out->temp_path(), spec) ||
        !(exr ? writer->write_image(OIIO::TypeDesc::FLOAT, pixels.data())
              : writer->write_image(OIIO::TypeDesc::UINT8, codes.data())) ||
        !writer->close())
        return out->write_error(writer->geterror());
    return out->commit();
}

}  // namespace cmfilter
