// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/microsurface/displacement_slope_color.h"

#include <algorithm>
#include <cmath>

namespace cmfilter {

template <typename SlopeMap>
DisplacementSlopeLayer displacement_slope_layer(const DisplacementTexture& texture, const SlopeMap* map,
                                                const FootprintPiece& piece, const HeightDirections& d,
                                                const DisplacementSlopeColorOptions& options)
{
    // The plastic number's lattice (the 2-D golden ratio).
    constexpr double kAlpha1 = 0.7548776662466927, kAlpha2 = 0.5698402909980532;
    const ViewAngles view{d.theta_o, d.phi_o}, light_angles{d.theta_i, d.phi_i};
    const SlopeViewFrame frame = slope_view_frame({}, view);  // theta and phi read as eq. 20 reads them
    const double cos_t = frame.cos_theta, sin_t = frame.sin_theta, dx = frame.dx, dy = frame.dy;
    const LightDirection light = LightDirection::from_angles(light_angles);
    const DisplacementMasking& masking = texture.masking();
    const double lambda_o = masking.lambda(view), lambda_i = masking.lambda(light_angles);
    const double lambda_seen_lit = lambda_sum(lambda_o, lambda_i, d.phi_o - d.phi_i, options.masking);
    const bool correlated = options.shading == SlopeShading::Correlated;

    const auto finite_or_zero = [](double x) { return std::isfinite(x) ? x : 0.0; };
    const double u = finite_or_zero(piece.u), v = finite_or_zero(piece.v);
    // Non-finite edges read as an infinite footprint: one whole repeat, as
    // DisplacementTexture::footprint reads them.
    const bool infinite = !std::isfinite(piece.e1u) || !std::isfinite(piece.e1v) || !std::isfinite(piece.e2u) ||
                          !std::isfinite(piece.e2v);
    const double e1u = infinite ? 1.0 : piece.e1u, e1v = infinite ? 0.0 : piece.e1v;
    const double e2u = infinite ? 0.0 : piece.e2u, e2v = infinite ? 1.0 : piece.e2v;
    const double texels = std::abs(e1u * e2v - e1v * e2u) * texture.size() * texture.size();
    const int most = std::max(1, options.max_samples), least = std::clamp(options.min_samples, 1, most);
    const int n = texels * options.samples_per_texel >= most
                      ? most
                      : std::max(least, static_cast<int>(std::ceil(texels * options.samples_per_texel)));
    Rgb color_sum, seen_colour_sum, plain;
    double seen_sum = 0, seen_lit_sum = 0,
           seen_area_sum = 0;  // weights as the colour takes them (times lambda_k when correlated)
    for (int k = 0; k < n; ++k) {
        const double a = std::fmod((k + 0.5) * kAlpha1, 1.0) - 0.5, b = std::fmod((k + 0.5) * kAlpha2, 1.0) - 0.5;
        const double x = u + a * e1u + b * e2u, y = v + a * e1v + b * e2v;
        double sx = 0, sy = 0;
        texture.slope(x, y, sx, sy);
        const double f = masking.height_cdf(texture.height(x, y));
        const double area = std::max(0.0, cos_t - sin_t * (sx * dx + sy * dy));  // eq. 20's weight
        const double shading = correlated ? light.facet_cosine(sx, sy) : 1.0;
        const double seen_area = area * std::pow(f, lambda_o);  // G1 (eq. 2)
        const double seen = seen_area * shading;
        const double seen_lit = area * std::pow(f, lambda_seen_lit) * shading;
        seen_sum += seen;
        seen_lit_sum += seen_lit;
        seen_area_sum += seen_area;
        if (map) {
            const Rgb c = map->evaluate(sx, sy);
            color_sum += (correlated ? seen_lit : seen) * c;
            seen_colour_sum += seen_area * c;
            plain += c;
        }
    }
    DisplacementSlopeLayer out;
    const double color_weight = correlated ? seen_lit_sum : seen_sum;
    if (map) {
        if (color_weight > 0) out.colour = (1.0 / color_weight) * color_sum;
        else if (seen_area_sum > 0)  // seen, but nothing seen faces the light: eq. 20's colour
            out.colour = (1.0 / seen_area_sum) * seen_colour_sum;
        else out.colour = (1.0 / n) * plain;
    }
    out.visibility = seen_sum > 0 ? std::clamp(seen_lit_sum / seen_sum, 0.0, 1.0)
                                  : mean_visibility(lambda_o, lambda_i, d.phi_o - d.phi_i, options.masking);
    return out;
}

template DisplacementSlopeLayer displacement_slope_layer(const DisplacementTexture&, const SteepnessColorMap*,
                                                         const FootprintPiece&, const HeightDirections&,
                                                         const DisplacementSlopeColorOptions&);
template DisplacementSlopeLayer displacement_slope_layer(const DisplacementTexture&, const SlopeVectorColorMap*,
                                                         const FootprintPiece&, const HeightDirections&,
                                                         const DisplacementSlopeColorOptions&);

}  // namespace cmfilter
