// SPDX-License-Identifier: Apache-2.0
// Slope colour maps weighted by each facet's cosine to the light, for
// filtering slope-coloured microsurfaces with the shading correlated with the
// colour. Eq. 19 (Heitz et al. 2013, sec. 5.2) takes a facet's shading
// rho max(0, <n(s), l>) as uncorrelated with its colour C_s(s), so that the
// filtered colour is <C_s, D_s> and the shading's mean rho-bar factors out.
// On a steepness map it is not: steep facets turned from the light are both
// dark and differently coloured. For Lambertian facets the colour the light
// actually brings out of the slopes a viewer sees is
//     <C_s, D_s>_l = <C_s lambda, D_s> / <lambda, D_s>,
//     lambda(s)   = max(0, <n(s), l>) = max(0, l_z - l_x s_x - l_y s_y) / sqrt(1 + |s|^2),
// for n(s) = (-s_x, -s_y, 1) / sqrt(1 + |s|^2) and the light l in the plane's
// frame: the same integrals over D_s as eq. 20's, of the map times lambda and
// of lambda alone. That is what the ray-traced reference's albedo estimate,
// sum C V_i <m, l>+ / sum <m, l>+ over the hits, measures. Every quadrature
// over D_s (slope_color.h, displacement_slope_color.h) takes these two
// maps in place of the map itself, and the ratio of the two results is the
// light-weighted colour.
#pragma once

#include "cmfilter/color/color.h"
#include "cmfilter/microsurface/slope_filtering.h"

#include <algorithm>
#include <cmath>

namespace cmfilter {

// Whether a slope colour is filtered as eq. 19 does, the facets' shading
// taken as uncorrelated with their colour (<C_s, D_s>), or weighted by each
// facet's cosine to the light (<C_s lambda, D_s> / <lambda, D_s>).
enum class SlopeShading { Uncorrelated, Correlated };

// The light's direction in the plane's frame (z the normal).
struct LightDirection {
    double x = 0, y = 0, z = 1;
    // Angles read as slope_view_frame reads a view's (NaN theta as 0, from 90
    // degrees on exactly at the horizon).
    static LightDirection from_angles(const ViewAngles& light)
    {
        const SlopeViewFrame f = slope_view_frame({}, light);
        return {f.sin_theta * f.dx, f.sin_theta * f.dy, f.cos_theta};
    }
    // lambda(s): the facet of slope s's cosine to the light, clamped at 0.
    double facet_cosine(double sx, double sy) const
    {
        return std::max(0.0, z - x * sx - y * sy) / std::sqrt(1 + sx * sx + sy * sy);
    }
};

// C_s(s) lambda(s).
template <typename SlopeMap>
struct LightWeightedSlopeMap {
    const SlopeMap* map;
    LightDirection light;
    Rgb evaluate(double sx, double sy) const { return light.facet_cosine(sx, sy) * map->evaluate(sx, sy); }
};

// lambda(s) in every channel.
struct LightCosineSlopeMap {
    LightDirection light;
    Rgb evaluate(double sx, double sy) const
    {
        const double c = light.facet_cosine(sx, sy);
        return {c, c, c};
    }
};

}  // namespace cmfilter
