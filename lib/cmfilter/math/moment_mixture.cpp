// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/math/moment_mixture.h"

#include <algorithm>
#include <cmath>

namespace cmfilter {

namespace {

// The positive root of 2 t^3 + kappa t - gamma2 = 0, clamped to [0, 1].
double two_point_fraction(double kappa, double gamma2)
{
    if (!(gamma2 > 1e-14)) return std::clamp(std::sqrt(std::max(0.0, -kappa / 2)), 0.0, 1.0);
    const auto g = [&](double t) { return (2 * t * t + kappa) * t - gamma2; };
    if (g(1) <= 0) return 1;  // beyond Pearson's bound: the nearest two-point distribution
    // Newton from t = 1: g is convex and increasing right of its root, so the
    // iterates fall monotonically onto it.
    double t = 1;
    for (int i = 0; i < 100; ++i) {
        const double slope = 6 * t * t + kappa;
        if (!(slope > 0)) break;
        const double next = t - g(t) / slope;
        if (!(next < t)) break;
        const double step = t - next;
        t = next;
        if (step < 1e-15) break;
    }
    return std::clamp(t, 0.0, 1.0);
}

}  // namespace

MomentMixture moment_mixture(double mean, double variance, double mu3, double mu4, const MomentMixtureOptions& options)
{
    MomentMixture m;
    m.lower = m.upper = mean;
    variance = std::max(0.0, variance);
    m.sigma = std::sqrt(variance);
    if (!(variance > options.min_variance) || !(variance > 0) || !std::isfinite(mu3) || !std::isfinite(mu4)) return m;
    const double s2 = variance * variance;
    const double kappa = mu4 / s2 - 3;                  // excess kurtosis
    const double gamma2 = mu3 * mu3 / (s2 * variance);  // skewness^2
    const double t = two_point_fraction(kappa, gamma2);
    if (!(t > 0)) return m;
    const double v = t * variance;  // the two-point part's variance
    // Its skewness (2p - 1) / sqrt(p (1 - p)) = mu3 / v^1.5 gives p; the
    // atoms sit at mean - (1 - p) d and mean + p d, v = p (1 - p) d^2.
    const double skew = mu3 / (v * std::sqrt(v));
    const double p = std::isfinite(skew) ? 0.5 * (1 + skew / std::sqrt(skew * skew + 4)) : (skew > 0 ? 1.0 : 0.0);
    const double q = p * (1 - p);
    if (!(q > 0)) return m;
    m.weight = p;
    m.lower = mean - std::sqrt(v * (1 - p) / p);
    m.upper = mean + std::sqrt(v * p / (1 - p));
    m.sigma = std::sqrt(std::max(0.0, variance - v));
    return m;
}

}  // namespace cmfilter
