// SPDX-License-Identifier: Apache-2.0
// The standard normal distribution's CDF Phi in log form and its quantile,
// for the height filtering distribution (height_filtering.h,
// height_color.h), whose CDF is Phi^(L + 1).
#pragma once

namespace cmfilter {

// ln Phi(x), accurate in both tails: the complement through log1p on the
// right, erfc itself on the left, the Mills-ratio series
// Phi(x) ~ phi(x) / |x| (1 - 1/x^2 + 3/x^4 - 15/x^6) where erfc underflows.
double log_normal_cdf(double x);

// Phi^-1: Acklam's rational approximation refined by one Halley step on
// erfc, accurate to about 1e-15 relative over (0, 1); -inf at 0, +inf at 1,
// NaN outside [0, 1].
double normal_quantile(double p);

}  // namespace cmfilter
