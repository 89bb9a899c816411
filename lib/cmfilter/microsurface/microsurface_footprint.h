// SPDX-License-Identifier: Apache-2.0
// The part of a Gaussian microsurface a pixel resolves and the part it does
// not (issue: heights that are visible geometry close up, filtered far away).
// Over a pixel's footprint, the parallelogram P = {c + a e1 + b e2 : a, b in
// [-1/2, 1/2]} in the microsurface's coordinates, each cosine of the
// microsurface (gaussian_microsurface.h) a cos(2 pi <f, x> + phi) has the
// box-filtered mean
//     s a cos(2 pi <f, c> + phi),   s = sinc(pi <f, e1>) sinc(pi <f, e2>),
// (sinc x = sin x / x): the resolved height at the pixel is the sum of these,
// exact for a box pixel, and its gradient the box-filtered slopes
// (resolved_slope, apart: it costs a sine per cosine that height-coloured
// pixels do not need). What the footprint does not resolve is the spread of
// the heights about that mean: averaged over the surface, its variance is
//     sigma_u^2 = sum_k a_k^2 (1 - s_k^2) / 2,
// and the unresolved slopes have the covariance
//     S = sum_k a_k^2 (1 - s_k^2) (2 pi)^2 f_k f_k^T / 2,
// so sigma_s along the unit direction d is sqrt(d^T S d). A point footprint
// (s = 1) resolves everything (sigma_u = 0: the colour is C_h of the height
// itself); a footprint much wider than the longest wavelength resolves
// nothing (s -> 0: the mean is 0 and sigma_u = sigma_h), so the filtered
// colour is continuous from close up to far away. These are the sigma_h and
// sigma_s the height filtering distribution D_h (eqs. 15-18) and Smith's
// Lambda (eq. 3) take, about the resolved mean height. The resolved part is
// itself a Gaussian surface, the box-filtered heights, with variance
// sigma_r^2 = sum_k a_k^2 s_k^2 / 2 and slope covariance
// R = sum_k a_k^2 s_k^2 (2 pi)^2 f_k f_k^T / 2 (sigma_r^2 + sigma_u^2 =
// sigma_h^2): what a light sees of its geometry (height_filtered_albedo.h).
#pragma once

#include "cmfilter/microsurface/gaussian_microsurface.h"

namespace cmfilter {

struct MicrosurfaceFootprint {
    double mean_height = 0;                                    // resolved: the box-filtered height at the centre
    double sigma_h = 0;                                        // unresolved height deviation
    double slope_xx = 0, slope_xy = 0, slope_yy = 0;           // unresolved slope covariance S
    double resolved_sigma_h = 0;                               // sigma_r
    double resolved_xx = 0, resolved_xy = 0, resolved_yy = 0;  // resolved slope covariance R

    // The unresolved slope deviation along the unit direction (cos a, sin a).
    double sigma_s(double azimuth) const;
    // The resolved one.
    double resolved_sigma_s(double azimuth) const;
};

// The footprint centred at (u, v) with edges (e1u, e1v) and (e2u, e2v), in
// the microsurface's units; zero edges: a point.
MicrosurfaceFootprint filter_microsurface(const GaussianMicrosurface& surface, double u, double v, double e1u,
                                          double e1v, double e2u, double e2v);

// The resolved slopes over the same footprint: the gradient of the resolved
// height, the mean of (dh/dx, dh/dy) over the parallelogram.
struct ResolvedSlope {
    double x = 0, y = 0;
};
ResolvedSlope resolved_slope(const GaussianMicrosurface& surface, double u, double v, double e1u, double e1v,
                             double e2u, double e2v);

}  // namespace cmfilter
