// SPDX-License-Identifier: Apache-2.0
// The slope-filtered colour <C_s, D_s> of eq. 20 (Heitz et al. 2013, sec.
// 5.2): the mean of a slope colour map (slope_color_map.h) over the slopes a
// viewer sees, D_s (slope_filtering.h), for slopes N(m, Sigma) and the view
// omega_o. Eq. 19 multiplies it by the mean visibility and the BRDF's mean.
//
// gaussian_slope_color replaces D_s by the Gaussian with D_s's exact mean
// and covariance (the paper's single-Gaussian approximation, fig. 9) and
// integrates the map over it by a tensor Gauss-Hermite rule along the
// covariance's principal axes (gauss_hermite.h): points_per_axis^2 map
// lookups.
//
// exact_slope_color integrates the map over D_s itself, in the view's frame
// (SlopeViewFrame): along d over u's law under D_s (the standard normal
// weighted by (k - z)_+, integrated up to its edge z = k; where the horizon
// lies below the mean slope, k = -x < 0, in y = k - z with the weight
// y e^{-x y - y^2/2}), across d over the
// Gaussian residual, each by 8-point Gauss-Legendre on `panels` equal panels
// spanning 9 standard deviations each side (or the weight's own reach), the
// weights normalised by their own quadrature: (8 panels)^2 map lookups. How
// dense it must be to serve as the reference, and how many Gauss-Hermite
// points the Gaussian needs, were measured (docs/slope.md).
#pragma once

#include "cmfilter/colormap/slope_color_map.h"
#include "cmfilter/microsurface/slope_filtering.h"

namespace cmfilter {

struct GaussianSlopeColorOptions {
    // In [1, 100]. 12: the mean CIEDE2000 against the exact D_s colour is at
    // most 0.72 over each measured sweep up to 80 degrees, 10 the smallest
    // count at most 1.0 (docs/slope.md).
    int points_per_axis = 12;
};

struct ExactSlopeColorOptions {
    // >= 1, 8 points each per axis. 32: within 0.0008 mean and 0.008 max
    // CIEDE2000 of 128 panels on the measured maps (docs/slope.md).
    int panels = 32;
};

// SlopeMap: SteepnessColorMap or SlopeVectorColorMap, or their light-weighted
// forms and LightCosineSlopeMap (light_weighted_slope_map.h): the
// instantiations slope_color.cpp provides.
template <typename SlopeMap>
Rgb gaussian_slope_color(const SlopeMap& map, const SlopeGaussian& slopes, const ViewAngles& view,
                         const GaussianSlopeColorOptions& options = {});

template <typename SlopeMap>
Rgb exact_slope_color(const SlopeMap& map, const SlopeGaussian& slopes, const ViewAngles& view,
                      const ExactSlopeColorOptions& options = {});

extern template Rgb gaussian_slope_color(const SteepnessColorMap&, const SlopeGaussian&, const ViewAngles&,
                                         const GaussianSlopeColorOptions&);
extern template Rgb gaussian_slope_color(const SlopeVectorColorMap&, const SlopeGaussian&, const ViewAngles&,
                                         const GaussianSlopeColorOptions&);
extern template Rgb exact_slope_color(const SteepnessColorMap&, const SlopeGaussian&, const ViewAngles&,
                                      const ExactSlopeColorOptions&);
extern template Rgb exact_slope_color(const SlopeVectorColorMap&, const SlopeGaussian&, const ViewAngles&,
                                      const ExactSlopeColorOptions&);

}  // namespace cmfilter
