// SPDX-License-Identifier: Apache-2.0
// The slope filtering distribution of a heightfield with Gaussian slopes
// (Heitz et al. 2013, sec. 5.2, eq. 20): the slopes a viewer sees, weighted
// by their foreshortened area. For slopes s = grad h = (s_x, s_y) ~ N(m, Sigma)
// over the footprint's projected area, the facet normal
// n(s) = (-s_x, -s_y, 1) / sqrt(1 + |s|^2) and the view direction
// omega_o = (sin t cos p, sin t sin p, cos t),
//
//   D_s(s) = max(0, <omega_o, n(s)>) / <z, n(s)> p(s) / Z
//          = max(0, cos t - sin t <s, d>) p(s) / Z,     d = (cos p, sin p),
//
// (1 / <z, n> turns projected area into facet area): a facet tilted towards
// the viewer (<s, d> < 0, its normal leaning along d) weighs more, one
// turned away less, and one with <s, d> >= cot t is hidden. The
// normalisation Z = int max(0, cos t - sin t <s, d>) p(s) ds is the
// projected area of the visible facets per unit of footprint; for m = 0 it is
// cos t (1 + Lambda(t)) with Smith's Lambda of eq. 3 (smith_lambda.h).
//
// The weight depends on s only through u = <s, d> ~ N(mu, sigma^2),
// mu = <m, d>, sigma^2 = d^T Sigma d: in z = (u - mu) / sigma it is
// proportional to (k - z)_+ with k = (cot t - mu) / sigma, so u's mean and
// variance under D_s are those of a standard normal weighted by a clamped
// linear function (closed forms in erfc and exp), and the slope across d,
// which is u's linear regression plus an independent Gaussian residual, keeps
// its conditional law: exact_slope_moments gives D_s's exact mean and
// covariance (the derivation step by step: docs/slope.md). D_s itself is
// not Gaussian (it has a hard edge at <s, d> = cot t); slope_color.h filters
// colours with it exactly and with the Gaussian of these moments.
#pragma once

#include "cmfilter/util/error.h"

#include <string>

namespace cmfilter {

// Slopes s ~ N(m, Sigma): m the resolved mean slope (0 on a flat mean
// surface), Sigma the unresolved slope covariance (MicrosurfaceFootprint's
// slope_xx, slope_xy, slope_yy).
struct SlopeGaussian {
    double mean_x = 0, mean_y = 0;
    double xx = 0, xy = 0, yy = 0;
};

// omega_o = (sin theta cos phi, sin theta sin phi, cos theta), radians, in the
// frame whose z is the normal of the plane of slope 0. theta in [0, pi/2]:
// NaN reads as 0 and theta >= pi/2 as exactly pi/2 (cos theta = 0).
struct ViewAngles {
    double theta = 0, phi = 0;
};

// A mean and a covariance of slopes, in the same layout as SlopeGaussian.
struct SlopeMoments {
    double mean_x = 0, mean_y = 0;
    double xx = 0, xy = 0, yy = 0;
};

// D_s in the view's frame: u = <s, d> along the view's azimuth and
// v = <s, e> across it, e = (-sin p, cos p). p(s) factors into u ~ N(mean_u,
// sigma_u^2) and v = mean_v + regression (u - mean_u) + r, with r ~ N(0,
// residual_variance) independent of u; the weight of eq. 20 depends on u
// alone, so D_s changes u's law and keeps v's given u.
struct SlopeViewFrame {
    double cos_theta = 1, sin_theta = 0;
    double dx = 1, dy = 0;          // d; e = (-dy, dx)
    double mean_u = 0, mean_v = 0;  // <m, d>, <m, e>
    double sigma_u = 0;             // sqrt(d^T Sigma d)
    double regression = 0;          // d^T Sigma e / d^T Sigma d (0 where sigma_u = 0)
    double residual_variance = 0;   // det Sigma / d^T Sigma d (e^T Sigma e where sigma_u = 0)
    // The slope back in x and y from its coordinates (u, v).
    double slope_x(double u, double v) const { return u * dx - v * dy; }
    double slope_y(double u, double v) const { return u * dy + v * dx; }
};

SlopeViewFrame slope_view_frame(const SlopeGaussian& slopes, const ViewAngles& view);

// BadInput naming `what` for a non-finite entry, a negative variance or a
// covariance that is not positive semi-definite (xy^2 > xx yy beyond
// rounding). The functions below take any SlopeGaussian: they read NaN as 0,
// negative variances as 0 and clamp |xy| to sqrt(xx yy).
Status validate(const SlopeGaussian& slopes, const std::string& what);

// Z = int max(0, cos t - sin t <s, d>) p(s) ds (eq. 20's normalisation);
// cos t (1 + Lambda) for m = 0. 0 where every facet faces away (a spread of 0
// and <m, d> >= cot t); it underflows to 0 as the visible share vanishes.
double slope_filtering_normalisation(const SlopeGaussian& slopes, const ViewAngles& view);

// The exact mean and covariance of D_s (eq. 20), finite for every theta in
// [0, pi/2], every spread (0 included) and any mean. Where Z is 0 (a spread
// of 0 along d and <m, d> >= cot t) the limit as the spread along d vanishes
// is taken: the slopes along d sit at the horizon, <s, d> = cot t.
SlopeMoments exact_slope_moments(const SlopeGaussian& slopes, const ViewAngles& view);

}  // namespace cmfilter
