// SPDX-License-Identifier: Apache-2.0
// The slope filtering distribution D_s of eq. 20 (slope_filtering.h): its
// exact mean and covariance against a 2-D Gauss-Legendre quadrature of the
// definition itself (the facet normal n(s), max(0, <omega_o, n>) / <z, n>
// and the 2-D Gaussian density through the inverse covariance), its
// normalisation against cos theta (1 + Lambda) from Smith's Lambda (eq. 3),
// and finite values over sweeps into every corner: theta = 90 degrees,
// vanishing and huge spreads, near-singular covariances, large mean slopes.
#include "cmfilter/microsurface/slope_filtering.h"

#include "cmfilter/math/gauss_legendre.h"
#include "cmfilter/microsurface/smith_lambda.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

using namespace cmfilter;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct QuadratureMoments {
    double Z = 0, mean_x = 0, mean_y = 0, xx = 0, xy = 0, yy = 0;
};

// The integrals of 1, s_x, s_y, s_x^2, s_x s_y, s_y^2 at once.
struct Sums {
    double v[6] = {0, 0, 0, 0, 0, 0};
    Sums& operator+=(const Sums& o)
    {
        for (int i = 0; i < 6; ++i) v[i] += o.v[i];
        return *this;
    }
    friend Sums operator+(Sums a, const Sums& b) { return a += b; }
    friend Sums operator*(double k, Sums a)
    {
        for (double& x : a.v) x *= k;
        return a;
    }
};

// int f(s) max(0, <omega_o, n(s)>) / <z, n(s)> p(s) ds for f = 1, s_x, s_y
// and the second moments, p the density of N(m, Sigma) (Sigma invertible),
// by Gauss-Legendre in coordinates (u, v) along and across the view's
// azimuth, u cut where <omega_o, n> changes sign (found by bisection on the
// definition) so that the integrand is smooth on every panel. Ranges: 10
// marginal standard deviations about the mean.
QuadratureMoments quadrature_moments(const SlopeGaussian& g, double theta, double phi, int panels_u, int panels_v)
{
    const double ox = std::sin(theta) * std::cos(phi), oy = std::sin(theta) * std::sin(phi), oz = std::cos(theta);
    const double det = g.xx * g.yy - g.xy * g.xy;
    const double ixx = g.yy / det, ixy = -g.xy / det, iyy = g.xx / det;
    const auto weighted_density = [&](double sx, double sy) {
        const double len = std::sqrt(1 + sx * sx + sy * sy);
        const double nx = -sx / len, ny = -sy / len, nz = 1 / len;
        const double w = std::max(0.0, ox * nx + oy * ny + oz * nz) / nz;
        const double dx = sx - g.mean_x, dy = sy - g.mean_y;
        const double q = ixx * dx * dx + 2 * ixy * dx * dy + iyy * dy * dy;
        return w * std::exp(-0.5 * q) / (2 * kPi * std::sqrt(det));
    };
    const double cx = std::cos(phi), cy = std::sin(phi);
    const auto sx_of = [&](double u, double v) { return u * cx - v * cy; };
    const auto sy_of = [&](double u, double v) { return u * cy + v * cx; };
    const double mu_u = g.mean_x * cx + g.mean_y * cy, mu_v = -g.mean_x * cy + g.mean_y * cx;
    const double su = std::sqrt(g.xx * cx * cx + 2 * g.xy * cx * cy + g.yy * cy * cy);
    const double sv = std::sqrt(g.xx * cy * cy - 2 * g.xy * cx * cy + g.yy * cx * cx);
    // The horizon along u: where the weight reaches 0 (none below 90 degrees
    // of a flat view), by bisection on <omega_o, n(u d)>.
    double u_hi = mu_u + 10 * su;
    const auto facing = [&](double u) { return ox * -sx_of(u, 0) + oy * -sy_of(u, 0) + oz > 0; };
    if (!facing(u_hi)) {
        double lo = std::min(mu_u, 0.0) - 10 * su - 1, hi = u_hi;
        for (int k = 0; k < 200; ++k) {
            const double mid = 0.5 * (lo + hi);
            (facing(mid) ? lo : hi) = mid;
        }
        u_hi = 0.5 * (lo + hi);
    }
    const double u_lo = std::min(mu_u, u_hi) - 10 * su;
    const double v_lo = mu_v - 10 * sv, v_hi = mu_v + 10 * sv;
    const Sums sum = gauss_legendre_8(
        [&](double u) {
        return gauss_legendre_8(
            [&](double v) {
            const double x = sx_of(u, v), y = sy_of(u, v), w = weighted_density(x, y);
            return Sums{{w, w * x, w * y, w * x * x, w * x * y, w * y * y}};
            },
            v_lo, v_hi, panels_v);
        },
        u_lo, u_hi, panels_u);
    QuadratureMoments r;
    const double* s = sum.v;
    r.Z = s[0];
    r.mean_x = s[1] / s[0];
    r.mean_y = s[2] / s[0];
    r.xx = s[3] / s[0] - r.mean_x * r.mean_x;
    r.xy = s[4] / s[0] - r.mean_x * r.mean_y;
    r.yy = s[5] / s[0] - r.mean_y * r.mean_y;
    return r;
}

