// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/colormap/slope_color_map.h"

#include "cmfilter/math/bilinear_texels.h"

#include <cmath>
#include <sstream>

namespace cmfilter {

Rgb SteepnessColorMap::evaluate(double sx, double sy) const
{
    constexpr double kDegreesPerRadian = 57.295779513082320877;
    return by_angle.evaluate(std::atan(std::hypot(sx, sy)) * kDegreesPerRadian);
}

Rgb SlopeVectorColorMap::evaluate(double sx, double sy) const
{
    // Image coordinates: s from the left edge, t from the top one.
    const double s = (sx + s_max) / (2 * s_max), t = (s_max - sy) / (2 * s_max);
    return bilinear_texels<Rgb>(s, t, width, height, TextureWrap::Clamp, Rgb{},
                                [this](int i, int j) { return texels[static_cast<std::size_t>(j) * width + i]; });
}

Status validate(const SteepnessColorMap& map, const std::string& what) { return validate(map.by_angle, what); }

Status validate(const SlopeVectorColorMap& map, const std::string& what)
{
    if (map.width < 1 || map.height < 1 ||
        map.texels.size() != static_cast<std::size_t>(map.width) * static_cast<std::size_t>(map.height)) {
        std::ostringstream msg;
        msg << what << ": " << map.texels.size() << " texels for a " << map.width << " x " << map.height
            << " slope map (expected width x height, at least one)";
        return bad_input(msg.str());
    }
    if (!std::isfinite(map.s_max) || !(map.s_max > 0)) {
        std::ostringstream msg;
        msg << what << ": s_max " << map.s_max << " must be finite and > 0";
        return bad_input(msg.str());
    }
    for (const Rgb& c : map.texels) {
        if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b))
            return bad_input(what + ": a texel is not finite");
    }
    return ok();
}

}  // namespace cmfilter
