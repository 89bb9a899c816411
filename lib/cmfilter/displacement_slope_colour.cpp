#include "cmfilter/displacement_slope_colour.h"

#include "cmfilter/light_weighted_slope_map.h"

#include <algorithm>
#include <cmath>

namespace cmfilter {

template <typename SlopeMap>
Rgb displacement_slope_colour(const DisplacementTexture& texture, const SlopeMap& map, double u, double v,
                              double e1u, double e1v, double e2u, double e2v, const ViewAngles& view,
                              const DisplacementSlopeColourOptions& options)
{
    // The plastic number's lattice (the 2-D golden ratio).
    constexpr double kAlpha1 = 0.7548776662466927, kAlpha2 = 0.5698402909980532;
    const SlopeViewFrame frame = slope_view_frame({}, view);  // theta and phi read as eq. 20 reads them
    const double cos_t = frame.cos_theta, sin_t = frame.sin_theta, dx = frame.dx, dy = frame.dy;
    const auto finite_or_zero = [](double x) { return std::isfinite(x) ? x : 0.0; };
    e1u = finite_or_zero(e1u), e1v = finite_or_zero(e1v), e2u = finite_or_zero(e2u), e2v = finite_or_zero(e2v);
    const int n = std::max(1, options.samples);
    Rgb weighted, plain;
    double weight = 0;
    for (int k = 0; k < n; ++k) {
        const double a = std::fmod((k + 0.5) * kAlpha1, 1.0) - 0.5, b = std::fmod((k + 0.5) * kAlpha2, 1.0) - 0.5;
        double sx = 0, sy = 0;
        texture.slope(u + a * e1u + b * e2u, v + a * e1v + b * e2v, sx, sy);
        const Rgb c = map.evaluate(sx, sy);
        const double w = std::max(0.0, cos_t - sin_t * (sx * dx + sy * dy));  // eq. 20's weight
        weighted += w * c;
        weight += w;
        plain += c;
    }
    return weight > 0 ? (1.0 / weight) * weighted : (1.0 / n) * plain;
}

template Rgb displacement_slope_colour(const DisplacementTexture&, const SteepnessColorMap&, double, double, double,
                                       double, double, double, const ViewAngles&,
                                       const DisplacementSlopeColourOptions&);
template Rgb displacement_slope_colour(const DisplacementTexture&, const SlopeVectorColorMap&, double, double, double,
                                       double, double, double, const ViewAngles&,
                                       const DisplacementSlopeColourOptions&);
// The light-weighted maps (light_weighted_slope_map.h).
template Rgb displacement_slope_colour(const DisplacementTexture&, const LightWeightedSlopeMap<SteepnessColorMap>&,
                                       double, double, double, double, double, double, const ViewAngles&,
                                       const DisplacementSlopeColourOptions&);
template Rgb displacement_slope_colour(const DisplacementTexture&, const LightWeightedSlopeMap<SlopeVectorColorMap>&,
                                       double, double, double, double, double, double, const ViewAngles&,
                                       const DisplacementSlopeColourOptions&);
template Rgb displacement_slope_colour(const DisplacementTexture&, const LightCosineSlopeMap&, double, double, double,
                                       double, double, double, const ViewAngles&,
                                       const DisplacementSlopeColourOptions&);

}  // namespace cmfilter
