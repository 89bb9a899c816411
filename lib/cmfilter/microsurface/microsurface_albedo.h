// SPDX-License-Identifier: Apache-2.0
// The colour of a microsurface material (scene.h) over one footprint, its
// layers (microsurface_colors.h) filtered and combined (Heitz et al. 2013,
// secs. 5 and 6):
//   height  C_h, V <C_h, D_h> (eq. 14; height_filtered_albedo.h);
//   slope   C_s, V <C_s, D_s> (eqs. 19-20; slope_color.h): D_s for the
//           unresolved slope covariance about the resolved mean slope, seen
//           from the view direction (on a textured displacement, its slopes
//           weighted by Smith's masking from their heights: exact from
//           samples, displacement_slope_color.h; the Gaussian methods from
//           the moment tables of masked_slope_table.h);
//   base    C0 over a driver that ignores the microsurface, V C0-bar, its
//           driver filtered as a plain material's (sec. 4).
// V is eq. 13's mean visibility times the resolved heights' shadowing V_r
// (height_filtered_albedo.h), shared by every layer (on a textured
// displacement, Smith's from the texture's heights and slopes, sampled or
// tabulated as its slopes are). Eq. 19 also takes the
// BRDF's mean rho-bar out of the colour, assuming C_s and rho uncorrelated;
// here, as for heights, rho-bar is the renderer's shading of the mean
// plane, so what this gives is an albedo.
//
// Combinations (sec. 6):
//   sum      k0 C0 + k1 C_h + k2 C_s  ->  V (k0 C0-bar + k1 <C_h, D_h> + k2 <C_s, D_s>),
//   product  C0 C_h C_s               ->  V C0-bar <C_h, D_h> <C_s, D_s>,
// over the layers present (the product of heights, slopes and driver taken
// as uncorrelated, as the paper does). A footprint cut into probes
// (render.cpp) averages V and the microsurface layers over them; the base
// layer is filtered over the whole footprint once, so the pixel's albedo is
//   sum:     k0 C0-bar mean(V) + mean(V (k1 <C_h, D_h> + k2 <C_s, D_s>)),
//   product: C0-bar mean(V <C_h, D_h> <C_s, D_s>).
// The naive method takes each map at the footprint's mean (C_h of the
// resolved height, C_s of the resolved slope, C0 of the driver's mean) and
// V = 1.
#pragma once

#include "cmfilter/color/color.h"
#include "cmfilter/microsurface/color_combination.h"
#include "cmfilter/microsurface/displacement_slope_color.h"
#include "cmfilter/microsurface/displacement_texture.h"
#include "cmfilter/microsurface/height_filtered_albedo.h"
#include "cmfilter/microsurface/light_weighted_slope_map.h"
#include "cmfilter/microsurface/microsurface_colors.h"
#include "cmfilter/microsurface/microsurface_footprint.h"

#include <optional>

namespace cmfilter {

// How D_s is represented: the resolved slope alone (naive), the Gaussian of
// D_s's exact moments with Gauss-Hermite (gaussian), or D_s itself (exact).
enum class SlopeRepresentation { Naive, Gaussian, Exact };

struct MicrosurfaceLayerOptions {
    HeightRepresentation heights = HeightRepresentation::PaperFit;
    SlopeRepresentation slopes = SlopeRepresentation::Gaussian;
    // The paper's forms (eqs. 13 and 19); render's defaults (RenderOptions)
    // are the correlated ones.
    MaskingShadowing masking = MaskingShadowing::Uncorrelated;
    SlopeShading slope_shading = SlopeShading::Uncorrelated;
    int hermite_points = 12;  // GaussianSlopeColorOptions::points_per_axis
    // ExactSlopeColorOptions::panels: 8 (4096 map lookups a probe) is within
    // 0.017 mean and 0.17 max CIEDE2000 of 128 panels (docs/slope.md).
    int exact_panels = 8;
};

// One probe's microsurface layers: V, and V times their sum (k1, k2) or
// product; AOVs: the mean and sigma of the heights seen lit (D_h's; the
// resolved mean for the naive method or without a height map).
struct MicrosurfaceLayers {
    double visibility = 1;
    Rgb shadowed;
    double mean = 0, sigma = 0;
};

// `slope` is the resolved mean slope over the probe (needed with a slope
// map; ignored otherwise). `table` serves HeightRepresentation::ExactMoments.
// On a textured `displacement` (null: a Gaussian microsurface) with a
// `piece`, SlopeRepresentation::Exact takes D_s and V from the texture's own
// slopes and heights sampled over it (displacement_slope_color.h), and
// Gaussian from its masked moment tables
// (DisplacementTexture::masked_footprint); without a piece, the Gaussian of
// the footprint's moments as elsewhere.
MicrosurfaceLayers microsurface_layers(const MicrosurfaceColors& colors, const MicrosurfaceFootprint& footprint,
                                       const ResolvedSlope& slope, const HeightDirections& directions,
                                       const MicrosurfaceLayerOptions& options, const HeightMomentTable& table,
                                       AlbedoCounts& counts, const DisplacementTexture* displacement = nullptr,
                                       const FootprintPiece* piece = nullptr);

// The footprint's albedo from the probes' mean V and mean shadowed layers
// and the base layer's filtered colour (none without a base layer).
Rgb combine_microsurface_albedo(const ColorCombination& combine, double mean_visibility, const Rgb& mean_shadowed,
                                const std::optional<Rgb>& base);

// The material's colour at one point of the displaced surface (the
// ray-traced methods): the combination of the layers present there.
Rgb combine_point_color(const ColorCombination& combine, const std::optional<Rgb>& base,
                        const std::optional<Rgb>& height, const std::optional<Rgb>& slope);

}  // namespace cmfilter
