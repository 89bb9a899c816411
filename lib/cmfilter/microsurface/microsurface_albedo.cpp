// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/microsurface/microsurface_albedo.h"

#include "cmfilter/microsurface/displacement_slope_color.h"
#include "cmfilter/microsurface/light_weighted_slope_map.h"
#include "cmfilter/microsurface/slope_color.h"

#include <algorithm>
#include <type_traits>
#include <variant>

namespace cmfilter {

namespace {

// <C_s, D_s> (eq. 20) for the slopes N(resolved mean, unresolved covariance)
// seen from the view.
Rgb slope_layer(const SlopeMap& map, const SlopeGaussian& slopes, const ResolvedSlope& slope, const HeightDirections& d,
                const MicrosurfaceLayerOptions& options)
{
    const ViewAngles view{d.theta_o, d.phi_o};
    // The mean of a (slope -> colour) function over D_s in the representation asked for.
    const auto over_ds = [&](const auto& m) -> Rgb {
        if (options.slopes == SlopeRepresentation::Exact) {
            ExactSlopeColorOptions o;
            o.panels = options.exact_panels;
            return exact_slope_color(m, slopes, view, o);
        }
        GaussianSlopeColorOptions o;
        o.points_per_axis = options.hermite_points;
        return gaussian_slope_color(m, slopes, view, o);
    };
    return std::visit(
        [&](const auto& m) -> Rgb {
            if (options.slopes == SlopeRepresentation::Naive) return m.evaluate(slope.x, slope.y);
            if (options.slope_shading == SlopeShading::Uncorrelated) return over_ds(m);  // eq. 20
            // <C_s lambda, D_s> / <lambda, D_s> (light_weighted_slope_map.h).
            const LightDirection light = LightDirection::from_angles({d.theta_i, d.phi_i});
            const double lit = over_ds(LightCosineSlopeMap{light}).r;
            if (!(lit > 1e-12)) return over_ds(m);  // no facet faces the light: eq. 20's colour
            return (1 / lit) * over_ds(LightWeightedSlopeMap<std::decay_t<decltype(m)>>{&m, light});
        },
        map);
}

// The slope layer and V of a textured displacement from its own slopes and
// heights over the piece (displacement_slope_color.h).
DisplacementSlopeLayer sampled_displacement_layer(const MicrosurfaceColors& m, const DisplacementTexture& texture,
                                                  const HeightDirections& d, const MicrosurfaceLayerOptions& options,
                                                  const FootprintPiece& piece)
{
    DisplacementSlopeColorOptions o;
    o.masking = options.masking;
    o.shading = options.slope_shading;
    if (!m.slope) return displacement_slope_layer(texture, static_cast<const SteepnessColorMap*>(nullptr), piece, d, o);
    return std::visit([&](const auto& map) { return displacement_slope_layer(texture, &map, piece, d, o); }, *m.slope);
}

// The Gaussian methods on a textured displacement: D_s fitted to the
// footprint's slopes weighted by G1 = F(h)^Lambda_o (masked_slope_table.h),
// and V = E[F^L] / E[F^Lambda_o], the share of what is seen that is lit
// (eq. 13 for a uniform F), Lambda from the texture's own slopes.
struct MaskedGaussian {
    SlopeGaussian slopes;
    double visibility = 1;
};

MaskedGaussian masked_gaussian(const DisplacementTexture& t, const HeightDirections& d,
                               const MicrosurfaceLayerOptions& options, const FootprintPiece& p)
{
    const DisplacementMasking& masking = t.masking();
    const double lambda_o = masking.lambda({d.theta_o, d.phi_o}), lambda_i = masking.lambda({d.theta_i, d.phi_i});
    const double lambda_seen_lit = lambda_sum(lambda_o, lambda_i, d.phi_o - d.phi_i, options.masking);
    const MaskedFootprint seen = t.masked_footprint(p.u, p.v, p.e1u, p.e1v, p.e2u, p.e2v, lambda_o);
    const MaskedFootprint seen_lit = t.masked_footprint(p.u, p.v, p.e1u, p.e1v, p.e2u, p.e2v, lambda_seen_lit);
    MaskedGaussian out;
    out.slopes = {seen.slope_x, seen.slope_y, seen.slope_xx, seen.slope_xy, seen.slope_yy};
    out.visibility = seen.g1 > 0 ? std::clamp(seen_lit.g1 / seen.g1, 0.0, 1.0)
                                 : mean_visibility(lambda_o, lambda_i, d.phi_o - d.phi_i, options.masking);
    return out;
}

Rgb times(const Rgb& a, const Rgb& b) { return {a.r * b.r, a.g * b.g, a.b * b.b}; }

}  // namespace

MicrosurfaceLayers microsurface_layers(const MicrosurfaceColors& m, const MicrosurfaceFootprint& f,
                                       const ResolvedSlope& slope, const HeightDirections& d,
                                       const MicrosurfaceLayerOptions& options, const HeightMomentTable& table,
                                       AlbedoCounts& counts, const DisplacementTexture* displacement,
                                       const FootprintPiece* piece)
{
    MicrosurfaceLayers out;
    out.mean = f.mean_height;
    std::optional<Rgb> height, slope_color;
    if (m.height) {
        const HeightAlbedo h = height_filtered_albedo(*m.height, f, d, options.heights, table, counts, options.masking);
        height = h.colour;
        out.visibility = options.heights == HeightRepresentation::Naive ? 1.0 : h.visibility * h.resolved_visibility;
        out.mean = h.mean;
        out.sigma = h.sigma;
    } else if (options.heights != HeightRepresentation::Naive) {
        out.visibility = microsurface_visibility(f, d, options.masking).total();
    }
    if (options.slopes == SlopeRepresentation::Exact && displacement && piece) {
        const DisplacementSlopeLayer sampled = sampled_displacement_layer(m, *displacement, d, options, *piece);
        out.visibility = sampled.visibility;
        if (m.slope) slope_color = sampled.colour;
    } else if (options.slopes == SlopeRepresentation::Gaussian && displacement && piece) {
        const MaskedGaussian masked = masked_gaussian(*displacement, d, options, *piece);
        out.visibility = masked.visibility;
        if (m.slope) slope_color = slope_layer(*m.slope, masked.slopes, slope, d, options);
    } else if (m.slope) {
        const SlopeGaussian slopes{slope.x, slope.y, f.slope_xx, f.slope_xy, f.slope_yy};
        slope_color = slope_layer(*m.slope, slopes, slope, d, options);
    }
    const ColorCombination& c = m.combine;
    Rgb layers;
    if (c.mode == CombineMode::Sum) {
        if (height) layers += c.height * *height;
        if (slope_color) layers += c.slope * *slope_color;
    } else {
        layers = {1, 1, 1};
        if (height) layers = times(layers, *height);
        if (slope_color) layers = times(layers, *slope_color);
    }
    out.shadowed = out.visibility * layers;
    return out;
}

Rgb combine_microsurface_albedo(const ColorCombination& c, double mean_visibility, const Rgb& mean_shadowed,
                                const std::optional<Rgb>& base)
{
    if (!base) return mean_shadowed;
    if (c.mode == CombineMode::Sum) return (c.base * mean_visibility) * *base + mean_shadowed;
    return times(*base, mean_shadowed);
}

Rgb combine_point_color(const ColorCombination& c, const std::optional<Rgb>& base, const std::optional<Rgb>& height,
                        const std::optional<Rgb>& slope)
{
    if (c.mode == CombineMode::Sum) {
        Rgb out;
        if (base) out += c.base * *base;
        if (height) out += c.height * *height;
        if (slope) out += c.slope * *slope;
        return out;
    }
    Rgb out{1, 1, 1};
    for (const auto* layer : {&base, &height, &slope})
        if (*layer) out = times(out, **layer);
    return out;
}

}  // namespace cmfilter
