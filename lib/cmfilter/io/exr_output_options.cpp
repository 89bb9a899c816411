// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/io/exr_output_options.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace cmfilter {

namespace {

constexpr const char* kCompressions[] = {"none", "rle", "zips", "zip", "piz", "pxr24", "b44", "b44a", "dwaa", "dwab"};
constexpr int kMaxTile = 4096;
constexpr float kHalfMax = 65504.0f;

}  // namespace

const char* to_string(ExrPixelType type) { return type == ExrPixelType::Half ? "half" : "float"; }

Expected<ExrPixelType> parse_exr_pixel_type(const std::string& text)
{
    if (text == "float") return ExrPixelType::Float;
    if (text == "half") return ExrPixelType::Half;
    return bad_input("pixel type '" + text + "' is unknown (expected half or float)");
}

Status check_exr_output_options(const ExrOutputOptions& options, const std::string& owner)
{
    const std::string& c = options.compression;
    const std::size_t colon = c.find(':');
    const std::string name = c.substr(0, colon);
    bool known = false;
    for (const char* k : kCompressions) known = known || name == k;
    std::string names;
    for (const char* k : kCompressions) names += std::string(names.empty() ? "" : ", ") + k;
    if (!known)
        return bad_input(owner + ".compression '" + c + "' is unknown (expected one of OpenEXR's: " + names + ")",
                         owner + ".compression");
    if (colon != std::string::npos) {
        const std::string level = c.substr(colon + 1);
        char* end = nullptr;
        const long v = std::strtol(level.c_str(), &end, 10);
        const bool zip = name == "zip" || name == "zips", dwa = name == "dwaa" || name == "dwab";
        const bool valid = !level.empty() && end && *end == '\0' &&
                           ((zip && v >= 1 && v <= 9) || (dwa && v >= 1 && v <= 1000));
        if (!valid)
            return bad_input(owner + ".compression '" + c +
                                 "' has an invalid level (expected zip:1..9, zips:1..9, dwaa:1..1000 or dwab:1..1000)",
                             owner + ".compression");
    }
    const bool none = options.tile_width == 0 && options.tile_height == 0;
    const auto side_ok = [](int s) { return s >= 1 && s <= kMaxTile; };
    if (!none && !(side_ok(options.tile_width) && side_ok(options.tile_height))) {
        std::ostringstream msg;
        msg << owner << ".tile " << options.tile_width << " " << options.tile_height
            << " is invalid (expected both sides in 1.." << kMaxTile << ")";
        return bad_input(msg.str(), owner + ".tile");
    }
    return ok();
}

void apply_exr_output_options(OIIO::ImageSpec& spec, const ExrOutputOptions& options)
{
    spec.set_format(options.pixel_type == ExrPixelType::Half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT);
    if (options.tile_width > 0 && options.tile_height > 0) {
        spec.tile_width = options.tile_width;
        spec.tile_height = options.tile_height;
        spec.tile_depth = 1;
    }
    spec.attribute("compression", options.compression);
    for (const auto& [name, value] : options.attributes) spec.attribute(name, value);
}

std::string exr_output_loss(const ExrOutputOptions& options)
{
    // OpenEXR (measured in docs/storage.md): pxr24 rounds float channels to
    // 24 bits and keeps half channels exact; b44 and b44a are lossy on half
    // channels and keep float ones exact; dwaa and dwab are lossy on colour
    // channels (R, G, B, Y) of either type.
    const std::string name = options.compression.substr(0, options.compression.find(':'));
    const bool half = options.pixel_type == ExrPixelType::Half;
    std::string loss = half ? "half" : "";
    const auto add = [&](const std::string& what) { loss += (loss.empty() ? "" : ", ") + what; };
    if (name == "pxr24" && !half) add("pxr24 (24-bit floats)");
    if ((name == "b44" || name == "b44a") && half) add(name);
    if (name == "dwaa" || name == "dwab") add(name + " (on colour channels)");
    return loss;
}

std::string exr_output_text(const ExrOutputOptions& options, const std::string& default_tiles)
{
    const std::string tiles = options.tile_width > 0 ? std::to_string(options.tile_width) + " x " +
                                                           std::to_string(options.tile_height) + " tiles"
                                                     : default_tiles;
    const std::string loss = exr_output_loss(options);
    return std::string(to_string(options.pixel_type)) + ", " + options.compression + ", " + tiles +
           (loss.empty() ? ", lossless" : ", lossy: " + loss);
}

Status check_half_range(const float* values, std::size_t count, const ExrOutputOptions& options,
                        const std::string& path)
{
    if (options.pixel_type != ExrPixelType::Half) return ok();
    for (std::size_t i = 0; i < count; ++i)
        if (!(std::fabs(values[i]) <= kHalfMax)) {
            std::ostringstream msg;
            msg << "'" << path << "': value " << values[i] << " does not fit a half (|v| <= 65504); write float";
            return bad_input(msg.str());
        }
    return ok();
}

}  // namespace cmfilter
