// SPDX-License-Identifier: Apache-2.0
// Smith's Lambda for Gaussian slopes (eq. 3), the mean visibility (eq. 13)
// and the moments of the height filtering distribution (eqs. 15-18), each
// against an independent computation: Lambda as Smith's integral
// (1/mu) int_mu^inf (q - mu) p(q) dq by the trapezoid rule; the moments of
// D_h in the variable t of u = P_h(h) = exp(-t / (L + 1)), t ~ Exp(1),
// with an inverse normal CDF by bisection; the closed forms of the largest
// of two and three normals; and the paper's fit as printed.
#include "cmfilter/microsurface/height_filtering.h"
#include "cmfilter/microsurface/height_moment_table.h"
#include "cmfilter/microsurface/smith_lambda.h"

#include <doctest/doctest.h>

#include <cmath>
#include <algorithm>
#include <limits>
#include <random>
#include <vector>

using namespace cmfilter;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Smith's Lambda for slopes q ~ N(0, s^2) along the direction, cot theta = mu.
double smith_integral(double mu, double s)
{
    const int n = 200000;
    const double hi = mu + 40 * s, h = (hi - mu) / n;
    double sum = 0;
    for (int k = 0; k <= n; ++k) {
        const double q = mu + k * h;
        const double f = (q - mu) * std::exp(-q * q / (2 * s * s)) / (s * std::sqrt(2 * kPi));
        sum += (k == 0 || k == n) ? 0.5 * f : f;
    }
    return sum * h / mu;
}

