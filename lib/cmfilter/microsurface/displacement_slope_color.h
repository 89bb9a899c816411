// SPDX-License-Identifier: Apache-2.0
// The slope layer of a textured displacement (displacement_texture.h) from
// its own slopes and heights rather than a Gaussian (Heitz et al. 2013, sec.
// 5.2): the `exact` method's colour <C_s, D_s> (eq. 20) and visibility V
// (eqs. 13 and 19) there.
//
// Points x_k sampled uniformly over the footprint carry their slope s_k and
// height h_k. Eq. 20 weighs a slope by its visible projected area,
//     a(s) = max(0, cos t - sin t <s, d>)        (slope_filtering.h),
// and takes the visible facets' heights as independent of their slopes. On
// a relief they are not (scales: flat tops high, steep rims low), so each
// point is also weighted by Smith's probability that it is seen, and seen and
// lit, from its height (displacement_masking.h):
//     seen_k     = a(s_k) F(h_k)^Lambda_o,
//     seen_lit_k = a(s_k) F(h_k)^L,   L = Lambda_o + Lambda_i (eq. 13), or
//                                     its direction-correlated form,
// F the surface's height CDF and the Lambdas from its own slopes. Then
//     <C_s, D_s> = sum seen_k C_s(s_k) / sum seen_k,
//     V          = sum seen_lit_k / sum seen_k           (eq. 13's share lit),
// and with the shading correlated with the colour (light_weighted_slope_map.h),
// lambda_k = max(0, <n(s_k), l>),
//     colour     = sum seen_lit_k lambda_k C_s(s_k) / sum seen_lit_k lambda_k,
//     V          = sum seen_lit_k lambda_k / sum seen_k lambda_k,
// whose product V colour is what the ray-traced reference's albedo estimate,
// sum C V_i <m, l>+ / sum <m, l>+ over the hits, measures. F and Lambda
// constant over the footprint (a flat surface, or theta = 0) give back eq. 20
// and eq. 13's V for these slopes.
//
// The samples, 16 per texel the footprint covers (at least 64, at most 4096),
// lie on a rank-2 Kronecker (golden-ratio) lattice over the
// parallelogram, c + (a_k - 1/2) e1 + (b_k - 1/2) e2 with (a_k, b_k) =
// frac((k + 1/2) (alpha1, alpha2)), alpha the plastic-number lattice: no
// period of the texture is commensurate with it, so a footprint of many
// repeats samples the whole pattern evenly; a point footprint samples its
// one point. Where no point is seen (at 90 degrees), the unweighted mean
// colour and eq. 13's limits for V.
#pragma once

#include "cmfilter/color/color.h"
#include "cmfilter/microsurface/displacement_texture.h"
#include "cmfilter/microsurface/height_filtered_albedo.h"
#include "cmfilter/microsurface/light_weighted_slope_map.h"
#include "cmfilter/colormap/slope_color_map.h"
#include "cmfilter/microsurface/smith_lambda.h"

namespace cmfilter {

// A footprint's parallelogram: centre (u, v), edges e1 and e2, texture units.
struct FootprintPiece {
    double u = 0, v = 0, e1u = 0, e1v = 0, e2u = 0, e2v = 0;
};

struct DisplacementSlopeColorOptions {
    // Points per footprint: samples_per_texel per texel the parallelogram
    // covers, within [min_samples, max_samples] (a point footprint takes
    // min_samples of the same point).
    int max_samples = 4096;  // >= 1
    int min_samples = 64;    // >= 1
    double samples_per_texel = 16;
    MaskingShadowing masking = MaskingShadowing::Uncorrelated;
    SlopeShading shading = SlopeShading::Uncorrelated;
};

struct DisplacementSlopeLayer {
    Rgb colour;  // black without a map
    double visibility = 1;
};

// SlopeMap: SteepnessColorMap or SlopeVectorColorMap; a null map gives the
// visibility alone.
template <typename SlopeMap>
DisplacementSlopeLayer displacement_slope_layer(const DisplacementTexture& texture, const SlopeMap* map,
                                                const FootprintPiece& piece, const HeightDirections& directions,
                                                const DisplacementSlopeColorOptions& options = {});

extern template DisplacementSlopeLayer displacement_slope_layer(const DisplacementTexture&, const SteepnessColorMap*,
                                                                const FootprintPiece&, const HeightDirections&,
                                                                const DisplacementSlopeColorOptions&);
extern template DisplacementSlopeLayer displacement_slope_layer(const DisplacementTexture&, const SlopeVectorColorMap*,
                                                                const FootprintPiece&, const HeightDirections&,
                                                                const DisplacementSlopeColorOptions&);

}  // namespace cmfilter
