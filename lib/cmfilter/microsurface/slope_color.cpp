// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/microsurface/slope_color.h"

#include "cmfilter/math/gauss_hermite.h"
#include "cmfilter/math/gauss_legendre.h"
#include "cmfilter/microsurface/light_weighted_slope_map.h"

#include <algorithm>
#include <cmath>

namespace cmfilter {

namespace {

constexpr double kPi = 3.14159265358979323846;

double standard_normal_density(double z) { return std::exp(-0.5 * z * z) / std::sqrt(2 * kPi); }

}  // namespace

template <typename SlopeMap>
Rgb gaussian_slope_color(const SlopeMap& map, const SlopeGaussian& slopes, const ViewAngles& view,
                         const GaussianSlopeColorOptions& options)
{
    const SlopeMoments m = exact_slope_moments(slopes, view);
    // Principal axes of the covariance: angle a with tan 2a = 2 xy / (xx - yy),
    // variances along (cos a, sin a) and (-sin a, cos a).
    const double angle = 0.5 * std::atan2(2 * m.xy, m.xx - m.yy);
    const double c = std::cos(angle), s = std::sin(angle);
    const double major = std::sqrt(std::max(0.0, m.xx * c * c + 2 * m.xy * c * s + m.yy * s * s));
    const double minor = std::sqrt(std::max(0.0, m.xx * s * s - 2 * m.xy * c * s + m.yy * c * c));
    const GaussHermiteRule rule = gauss_hermite_rule(options.points_per_axis);
    Rgb sum;
    for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
        const double p = major * rule.nodes[i];
        Rgb row;
        for (std::size_t j = 0; j < rule.nodes.size(); ++j) {
            const double q = minor * rule.nodes[j];
            row += rule.weights[j] * map.evaluate(m.mean_x + p * c - q * s, m.mean_y + p * s + q * c);
        }
        sum += rule.weights[i] * row;
    }
    return sum;
}

template <typename SlopeMap>
Rgb exact_slope_color(const SlopeMap& map, const SlopeGaussian& slopes, const ViewAngles& view,
                      const ExactSlopeColorOptions& options)
{
    const int panels = std::max(1, options.panels);
    const SlopeViewFrame f = slope_view_frame(slopes, view);
    const double residual = std::sqrt(f.residual_variance);
    // The colour at u, averaged over the residual across d (eq. 20's inner
    // integral), and the residual's total weight for the normalisation.
    const auto across = [&](double u) {
        const double centre = f.mean_v + f.regression * (u - f.mean_u);
        const auto at = [&](double w) {
            const double v = centre + residual * w;
            return standard_normal_density(w) * map.evaluate(f.slope_x(u, v), f.slope_y(u, v));
        };
        return gauss_legendre_8(at, -9.0, 9.0, panels);
    };
    const double across_weight = gauss_legendre_8(standard_normal_density, -9.0, 9.0, panels);
    // u's law under D_s: a weight over a parameter t, and u(t).
    const double a = f.cos_theta, b = f.sin_theta;
    const double margin = a - b * f.mean_u, scale = b * f.sigma_u;
    const auto average = [&](auto weight, auto u_of, double lo, double hi) {
        const Rgb sum = gauss_legendre_8([&](double t) { return weight(t) * across(u_of(t)); }, lo, hi, panels);
        const double total = gauss_legendre_8(weight, lo, hi, panels) * across_weight;
        return (1 / total) * sum;
    };
    if (!(scale > 0)) {
        // No weighting (D_s = p), or the limit at the horizon (slope_filtering.h).
        if (margin <= 0) return (1 / across_weight) * across(a / b);
        if (!(f.sigma_u > 0)) return (1 / across_weight) * across(f.mean_u);
        return average(
            standard_normal_density, [&](double z) { return f.mean_u + f.sigma_u * z; }, -9.0, 9.0);
    }
    const double k = margin / scale;
    if (k >= 0) {
        // z = (u - mean_u) / sigma_u, weight (k - z)_+ phi(z), scaled by 1/k
        // for k >= 1 so that a spread going to 0 (k -> inf) stays finite.
        const auto u_of = [&](double z) { return f.mean_u + f.sigma_u * z; };
        if (k >= 1) {
            return average([k](double z) { return (1 - z / k) * standard_normal_density(z); }, u_of, -9.0,
                           std::min(k, 9.0));
        }
        return average([k](double z) { return (k - z) * standard_normal_density(z); }, u_of, -9.0, k);
    }
    // Beyond the mean: y = k - z >= 0, weight y e^{-x y - y^2/2} (phi(k)
    // factored out), u = cot t - sigma_u y; it is below e^{-40} of its peak
    // past y = min(9, 40 / x).
    const double x = -k;
    const double reach = std::min(9.0, 40.0 / x);
    return average([x](double y) { return y * std::exp(-x * y - 0.5 * y * y); },
                   [&](double y) { return a / b - f.sigma_u * y; }, 0.0, reach);
}

template Rgb gaussian_slope_color(const SteepnessColorMap&, const SlopeGaussian&, const ViewAngles&,
                                  const GaussianSlopeColorOptions&);
template Rgb gaussian_slope_color(const SlopeVectorColorMap&, const SlopeGaussian&, const ViewAngles&,
                                  const GaussianSlopeColorOptions&);
template Rgb exact_slope_color(const SteepnessColorMap&, const SlopeGaussian&, const ViewAngles&,
                               const ExactSlopeColorOptions&);
template Rgb exact_slope_color(const SlopeVectorColorMap&, const SlopeGaussian&, const ViewAngles&,
                               const ExactSlopeColorOptions&);
// The light-weighted maps (light_weighted_slope_map.h).
template Rgb gaussian_slope_color(const LightWeightedSlopeMap<SteepnessColorMap>&, const SlopeGaussian&,
                                  const ViewAngles&, const GaussianSlopeColorOptions&);
template Rgb gaussian_slope_color(const LightWeightedSlopeMap<SlopeVectorColorMap>&, const SlopeGaussian&,
                                  const ViewAngles&, const GaussianSlopeColorOptions&);
template Rgb gaussian_slope_color(const LightCosineSlopeMap&, const SlopeGaussian&, const ViewAngles&,
                                  const GaussianSlopeColorOptions&);
template Rgb exact_slope_color(const LightWeightedSlopeMap<SteepnessColorMap>&, const SlopeGaussian&, const ViewAngles&,
                               const ExactSlopeColorOptions&);
template Rgb exact_slope_color(const LightWeightedSlopeMap<SlopeVectorColorMap>&, const SlopeGaussian&,
                               const ViewAngles&, const ExactSlopeColorOptions&);
template Rgb exact_slope_color(const LightCosineSlopeMap&, const SlopeGaussian&, const ViewAngles&,
                               const ExactSlopeColorOptions&);

}  // namespace cmfilter
