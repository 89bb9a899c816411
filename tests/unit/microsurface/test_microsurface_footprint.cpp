// SPDX-License-Identifier: Apache-2.0
// The resolved and unresolved parts of a microsurface over a footprint
// (microsurface_footprint.h), against brute-force averages over points of the
// parallelogram.
#include "cmfilter/microsurface/microsurface_footprint.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace cmfilter;

namespace {

GaussianMicrosurface test_surface()
{
    GaussianMicrosurfaceOptions o;
    o.cosines = 64;
    o.sigma_h = 0.03;
    o.min_wavelength = 0.05;
    o.max_wavelength = 0.4;
    o.seed = 5;
    return *GaussianMicrosurface::create(o);
}

// The mean of h and h^2 and of the slope along d over the parallelogram, on
// an n x n midpoint grid.
struct Brute {
    double mean = 0, variance = 0, slope_variance = 0;
};

Brute brute_force(const GaussianMicrosurface& s, double u, double v, double e1u, double e1v, double e2u, double e2v,
                  double azimuth, int n)
{
    double h1 = 0, h2 = 0, d1 = 0, d2 = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double a = (i + 0.5) / n - 0.5, b = (j + 0.5) / n - 0.5;
            const double x = u + a * e1u + b * e2u, y = v + a * e1v + b * e2v;
            const double h = s.height(x, y);
            double gx = 0, gy = 0;
            s.gradient(x, y, gx, gy);
            const double d = gx * std::cos(azimuth) + gy * std::sin(azimuth);
            h1 += h;
            h2 += h * h;
            d1 += d;
            d2 += d * d;
        }
    const double m = 1.0 / (n * n);
    return {h1 * m, h2 * m - h1 * h1 * m * m, d2 * m - d1 * d1 * m * m};
}

}  // namespace

TEST_CASE("the resolved height is the box-filtered mean over the footprint")
{
    const GaussianMicrosurface s = test_surface();
    for (double w : {0.01, 0.07, 0.3}) {
        CAPTURE(w);
        const double e1u = w, e1v = 0.3 * w, e2u = -0.2 * w, e2v = 0.6 * w;
        const MicrosurfaceFootprint f = filter_microsurface(s, 0.37, -1.2, e1u, e1v, e2u, e2v);
        const Brute b = brute_force(s, 0.37, -1.2, e1u, e1v, e2u, e2v, 0, 400);
        CHECK(f.mean_height == doctest::Approx(b.mean).epsilon(1e-4).scale(0.03));
    }
}

TEST_CASE("the unresolved height and slope deviations are the footprint's own spread, averaged over the surface")
{
    const GaussianMicrosurface s = test_surface();
    for (double w : {0.03, 0.1, 0.4}) {
        CAPTURE(w);
        const double e1u = w, e1v = 0.2 * w, e2u = 0.1 * w, e2v = 0.5 * w;
        // Average the footprint's own variances over many centres.
        double var = 0, slope_var = 0;
        const int centres = 200;
        for (int k = 0; k < centres; ++k) {
            const double u = 17.3 * std::sin(1.7 * k), v = 11.1 * std::cos(2.3 * k);
            const Brute b = brute_force(s, u, v, e1u, e1v, e2u, e2v, 0.7, 48);
            var += b.variance / centres;
            slope_var += b.slope_variance / centres;
        }
        const MicrosurfaceFootprint f = filter_microsurface(s, 0.0, 0.0, e1u, e1v, e2u, e2v);
        // 200 centres: the average is within a few per cent of its expectation.
        CHECK(f.sigma_h == doctest::Approx(std::sqrt(var)).epsilon(0.05));
        CHECK(f.sigma_s(0.7) == doctest::Approx(std::sqrt(slope_var)).epsilon(0.05));
    }
}

