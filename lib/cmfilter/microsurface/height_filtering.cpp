// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/microsurface/height_filtering.h"

#include "cmfilter/math/gauss_legendre.h"
#include "cmfilter/math/normal_distribution.h"

#include <algorithm>
#include <cmath>

namespace cmfilter {

namespace {

constexpr double kPi = 3.14159265358979323846;

// d/dx ln Phi(x) = phi(x) / Phi(x).
double normal_hazard_left(double x) { return std::exp(-0.5 * x * x - 0.5 * std::log(2 * kPi) - log_normal_cdf(x)); }

}  // namespace

HeightMoments exact_height_moments(double lambda_sum, double sigma_h)
{
    const double L = std::min(std::max(0.0, std::isnan(lambda_sum) ? 0.0 : lambda_sum), 1e100);
    const double s = std::max(0.0, sigma_h);
    // The density of x = h / sigma_h: (L + 1) Phi(x)^L phi(x). Its log,
    // g(x) = ln(L + 1) + L ln Phi(x) - x^2 / 2 - ln sqrt(2 pi), is concave;
    // its peak solves L phi(x) / Phi(x) = x (Newton from sqrt(2 ln(L+1))).
    const auto log_density = [&](double x) {
        return std::log1p(L) + L * log_normal_cdf(x) - 0.5 * x * x - 0.5 * std::log(2 * kPi);
    };
    double peak = std::sqrt(2 * std::log1p(L));
    for (int k = 0; k < 60; ++k) {
        const double hz = normal_hazard_left(peak);
        const double f = L * hz - peak;
        // f'(x) = L hz (-x - hz) - 1.
        const double df = L * hz * (-peak - hz) - 1;
        const double step = f / df;
        peak -= step;
        if (std::abs(step) < 1e-14 * (1 + std::abs(peak))) break;
    }
    // Width from the curvature at the peak; integrate 14 widths each side
    // (the density falls faster than a Gaussian on the right, slower on the
    // left but still like e^{-x^2/2}), 24 panels.
    const double hz = normal_hazard_left(peak);
    const double curvature = L * hz * (peak + hz) + 1;  // -g''(x) at the peak (>= 1)
    const double width = 1.0 / std::sqrt(curvature);
    const double lo = peak - std::max(14 * width, 0.0) - (L < 1 ? 10 : 0), hi = peak + 14 * width + (L < 1 ? 4 : 0);
    const double g0 = log_density(peak);
    const auto w = [&](double x) { return std::exp(log_density(x) - g0); };
    const double m0 = gauss_legendre_8(w, lo, hi, 24);
    const double m1 = gauss_legendre_8([&](double x) { return (x - peak) * w(x); }, lo, hi, 24) / m0;
    const double m2 = gauss_legendre_8([&](double x) { return (x - peak - m1) * (x - peak - m1) * w(x); }, lo, hi, 24) /
                      m0;
    return {s * (peak + m1), s * std::sqrt(std::max(0.0, m2))};
}

HeightMoments paper_height_fit(double lambda_sum, double sigma_h)
{
    const double L = std::min(std::max(0.0, std::isnan(lambda_sum) ? 0.0 : lambda_sum), 1e100);
    const double s = std::max(0.0, sigma_h);
    return {0.39 * s * std::log(4.75 * L + 1.0),           // eq. 17
            s / (1.0 + 0.26 * std::log(1.13 * L + 1.0))};  // eq. 18 (central)
}

}  // namespace cmfilter
