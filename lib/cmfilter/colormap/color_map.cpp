// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/colormap/color_map.h"

#include <cmath>
#include <sstream>

namespace cmfilter {

Rgb ColorMap::evaluate(double v) const
{
    const long n = size();
    double x = node_coordinate(v);
    if (std::isnan(x)) return texels.front();
    if (wrap == WrapMode::Clamp) {
        if (!(x > 0.0)) return texels.front();
        if (x >= static_cast<double>(n - 1)) return texels.back();
    } else {
        // Periodic in node space: period n (repeat) or 2n (mirror).
        if (!std::isfinite(x)) return texels.front();
        const double period = wrap == WrapMode::Repeat ? n : 2.0 * n;
        x = std::fmod(x, period);
        if (x < 0) x += period;
    }
    const double k = std::floor(x);
    const double t = x - k;
    const long ki = static_cast<long>(k);
    return (1.0 - t) * node(ki) + t * node(ki + 1);
}

Status validate(const ColorMap& map, const std::string& what)
{
    if (map.texels.empty()) return bad_input(what + ": the colour map has no texels");
    if (!std::isfinite(map.vmin) || !std::isfinite(map.vmax) || !(map.vmin < map.vmax)) {
        std::ostringstream msg;
        msg << what << ": domain " << map.vmin << ":" << map.vmax << " is invalid (expected finite vmin < vmax)";
        return bad_input(msg.str());
    }
    for (std::size_t i = 0; i < map.texels.size(); ++i) {
        const Rgb& c = map.texels[i];
        if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b)) {
            std::ostringstream msg;
            msg << what << ": texel " << i << " is not finite (" << c.r << ", " << c.g << ", " << c.b
                << "); expected finite colours";
            return bad_input(msg.str());
        }
    }
    return ok();
}

}  // namespace cmfilter
