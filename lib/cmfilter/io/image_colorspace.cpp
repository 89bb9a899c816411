// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/io/image_colorspace.h"

#include <cmath>
#include <sstream>

namespace cmfilter {

namespace {

// OpenImageIO's word for "linear" with no primaries: what its OpenEXR and
// HDR readers report for every file.
bool is_generic_linear(const std::string& name) { return name == "Linear" || name == "linear"; }

// The colour space as named (before resolution) and the rule that chose it,
// in this order: the caller's name; a PNG gAMA chunk; what the file declares
// (colorInteropID, cmfilter:linear_space); the config's file rules, when a
// rule other than Default matches; what OpenImageIO reports (oiio:ColorSpace,
// its "Linear" read as the scene_linear role); the config's defaults.
Expected<ImageColorSpace> choose(const ImageData& img, const std::string& path, const std::string& requested,
                                 const std::string& option, const ColorConfig& config)
{
    if (!requested.empty()) return ImageColorSpace{requested, option};
    if (img.oiio_colorspace == "GammaCorrected") {
        // OpenImageIO reports a PNG gAMA chunk (and similar) as a pure power law.
        const float g = img.gamma_attr;
        if (std::fabs(g - 2.2f) < 0.01f) return ImageColorSpace{"Gamma 2.2", "file metadata (gamma 2.2)"};
        if (std::fabs(g - 1.8f) < 0.01f) return ImageColorSpace{"Gamma 1.8", "file metadata (gamma 1.8)"};
        if (std::fabs(g - 1.0f) < 0.01f) return ImageColorSpace{"scene_linear", "file metadata (gamma 1.0)"};
        std::ostringstream msg;
        msg << "'" << path << "' declares gamma " << g << ", which no colour space of the config matches; pass "
            << option << " NAME";
        return bad_input(msg.str(), option);
    }
    if (!img.colorspace_attr.empty()) return ImageColorSpace{img.colorspace_attr, "file metadata"};
    if (std::string ruled = config.file_rule_space(path); !ruled.empty())
        return ImageColorSpace{ruled, "the config's file rules"};
    if (is_generic_linear(img.oiio_colorspace))
        return ImageColorSpace{"scene_linear", "file metadata (linear: the scene_linear role)"};
    if (!img.oiio_colorspace.empty()) return ImageColorSpace{img.oiio_colorspace, "file metadata"};
    if (img.is_float) return ImageColorSpace{"scene_linear", "default for float files"};
    auto srgb = config.srgb_texture_name();
    if (srgb) return ImageColorSpace{*srgb, "default for integer files"};
    if (std::string fallback = config.role_space("default"); !fallback.empty())
        return ImageColorSpace{fallback, "default for integer files (the default role)"};
    return srgb.error();
}

}  // namespace

Expected<ImageColorSpace> decide_image_colorspace(const ImageData& img, const std::string& path,
                                                  const std::string& requested, const std::string& option,
                                                  const ColorConfig& config)
{
    auto choice = choose(img, path, requested, option, config);
    if (!choice) return choice.error();
    auto canonical = config.resolve(choice->colorspace);
    if (!canonical) {
        if (choice->rule == "file metadata")
            return bad_input("'" + path + "' declares colour space '" + choice->colorspace +
                                 "' (oiio:ColorSpace), which the " + config.source() +
                                 " OpenColorIO config does not know; pass " + option + " NAME",
                             option);
        return canonical.error();
    }
    return ImageColorSpace{*canonical, choice->rule};
}

Status image_rgb_to_scene_linear(std::vector<float>& rgb, const ImageColorSpace& space, const ColorConfig& config)
{
    if (config.is_data(space.colorspace)) return ok();
    return config.to_scene_linear(rgb, space.colorspace);
}

}  // namespace cmfilter