SlopeGaussian isotropic(double sigma, double mx = 0, double my = 0)
{
    return {mx, my, sigma * sigma, 0, sigma * sigma};
}

// sigma along x, sigma / 3 along y, correlation 0.6.
SlopeGaussian anisotropic(double sigma, double mx = 0, double my = 0)
{
    const double sy = sigma / 3;
    return {mx, my, sigma * sigma, 0.6 * sigma * sy, sy * sy};
}

bool finite(const SlopeMoments& m)
{
    return std::isfinite(m.mean_x) && std::isfinite(m.mean_y) && std::isfinite(m.xx) && std::isfinite(m.xy) &&
           std::isfinite(m.yy);
}

}  // namespace

TEST_CASE("the definition's quadrature gives back the slope Gaussian at normal incidence")
{
    // A check of the test's own quadrature: at theta = 0 the weight is 1.
    const SlopeGaussian g = anisotropic(0.5, 0.2, -0.1);
    const QuadratureMoments q = quadrature_moments(g, 0, 0.3, 40, 40);
    CHECK(q.Z == doctest::Approx(1).epsilon(1e-12));
    CHECK(q.mean_x == doctest::Approx(0.2).epsilon(1e-12));
    CHECK(q.mean_y == doctest::Approx(-0.1).epsilon(1e-12));
    CHECK(q.xx == doctest::Approx(g.xx).epsilon(1e-10));
    CHECK(q.xy == doctest::Approx(g.xy).epsilon(1e-10));
    CHECK(q.yy == doctest::Approx(g.yy).epsilon(1e-10));
}

TEST_CASE("exact slope moments match 2-D quadrature of eq. 20 up to 89.9 degrees")
{
    int compared = 0;
    double worst = 0;
    for (int shape = 0; shape < 2; ++shape) {
        for (const double mean_scale : {0.0, 1.0}) {
            for (double sigma : {0.1, 0.3, 0.6, 1.0}) {
                // A nonzero mean of (0.2, -0.1): facing away beyond
                // cot theta = <m, d> (k < 0) at the steepest views.
                const double mx = 0.2 * mean_scale, my = -0.1 * mean_scale;
                const SlopeGaussian g = shape == 0 ? isotropic(sigma, mx, my) : anisotropic(sigma, mx, my);
                for (double degrees : {0.0, 15.0, 40.0, 60.0, 75.0, 85.0, 89.0, 89.9}) {
                    for (double phi : {0.0, 2.2, 4.0}) {
                        const double theta = degrees * kPi / 180;
                        CAPTURE(shape);
                        CAPTURE(sigma);
                        CAPTURE(mean_scale);
                        CAPTURE(degrees);
                        CAPTURE(phi);
                        const SlopeMoments m = exact_slope_moments(g, {theta, phi});
                        const QuadratureMoments q = quadrature_moments(g, theta, phi, 32, 32);
                        // Relative, with an absolute floor near zero: 1e-9 of
                        // the slopes' own scale (their standard deviation, or
                        // its square).
                        const double scale = std::sqrt(g.xx + g.yy);
                        const auto close = [&](double value, double reference, double floor) {
                            const double error = std::abs(value - reference) / std::max(std::abs(reference), floor);
                            worst = std::max(worst, error);
                            return error <= 1e-9;
                        };
                        CHECK(close(slope_filtering_normalisation(g, {theta, phi}), q.Z, 0));
                        CHECK(close(m.mean_x, q.mean_x, scale));
                        CHECK(close(m.mean_y, q.mean_y, scale));
                        CHECK(close(m.xx, q.xx, scale * scale));
                        CHECK(close(m.xy, q.xy, scale * scale));
                        CHECK(close(m.yy, q.yy, scale * scale));
                        ++compared;
                    }
                }
            }
        }
    }
    CHECK(compared == 2 * 2 * 4 * 8 * 3);
    MESSAGE("worst relative difference: " << worst);
}

