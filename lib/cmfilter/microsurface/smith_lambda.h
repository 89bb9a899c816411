// SPDX-License-Identifier: Apache-2.0
// Masking of a microsurface with Gaussian slopes (Heitz et al. 2013, sec.
// 5.1): Smith's Lambda, eq. 3, and the mean visibility of eq. 13.
//
//   Lambda(theta) = sigma_s / (sqrt(2 pi) cot theta) exp(-cot^2 theta / (2 sigma_s^2))
//                   - erfc(cot theta / (sqrt(2) sigma_s)) / 2
//
// for the direction at angle theta from the mean normal and sigma_s the
// standard deviation of the slopes along it. Lambda is 0 at theta = 0, grows
// without bound as theta -> 90 degrees and is +infinity there (cot theta =
// 0): a grazing direction sees only the highest points. Computed without
// cancellation (as erfc's scaled form), finite for every theta < 90 degrees
// and every sigma_s > 0; sigma_s = 0 (a flat surface) gives 0 below 90
// degrees.
#pragma once

namespace cmfilter {

// theta in radians, in [0, pi/2]; beyond it the direction is below the
// surface and clamped to pi/2. sigma_s >= 0.
double smith_lambda_gaussian(double theta, double sigma_s);

// The same from mu = cot theta >= 0 (+infinity: theta = 0).
double smith_lambda_gaussian_cot(double mu, double sigma_s);

// Eq. 13: the share of the viewed microsurface that is lit,
// (1 + Lambda_o) / (1 + Lambda_o + Lambda_i), in [0, 1]. Its limits where a
// Lambda is infinite: Lambda_i = inf gives 0 (grazing light) unless Lambda_o
// is infinite too, where the limit along equal angles, 1/2, is taken;
// Lambda_o = inf alone gives 1.
double mean_visibility(double lambda_o, double lambda_i);

// Masking and shadowing as eq. 13 takes them (independent: a point's
// visibility to the viewer and to the light multiply, so the heights seen lit
// are weighted by P_h^(Lambda_o + Lambda_i)), or correlated by the
// directions' azimuths: a light behind the viewer sees what the viewer sees.
// The direction-correlated form (van Ginneken et al. 1998, in the form of
// Heitz 2014, "Understanding the masking-shadowing function in
// microfacet-based BRDFs", sec. 6) replaces the sum by
//     L = max(Lambda_o, Lambda_i) + lambda(phi) min(Lambda_o, Lambda_i),
//     lambda(phi) = 4.41 phi / (4.41 phi + 1),
// phi in [0, pi] the azimuth between the two directions: 0 (the light from
// the viewer's side) gives the larger Lambda alone, pi nearly the sum.
enum class MaskingShadowing { Uncorrelated, DirectionCorrelated };

// The Lambda sum that weights the heights seen lit, P_h^L (eq. 16): the sum
// (Uncorrelated) or the form above; phi is folded into [0, pi]. Infinite
// where either Lambda is.
double lambda_sum(double lambda_o, double lambda_i, double azimuth_difference, MaskingShadowing masking);

// The share of the viewed microsurface that is lit for that Lambda sum,
// (1 + Lambda_o) / (1 + L) (eq. 13 for the plain sum), in [0, 1], with the
// limits of mean_visibility where a Lambda is infinite (the correlated form
// at phi = 0 sees everything lit when both are).
double mean_visibility(double lambda_o, double lambda_i, double azimuth_difference, MaskingShadowing masking);

}  // namespace cmfilter
