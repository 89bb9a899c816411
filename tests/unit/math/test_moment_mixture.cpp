// SPDX-License-Identifier: Apache-2.0
// The two-Gaussian mixture of a footprint's first four moments
// (moment_mixture.h) against moments computed independently: sums over
// discrete distributions, and the mixture's own moments by quadrature of its
// density on a fine grid, which must be the moments it was made from.
#include "cmfilter/math/moment_mixture.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace cmfilter;

namespace {

struct Moments {
    double mean = 0, variance = 0, mu3 = 0, mu4 = 0;
};

// Of a discrete distribution, by summation.
Moments discrete_moments(const std::vector<double>& values, const std::vector<double>& weights)
{
    double total = 0, mean = 0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        total += weights[i];
        mean += weights[i] * values[i];
    }
    mean /= total;
    Moments m;
    m.mean = mean;
    for (std::size_t i = 0; i < values.size(); ++i) {
        const double d = values[i] - mean, w = weights[i] / total;
        m.variance += w * d * d;
        m.mu3 += w * d * d * d;
        m.mu4 += w * d * d * d * d;
    }
    return m;
}

// Of the mixture's density, by the trapezoidal rule over +-12 widths around
// both components (the mixture's weights, not its algebra).
Moments mixture_moments_by_quadrature(const MomentMixture& mix)
{
    const double s = mix.sigma, lo = std::min(mix.lower, mix.upper) - 12 * s,
                 hi = std::max(mix.lower, mix.upper) + 12 * s;
    const int n = 200000;
    const double h = (hi - lo) / n;
    const auto pdf = [&](double x) {
        const auto g = [&](double mu) {
            return std::exp(-0.5 * (x - mu) * (x - mu) / (s * s)) / (s * std::sqrt(2 * M_PI));
        };
        return mix.weight * g(mix.lower) + (1 - mix.weight) * g(mix.upper);
    };
    double raw[5] = {0, 0, 0, 0, 0};
    for (int i = 0; i <= n; ++i) {
        const double x = lo + i * h, w = (i == 0 || i == n ? 0.5 : 1.0) * h * pdf(x);
        double p = 1;
        for (double& r : raw) {
            r += w * p;
            p *= x;
        }
    }
    const double mean = raw[1] / raw[0];
    Moments m;
    m.mean = mean;
    // Central moments by a second pass (no cancellation between raw moments).
    for (int i = 0; i <= n; ++i) {
        const double x = lo + i * h, w = (i == 0 || i == n ? 0.5 : 1.0) * h * pdf(x) / raw[0], d = x - mean;
        m.variance += w * d * d;
        m.mu3 += w * d * d * d;
        m.mu4 += w * d * d * d * d;
    }
    return m;
}

}  // namespace

TEST_CASE("a two-valued footprint is its own mixture: the two values, their weights, width 0")
{
    for (double p : {0.5, 0.2, 0.93, 0.01}) {
        CAPTURE(p);
        const Moments m = discrete_moments({0.2, 0.85}, {p, 1 - p});
        const MomentMixture mix = moment_mixture(m.mean, m.variance, m.mu3, m.mu4);
        CHECK(mix.lower == doctest::Approx(0.2).epsilon(1e-9));
        CHECK(mix.upper == doctest::Approx(0.85).epsilon(1e-9));
        CHECK(mix.weight == doctest::Approx(p).epsilon(1e-9));
        CHECK(mix.sigma <= 1e-6);
    }
}

TEST_CASE("a Gaussian footprint, or a symmetric heavy-tailed one, stays the paper's one Gaussian")
{
    const double sigma = 0.07;
    const double v = sigma * sigma;
    // N(0.4, sigma^2): mu3 = 0, mu4 = 3 sigma^4; Laplace: mu4 = 6 sigma^4.
    for (double kurtosis : {3.0, 6.0}) {
        const MomentMixture mix = moment_mixture(0.4, v, 0, kurtosis * v * v);
        CHECK(mix.lower == doctest::Approx(0.4));
        CHECK(mix.upper == doctest::Approx(0.4));
        CHECK(mix.sigma == doctest::Approx(sigma).epsilon(1e-12));
    }
}