// The standard normal quantile by bisection on erfc (slow, independent).
double normal_quantile(double u)
{
    double lo = -40, hi = 40;
    for (int k = 0; k < 64; ++k) {
        const double mid = 0.5 * (lo + hi);
        (0.5 * std::erfc(-mid / std::sqrt(2.0)) < u ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// Mean and central sd of x = P^-1(u), u = exp(-t / (L + 1)), t ~ Exp(1):
// u then has density (L + 1) u^L on [0, 1], D_h in the variable u.
// Midpoint rule in v = 1 - e^{-t} (uniform), with the tail cut where u
// would round to 1.
HeightMoments moments_by_exponential(double L)
{
    const int n = 200000;
    double m1 = 0, m2 = 0;
    for (int k = 0; k < n; ++k) {
        const double v = (k + 0.5) / n;  // v uniform: t = -ln(1 - v)
        const double t = -std::log1p(-v);
        const double logu = -t / (L + 1);  // ln u
        // x = Phi^-1(u) with u = e^{logu}: close to 1 read from its complement.
        const double x = logu > -1e-3 ? -normal_quantile(-std::expm1(logu)) : normal_quantile(std::exp(logu));
        m1 += x;
        m2 += x * x;
    }
    m1 /= n;
    m2 = m2 / n - m1 * m1;
    return {m1, std::sqrt(m2)};
}

}  // namespace

TEST_CASE("Smith Lambda for Gaussian slopes matches Smith's integral, is 0 head-on and infinite at 90 degrees")
{
    for (double s : {0.05, 0.3, 1.0, 3.0})
        for (double theta_deg : {10.0, 30.0, 50.0, 70.0, 85.0, 89.0}) {
            const double mu = 1.0 / std::tan(theta_deg * kPi / 180);
            CAPTURE(s);
            CAPTURE(theta_deg);
            const double expected = smith_integral(mu, s);
            const double got = smith_lambda_gaussian(theta_deg * kPi / 180, s);
            CHECK(got == doctest::Approx(expected).epsilon(1e-6).scale(1e-12));
        }
    CHECK(smith_lambda_gaussian(0, 0.5) == 0);
    CHECK(std::isinf(smith_lambda_gaussian(kPi / 2, 0.5)));
    CHECK(smith_lambda_gaussian(kPi, 0.5) == smith_lambda_gaussian(kPi / 2, 0.5));
    CHECK(smith_lambda_gaussian(0.3, 0) == 0);
    // Monotone and finite below 90 degrees, for small and large slopes.
    for (double s : {1e-6, 1e-3, 0.2, 10.0, 1e3}) {
        double previous = 0;
        for (int k = 0; k < 9000; ++k) {
            const double theta = k * (kPi / 2) / 9000;
            const double lambda = smith_lambda_gaussian(theta, s);
            CHECK(std::isfinite(lambda));
            CHECK(lambda >= previous - 1e-15 * (1 + previous));
            previous = lambda;
        }
    }
}

TEST_CASE("mean visibility is eq. 13 and stays in 0 to 1 at grazing angles")
{
    CHECK(mean_visibility(0, 0) == 1);
    CHECK(mean_visibility(1, 2) == doctest::Approx(0.5));
    const double inf = std::numeric_limits<double>::infinity();
    CHECK(mean_visibility(0.3, inf) == 0);
    CHECK(mean_visibility(inf, 0.3) == 1);
    CHECK(mean_visibility(inf, inf) == 0.5);
    CHECK(mean_visibility(1e6, 1e6) == doctest::Approx(0.5).epsilon(1e-5));
}

TEST_CASE("height filtering moments match an independent quadrature from L = 0 to 1e6")
{
    // The largest of n normals: n = 2, mean 1/sqrt(pi), variance 1 - 1/pi;
    // n = 3, mean 3 / (2 sqrt(pi)).
    const HeightMoments two = exact_height_moments(1, 1);
    CHECK(two.mean == doctest::Approx(1 / std::sqrt(kPi)).epsilon(1e-9));
    CHECK(two.sigma == doctest::Approx(std::sqrt(1 - 1 / kPi)).epsilon(1e-9));
    CHECK(exact_height_moments(2, 1).mean == doctest::Approx(1.5 / std::sqrt(kPi)).epsilon(1e-9));
    const HeightMoments none = exact_height_moments(0, 2.5);
    CHECK(std::abs(none.mean) < 1e-9);
    CHECK(none.sigma == doctest::Approx(2.5).epsilon(1e-9));

    for (double L : {0.25, 0.5, 3.0, 10.0, 100.0, 1e3, 1e4, 1e5, 1e6}) {
        CAPTURE(L);
        const HeightMoments got = exact_height_moments(L, 1);
        const HeightMoments expected = moments_by_exponential(L);
        CHECK(got.mean == doctest::Approx(expected.mean).epsilon(1e-4));
        CHECK(got.sigma == doctest::Approx(expected.sigma).epsilon(1e-4));
        // sigma_h scales both.
        const HeightMoments scaled = exact_height_moments(L, 0.3);
        CHECK(scaled.mean == doctest::Approx(0.3 * got.mean).epsilon(1e-12));
        CHECK(scaled.sigma == doctest::Approx(0.3 * got.sigma).epsilon(1e-12));
    }
}

TEST_CASE("height filtering moments stay finite from L = 0 to infinity and for a flat surface")
{
    for (double L : {0.0, 1e-12, 1e-3, 1.0, 1e6, 1e12, 1e100, 1e300, std::numeric_limits<double>::infinity()}) {
        CAPTURE(L);
        for (double s : {0.0, 1e-9, 1.0, 1e6}) {
            const HeightMoments e = exact_height_moments(L, s);
            const HeightMoments f = paper_height_fit(L, s);
            CHECK(std::isfinite(e.mean));
            CHECK(std::isfinite(e.sigma));
            CHECK(std::isfinite(f.mean));
            CHECK(std::isfinite(f.sigma));
            CHECK(e.sigma >= 0);
        }
    }
}

TEST_CASE("the paper's fit is eqs. 17-18 as published")
{
    for (double L : {0.0, 0.5, 2.0, 40.0, 1e4}) {
        CAPTURE(L);
        const HeightMoments f = paper_height_fit(L, 0.7);
        CHECK(f.mean == doctest::Approx(0.39 * 0.7 * std::log(4.75 * L + 1)));
        CHECK(f.sigma == doctest::Approx(0.7 / (1 + 0.26 * std::log(1.13 * L + 1))));
    }
}

TEST_CASE("the height moment table is within 1e-4 of the exact moments up to L = 1e6")
{
    auto table = HeightMomentTable::create();
    REQUIRE(table);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> log_l(-6, 6);
    double worst = 0;
    for (int k = 0; k < 2000; ++k) {
        const double L = std::pow(10.0, log_l(rng));
        const HeightMoments got = table->lookup(L, 2.0), exact = exact_height_moments(L, 2.0);
        // Relative, but absolute (in sigma_h) near a zero mean.
        worst = std::max(worst, std::abs(got.mean - exact.mean) / std::max(std::abs(exact.mean), 2.0));
        worst = std::max(worst, std::abs(got.sigma - exact.sigma) / exact.sigma);
    }
    CAPTURE(worst);
    CHECK(worst < 1e-4);
    // Ends: L = 0 is N(0, sigma_h^2); beyond the last node, the last node.
    CHECK(std::abs(table->lookup(0, 1).mean) < 1e-9);
    CHECK(table->lookup(0, 1).sigma == doctest::Approx(1).epsilon(1e-9));
    CHECK(table->lookup(std::numeric_limits<double>::infinity(), 1).mean == table->lookup(1e6, 1).mean);
    CHECK(std::isfinite(table->lookup(std::nan(""), 1).mean));
    // A coarse table misses the bound: the test can fail.
    HeightMomentTableOptions coarse;
    coarse.nodes = 16;
    auto rough = HeightMomentTable::create(coarse);
    REQUIRE(rough);
    CHECK(std::abs(rough->lookup(3.3, 1).mean - exact_height_moments(3.3, 1).mean) > 1e-4);
    coarse.nodes = 1;
    CHECK_FALSE(HeightMomentTable::create(coarse));
}
