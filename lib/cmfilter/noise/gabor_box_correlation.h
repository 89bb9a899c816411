// SPDX-License-Identifier: Apache-2.0
// The box correlation (box_correlation.h) of 2-D Gabor noise (gabor_noise.h),
// in closed form up to 1-D quadratures. By Campbell's theorem the
// autocorrelation is lambda E[w^2] times that of one kernel (Lagae et al.
// 2009, sec. 3.3; derivation in docs/noise.md):
//     R(d) / R(0) = exp(-pi a^2 |d|^2 / 2) (c(d) + E) / (1 + E),  E = exp(-2 pi F0^2 / a^2),
// with c(d) = cos(2 pi F0 <omega, d>) for a fixed orientation omega and
// c(d) = J0(2 pi F0 |d|) (its average over orientations) for isotropic noise.
// Over a square [-h, h]^2, h = k p / 2 (p = GaborNoise::period()), the
// Gaussian factorises and the odd sine terms vanish:
//     integral of exp(...) cos(<theta, d>) = I(theta_x) I(theta_y),
//     I(theta) = integral over [-h, h] of exp(-pi a^2 t^2 / 2) cos(theta t) dt,
// and the isotropic case averages I(theta cos phi) I(theta sin phi) over phi
// in [0, pi/2]. Each I is integrated with 8-point Gauss-Legendre on panels of
// at most a quarter wavelength, out to where the envelope is below e^-75.
#pragma once

#include "cmfilter/noise/box_correlation.h"
#include "cmfilter/noise/gabor_noise.h"

namespace cmfilter {

BoxCorrelation gabor_noise_box_correlation(const GaborNoiseOptions& options);

}  // namespace cmfilter