TEST_CASE("exact slope moments match quadrature for a mean slope far beyond the horizon")
{
    // <m, d> = 1.52 against cot 60 deg = 0.577: the visible slopes lie in the
    // Gaussian's tail, k = (cot theta - <m, d>) / sigma_u = -1.9, -4.7 and
    // -9.3 (the Mills-ratio branch, then the continued fraction).
    double worst = 0;
    for (double sigma : {0.1, 0.2, 0.5}) {
        CAPTURE(sigma);
        const SlopeGaussian g = anisotropic(sigma, 1.5, 0.3);
        const double theta = 60 * kPi / 180, phi = 0.1;
        const SlopeMoments m = exact_slope_moments(g, {theta, phi});
        const QuadratureMoments q = quadrature_moments(g, theta, phi, 160, 48);
        const double pairs[6][2] = {{slope_filtering_normalisation(g, {theta, phi}), q.Z},
                                    {m.mean_x, q.mean_x},
                                    {m.mean_y, q.mean_y},
                                    {m.xx, q.xx},
                                    {m.xy, q.xy},
                                    {m.yy, q.yy}};
        for (const auto& p : pairs) {
            const double error = std::abs(p[0] - p[1]) / std::abs(p[1]);
            worst = std::max(worst, error);
            CHECK(error <= 1e-9);
        }
    }
    MESSAGE("worst relative difference beyond the horizon: " << worst);
}

TEST_CASE("the normalisation is cos theta (1 + Lambda) for a zero mean slope")
{
    for (double sigma : {0.05, 0.1, 0.3, 0.6, 1.0, 3.0}) {
        for (double degrees : {0.0, 5.0, 30.0, 60.0, 80.0, 89.0, 89.9, 89.999}) {
            for (double phi : {0.0, 1.0, 2.5}) {
                CAPTURE(sigma);
                CAPTURE(degrees);
                CAPTURE(phi);
                const double theta = degrees * kPi / 180;
                for (const SlopeGaussian& g : {isotropic(sigma), anisotropic(sigma)}) {
                    // Smith's Lambda takes sigma_s along the view's azimuth.
                    const double c = std::cos(phi), s = std::sin(phi);
                    const double sigma_s = std::sqrt(g.xx * c * c + 2 * g.xy * c * s + g.yy * s * s);
                    const double expected = std::cos(theta) * (1 + smith_lambda_gaussian(theta, sigma_s));
                    CHECK(slope_filtering_normalisation(g, {theta, phi}) == doctest::Approx(expected).epsilon(1e-12));
                }
            }
        }
    }
    // At 90 degrees cos theta (1 + Lambda) -> sigma_s / sqrt(2 pi) (eq. 3's
    // first term times cos theta, sin theta -> 1): the mean of max(0, -u).
    const SlopeGaussian g = anisotropic(0.4);
    CHECK(slope_filtering_normalisation(g, {kPi / 2, 0}) == doctest::Approx(0.4 / std::sqrt(2 * kPi)).epsilon(1e-14));
}

TEST_CASE("exact slope moments leave the Gaussian as it is at normal incidence")
{
    const SlopeGaussian g = anisotropic(0.7, 0.3, -0.2);
    const SlopeMoments m = exact_slope_moments(g, {0, 1.3});
    CHECK(m.mean_x == doctest::Approx(g.mean_x).epsilon(1e-15));
    CHECK(m.mean_y == doctest::Approx(g.mean_y).epsilon(1e-15));
    CHECK(m.xx == doctest::Approx(g.xx).epsilon(1e-15));
    CHECK(m.xy == doctest::Approx(g.xy).epsilon(1e-15));
    CHECK(m.yy == doctest::Approx(g.yy).epsilon(1e-15));
}

TEST_CASE("exact slope moments tend to their limits as the spread vanishes")
{
    // Facing the viewer (<m, d> < cot theta): D_s -> the point mass at m.
    const SlopeGaussian facing = isotropic(1e-9, 0.2, 0.1);
    const SlopeMoments a = exact_slope_moments(facing, {1.0, 0.0});
    CHECK(a.mean_x == doctest::Approx(0.2).epsilon(1e-8));
    CHECK(a.mean_y == doctest::Approx(0.1).epsilon(1e-8));
    CHECK(a.xx <= 1.1e-18);
    CHECK(a.yy <= 1.1e-18);
    // Turned away (<m, d> = 2 > cot 60 deg): the visible slopes crowd at the
    // horizon, <s, d> -> cot theta, spread -> 0; across d the mean stays.
    const SlopeGaussian away = isotropic(1e-9, 2.0, 0.5);
    const SlopeMoments b = exact_slope_moments(away, {kPi / 3, 0.0});
    CHECK(b.mean_x == doctest::Approx(1 / std::tan(kPi / 3)).epsilon(1e-8));
    CHECK(b.mean_y == doctest::Approx(0.5).epsilon(1e-12));
    CHECK(b.xx <= 1e-30);
    CHECK(slope_filtering_normalisation(away, {kPi / 3, 0.0}) == 0);
    // A spread of exactly 0 gives the same limits.
    const SlopeGaussian flat{2.0, 0.5, 0, 0, 0};
    const SlopeMoments c = exact_slope_moments(flat, {kPi / 3, 0.0});
    CHECK(c.mean_x == doctest::Approx(1 / std::tan(kPi / 3)).epsilon(1e-14));
    CHECK(c.mean_y == 0.5);
    CHECK(c.xx == 0);
}