TEST_CASE("a mixture of two Gaussians of one width is recovered from its moments")
{
    struct Case {
        double p, a, b, s;
    };
    for (const Case c : {Case{0.5, 0.3, 0.7, 0.05}, Case{0.2, 0.1, 0.6, 0.02}, Case{0.9, -1.0, 2.0, 0.5}}) {
        CAPTURE(c.p);
        MomentMixture truth;
        truth.weight = c.p;
        truth.lower = c.a;
        truth.upper = c.b;
        truth.sigma = c.s;
        const Moments m = mixture_moments_by_quadrature(truth);
        const MomentMixture mix = moment_mixture(m.mean, m.variance, m.mu3, m.mu4);
        CHECK(mix.weight == doctest::Approx(c.p).epsilon(1e-5));
        CHECK(mix.lower == doctest::Approx(c.a).epsilon(1e-5));
        CHECK(mix.upper == doctest::Approx(c.b).epsilon(1e-5));
        CHECK(mix.sigma == doctest::Approx(c.s).epsilon(1e-4));
    }
}

TEST_CASE("for skewed footprints the mixture has the footprint's four moments")
{
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    int checked = 0;
    for (int trial = 0; trial < 40; ++trial) {
        std::vector<double> values(5), weights(5);
        for (int i = 0; i < 5; ++i) {
            values[i] = u(rng);
            weights[i] = 0.05 + u(rng);
        }
        const Moments m = discrete_moments(values, weights);
        CAPTURE(trial);
        const MomentMixture mix = moment_mixture(m.mean, m.variance, m.mu3, m.mu4);
        REQUIRE(std::isfinite(mix.weight));
        CHECK(mix.weight >= 0);
        CHECK(mix.weight <= 1);
        CHECK(mix.lower <= mix.upper);
        if (mix.sigma < 1e-3) continue;  // the quadrature needs a width
        const Moments q = mixture_moments_by_quadrature(mix);
        CHECK(q.mean == doctest::Approx(m.mean).epsilon(1e-7));
        CHECK(q.variance == doctest::Approx(m.variance).epsilon(1e-6));
        CHECK(q.mu3 == doctest::Approx(m.mu3).epsilon(1e-5).scale(m.variance * std::sqrt(m.variance)));
        CHECK(q.mu4 == doctest::Approx(m.mu4).epsilon(1e-5));
        ++checked;
    }
    CHECK(checked >= 30);
}

TEST_CASE("impossible, tiny or non-finite moments give a finite mixture")
{
    // mu4 below Pearson's bound mu3^2 / sigma^2 + sigma^4 (rounding in a float pyramid).
    const MomentMixture beyond = moment_mixture(0.5, 0.01, 0.0005, 0.5 * 0.0001);
    CHECK(std::isfinite(beyond.lower));
    CHECK(std::isfinite(beyond.upper));
    CHECK(beyond.sigma == doctest::Approx(0).epsilon(1e-12));
    MomentMixtureOptions options;
    options.min_variance = 1e-6;
    const MomentMixture tiny = moment_mixture(0.5, 1e-7, 1e-9, 1e-20, options);
    CHECK(tiny.lower == 0.5);
    CHECK(tiny.upper == 0.5);
    CHECK(tiny.sigma == doctest::Approx(std::sqrt(1e-7)));
    for (double bad : {std::nan(""), std::numeric_limits<double>::infinity()}) {
        const MomentMixture m = moment_mixture(0.5, 0.01, bad, 0.0003);
        CHECK(m.lower == 0.5);
        CHECK(m.sigma == doctest::Approx(0.1));
    }
    const MomentMixture none = moment_mixture(0.25, 0, 0, 0);
    CHECK(none.lower == 0.25);
    CHECK(none.sigma == 0);
}