TEST_CASE("a point footprint resolves everything and a wide one nothing")
{
    const GaussianMicrosurface s = test_surface();
    const MicrosurfaceFootprint point = filter_microsurface(s, 0.2, 0.9, 0, 0, 0, 0);
    CHECK(point.mean_height == doctest::Approx(s.height(0.2, 0.9)).epsilon(1e-12));
    CHECK(point.sigma_h == 0);
    CHECK(point.sigma_s(0.3) == 0);
    const MicrosurfaceFootprint wide = filter_microsurface(s, 0.2, 0.9, 400, 0, 0, 400);
    CHECK(std::fabs(wide.mean_height) < 1e-4 * s.sigma_h());
    CHECK(wide.sigma_h == doctest::Approx(s.sigma_h()).epsilon(1e-4));
    for (double a : {0.0, 1.0, 2.5}) CHECK(wide.sigma_s(a) == doctest::Approx(s.sigma_s(a)).epsilon(1e-4));
    CHECK(point.resolved_sigma_h == doctest::Approx(s.sigma_h()).epsilon(1e-12));
    CHECK(wide.resolved_sigma_h < 1e-3 * s.sigma_h());
}

TEST_CASE("the resolved part's spread is the spread of the box-filtered heights over the surface")
{
    const GaussianMicrosurface s = test_surface();
    const double w = 0.12, e1u = w, e1v = 0.1 * w, e2u = -0.3 * w, e2v = 0.8 * w;
    // The filtered heights and slopes (finite differences of the filtered
    // height) over many centres.
    double h2 = 0, d2 = 0;
    const int centres = 4000;
    const double step = 1e-5, azimuth = 2.0;
    for (int k = 0; k < centres; ++k) {
        const double u = 23.1 * std::sin(1.3 * k + 0.2), v = 19.7 * std::cos(0.7 * k);
        const double h = filter_microsurface(s, u, v, e1u, e1v, e2u, e2v).mean_height;
        const double ahead =
            filter_microsurface(s, u + step * std::cos(azimuth), v + step * std::sin(azimuth), e1u, e1v, e2u, e2v)
                .mean_height;
        h2 += h * h / centres;
        d2 += (ahead - h) * (ahead - h) / (step * step) / centres;
    }
    const MicrosurfaceFootprint f = filter_microsurface(s, 0, 0, e1u, e1v, e2u, e2v);
    CHECK(f.resolved_sigma_h == doctest::Approx(std::sqrt(h2)).epsilon(0.05));
    CHECK(f.resolved_sigma_s(azimuth) == doctest::Approx(std::sqrt(d2)).epsilon(0.05));
    CHECK(f.resolved_sigma_h * f.resolved_sigma_h + f.sigma_h * f.sigma_h ==
          doctest::Approx(s.sigma_h() * s.sigma_h()).epsilon(1e-9));
}

TEST_CASE("the resolved slopes are the mean slopes over the footprint")
{
    const GaussianMicrosurface s = test_surface();
    for (double w : {0.0, 0.02, 0.15}) {
        CAPTURE(w);
        const double e1u = w, e1v = 0.25 * w, e2u = -0.1 * w, e2v = 0.7 * w;
        const ResolvedSlope f = resolved_slope(s, 0.61, 2.3, e1u, e1v, e2u, e2v);
        // The mean of the gradient over the parallelogram, on a midpoint grid.
        const int n = w > 0 ? 300 : 1;
        double gx = 0, gy = 0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const double a = (i + 0.5) / n - 0.5, b = (j + 0.5) / n - 0.5;
                double dx = 0, dy = 0;
                s.gradient(0.61 + a * e1u + b * e2u, 2.3 + a * e1v + b * e2v, dx, dy);
                gx += dx / (n * n);
                gy += dy / (n * n);
            }
        CHECK(f.x == doctest::Approx(gx).epsilon(1e-4).scale(0.1));
        CHECK(f.y == doctest::Approx(gy).epsilon(1e-4).scale(0.1));
    }
}
