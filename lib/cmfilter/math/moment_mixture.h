// SPDX-License-Identifier: Apache-2.0
// A footprint's distribution of f from its first four moments, as a mixture
// of two Gaussians of one common width: f ~ p N(a, s^2) + (1 - p) N(b, s^2).
// Where the paper's filtering distribution is the one Gaussian of the first
// two moments (Heitz et al. 2013, sec. 4.2), this matches the third and
// fourth central moments too, so a footprint that straddles an edge of the
// driver (two groups of values) keeps its two groups, and the colour is
//   p T(a, s) + (1 - p) T(b, s)
// with the same prefiltered table T of eq. 10, two lookups instead of one.
//
// The mixture is a two-point distribution X (atoms a < b, weights p, 1 - p)
// convolved with N(0, s^2). Cumulants add and a Gaussian has none above the
// second, so X has variance v = sigma^2 - s^2, third central moment mu3 and
// fourth cumulant k4 = mu4 - 3 sigma^4 of the whole. A two-point
// distribution has excess kurtosis = skewness^2 - 2, which in t = v /
// sigma^2, gamma^2 = mu3^2 / sigma^6, kappa = k4 / sigma^4 reads
//   2 t^3 + kappa t - gamma^2 = 0,
// whose positive root is unique (the cubic is negative at 0, convex for
// t > 0) and at most 1 for any distribution (Pearson's inequality kurtosis
// >= skewness^2 + 1 is the cubic's value at 1 being >= 0). Symmetric
// footprints with positive excess kurtosis have no such mixture but the
// Gaussian (t = 0); a two-valued footprint is a two-point distribution
// (t = 1, s = 0), which the mixture reproduces exactly.
#pragma once

namespace cmfilter {

struct MomentMixture {
    double weight = 1;  // p, the weight of the lower component a
    double lower = 0;   // a
    double upper = 0;   // b (a = b = mean when the mixture is one Gaussian)
    double sigma = 0;   // s, the width of both components
};

struct MomentMixtureOptions {
    // Below this variance the footprint is taken as one Gaussian: the third
    // and fourth moments of a float32 pyramid are rounding noise there.
    double min_variance = 0;
};

// The options for a float32 pyramid of a driver with values in [lo, hi]:
// a footprint narrower than a millionth of the range squared is one Gaussian
// (its third and fourth moments are rounding there).
inline MomentMixtureOptions pyramid_mixture_options(double lo, double hi)
{
    MomentMixtureOptions o;
    o.min_variance = 1e-6 * (hi - lo) * (hi - lo);
    return o;
}

// From the mean, the variance sigma^2 >= 0, and the third and fourth central
// moments mu3 and mu4 of a footprint. Moments outside what any distribution
// can have (mu4 < mu3^2 / sigma^2 + sigma^4, from rounding) give the
// two-point distribution nearest them (t = 1); non-finite moments give the
// Gaussian of the mean and variance. The result is finite whenever mean and
// variance are.
MomentMixture moment_mixture(double mean, double variance, double mu3, double mu4,
                             const MomentMixtureOptions& options = {});

}  // namespace cmfilter
