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

}  // namespace cmfilter