TEST_CASE(
    "exact slope moments are finite over theta to exactly 90 degrees, any spread, near-singular covariances and large means")
{
    int checked = 0;
    for (double theta : {0.0, 1e-9, 0.3, 1.0, 1.5, 1.5707, kPi / 2 - 1e-12, kPi / 2, 2.0, 1e300}) {
        for (double sigma : {0.0, 1e-300, 1e-150, 1e-12, 1e-4, 0.1, 1.0, 10.0, 1e3, 1e150}) {
            for (double ratio : {1.0, 1e-6, 1e-12, 0.0}) {
                for (double correlation : {0.0, 0.999999, -1.0}) {
                    for (double mean : {0.0, 0.3, -0.3, 5.0, 1e3, -1e3, 1e100}) {
                        for (double phi : {0.0, 0.8, kPi / 2, 3.0}) {
                            const double sy = sigma * ratio;
                            const SlopeGaussian g{mean, -0.5 * mean, sigma * sigma, correlation * sigma * sy, sy * sy};
                            const SlopeMoments m = exact_slope_moments(g, {theta, phi});
                            const double Z = slope_filtering_normalisation(g, {theta, phi});
                            CAPTURE(theta);
                            CAPTURE(sigma);
                            CAPTURE(ratio);
                            CAPTURE(correlation);
                            CAPTURE(mean);
                            CAPTURE(phi);
                            REQUIRE(finite(m));
                            REQUIRE(std::isfinite(Z));
                            REQUIRE(Z >= 0);
                            REQUIRE(m.xx >= 0);
                            REQUIRE(m.yy >= 0);
                            // Positive semi-definite up to rounding relative to
                            // the largest entry (the frame's rotation leaves
                            // errors of about 1e-16 of it in the smallest).
                            const double largest = m.xx + m.yy;
                            REQUIRE(m.xy * m.xy <= m.xx * m.yy + 1e-12 * largest * largest);
                            ++checked;
                        }
                    }
                }
            }
        }
    }
    CHECK(checked == 10 * 10 * 4 * 3 * 7 * 4);
}

TEST_CASE("slope Gaussians that are not finite or not positive semi-definite are refused")
{
    CHECK(validate(SlopeGaussian{0, 0, 1, 0.5, 1}, "slopes"));
    CHECK(validate(SlopeGaussian{0, 0, 0, 0, 0}, "slopes"));
    const Status nan = validate(SlopeGaussian{std::nan(""), 0, 1, 0, 1}, "slopes");
    REQUIRE_FALSE(nan);
    CHECK(nan.error().kind == ErrorKind::BadInput);
    CHECK(nan.error().message.find("slopes") != std::string::npos);
    CHECK_FALSE(validate(SlopeGaussian{0, 0, -1, 0, 1}, "slopes"));
    const Status indefinite = validate(SlopeGaussian{0, 0, 1, 1.5, 1}, "slopes");
    REQUIRE_FALSE(indefinite);
    CHECK(indefinite.error().message.find("positive semi-definite") != std::string::npos);
}

TEST_CASE("the continued fraction and the Mills-ratio forms agree where they meet")
{
    // k = (cot theta - <m, d>) / sigma = -3 exactly (the continued fraction)
    // and one ulp of <m, d> closer (the Mills ratio through erfcx): the two
    // evaluations of u's law under D_s meet there.
    const double theta = kPi / 4, cot = 1 / std::tan(theta);
    const double at = cot + 3, below = std::nextafter(at, 0.0);
    const SlopeGaussian a{at, 0, 1, 0.3, 0.5}, b{below, 0, 1, 0.3, 0.5};
    const SlopeMoments ma = exact_slope_moments(a, {theta, 0}), mb = exact_slope_moments(b, {theta, 0});
    const double za = slope_filtering_normalisation(a, {theta, 0}), zb = slope_filtering_normalisation(b, {theta, 0});
    const double differences[4] = {std::abs(ma.mean_x - mb.mean_x) / std::abs(ma.mean_x),
                                   std::abs(ma.xx - mb.xx) / ma.xx, std::abs(ma.yy - mb.yy) / ma.yy,
                                   std::abs(za - zb) / za};
    const double worst = *std::max_element(differences, differences + 4);
    MESSAGE("largest relative difference across the branches: " << worst);
    CHECK(worst <= 1e-12);
}
