// SPDX-License-Identifier: Apache-2.0
// Helpers for the tests of layered microsurface materials (slope colour maps,
// base layers, combinations): the per-channel range of a slope map's texels,
// materials prepared from a parsed scene, and the text of loading errors.
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/scene/scene.h"
#include "cmfilter/scene/scene_materials.h"

#include "microsurface_test_support.h"

#include <doctest/doctest.h>

#include <string>
#include <variant>
#include <vector>

namespace cmfilter_test {

inline ColorRange texel_range(const std::vector<cmfilter::Rgb>& texels)
{
    REQUIRE_FALSE(texels.empty());
    ColorRange r{texels.front(), texels.front()};
    for (const cmfilter::Rgb& t : texels) {
        r.lo = {std::min(r.lo.r, t.r), std::min(r.lo.g, t.g), std::min(r.lo.b, t.b)};
        r.hi = {std::max(r.hi.r, t.r), std::max(r.hi.g, t.g), std::max(r.hi.b, t.b)};
    }
    return r;
}

// Every colour a slope map can give lies in its texels' range (linear or
// bilinear between texels, clamped or repeated beyond).
inline ColorRange slope_range(const cmfilter::SlopeMap& map)
{
    if (const auto* s = std::get_if<cmfilter::SteepnessColorMap>(&map)) return texel_range(s->by_angle.texels);
    return texel_range(std::get<cmfilter::SlopeVectorColorMap>(map).texels);
}

// prepare_materials with the built-in colour configuration; the test stops
// with the error's message if it fails.
inline std::vector<cmfilter::Material> prepared_materials(const cmfilter::Scene& scene, int threads)
{
    auto config = cmfilter::ColorConfig::load("");
    REQUIRE(config);
    cmfilter::MaterialOptions options;
    options.threads = threads;
    auto materials = cmfilter::prepare_materials(scene, *config, options);
    REQUIRE_MESSAGE(materials, (materials ? "" : materials.error().message));
    return std::move(*materials);
}

// A scene refused on loading: its BadInput message after "<path>: ", or a
// note saying what went wrong ("(parsed)" when it loaded).
inline std::string bad_input_after_path(const cmfilter::Expected<cmfilter::Scene>& parsed, const std::string& path)
{
    if (parsed) return "(parsed)";
    CHECK(parsed.error().kind == cmfilter::ErrorKind::BadInput);
    const std::string& message = parsed.error().message;
    const std::string prefix = path + ": ";
    return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : "(not prefixed) " + message;
}

inline bool starts_with(const std::string& text, const std::string& start) { return text.rfind(start, 0) == 0; }
inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace cmfilter_test
