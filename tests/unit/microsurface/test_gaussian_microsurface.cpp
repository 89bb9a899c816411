// SPDX-License-Identifier: Apache-2.0
// The random-phase cosine microsurface (gaussian_microsurface.h): its
// exact sigma_h and direction-dependent sigma_s against statistics measured
// over random points (slopes by central differences of the heights), its
// heights' Gaussian shape (skewness 0, kurtosis 3), and bad options.
#include "cmfilter/microsurface/gaussian_microsurface.h"

#include <doctest/doctest.h>

#include <cmath>
#include <random>

using namespace cmfilter;

TEST_CASE("microsurface statistics measured over random points match its exact sigma_h and sigma_s")
{
    GaussianMicrosurfaceOptions o;
    o.cosines = 256;
    o.sigma_h = 0.05;
    o.min_wavelength = 0.01;
    o.max_wavelength = 0.1;
    o.seed = 7;
    auto s = GaussianMicrosurface::create(o);
    REQUIRE(s);
    CHECK(s->sigma_h() == 0.05);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> at(0, 100);  // a thousand longest wavelengths
    const int n = 100000;
    const double eps = 1e-5;
    double m1 = 0, m2 = 0, m3 = 0, m4 = 0;
    const double azimuths[3] = {0.0, 0.7, 2.0};
    double slope2[3] = {0, 0, 0};
    for (int k = 0; k < n; ++k) {
        const double x = at(rng), y = at(rng);
        const double h = s->height(x, y);
        m1 += h;
        m2 += h * h;
        m3 += h * h * h;
        m4 += h * h * h * h;
        for (int a = 0; a < 3; ++a) {
            const double dx = std::cos(azimuths[a]), dy = std::sin(azimuths[a]);
            const double d = (s->height(x + eps * dx, y + eps * dy) - s->height(x - eps * dx, y - eps * dy)) /
                             (2 * eps);
            slope2[a] += d * d;
        }
        if (k < 100) {
            double gx = 0, gy = 0;
            s->gradient(x, y, gx, gy);
            const double fx = (s->height(x + eps, y) - s->height(x - eps, y)) / (2 * eps);
            const double fy = (s->height(x, y + eps) - s->height(x, y - eps)) / (2 * eps);
            CHECK(gx == doctest::Approx(fx).epsilon(2e-4).scale(1));
            CHECK(gy == doctest::Approx(fy).epsilon(2e-4).scale(1));
        }
    }
    m1 /= n;
    const double var = m2 / n - m1 * m1;
    CHECK(std::abs(m1) < 0.02 * o.sigma_h);
    CHECK(std::sqrt(var) == doctest::Approx(o.sigma_h).epsilon(0.02));
    const double skew = (m3 / n) / std::pow(var, 1.5);
    const double kurt = (m4 / n) / (var * var);
    CHECK(std::abs(skew) < 0.05);
    CHECK(kurt == doctest::Approx(3.0).epsilon(0.05));
    for (int a = 0; a < 3; ++a) {
        CAPTURE(azimuths[a]);
        CHECK(std::sqrt(slope2[a] / n) == doctest::Approx(s->sigma_s(azimuths[a])).epsilon(0.02));
    }
}

TEST_CASE("microsurface refuses bad options, naming them")
{
    GaussianMicrosurfaceOptions o;
    o.cosines = 0;
    auto a = GaussianMicrosurface::create(o);
    REQUIRE_FALSE(a);
    CHECK(a.error().message.find("cosines") != std::string::npos);
    o = {};
    o.sigma_h = -1;
    CHECK_FALSE(GaussianMicrosurface::create(o));
    o = {};
    o.min_wavelength = 0.2;
    o.max_wavelength = 0.1;
    CHECK_FALSE(GaussianMicrosurface::create(o));
    o = {};
    o.sigma_h = 0;  // a flat surface is fine
    auto flat = GaussianMicrosurface::create(o);
    REQUIRE(flat);
    CHECK(flat->height(0.3, 0.4) == 0);
    CHECK(flat->sigma_s(1.0) == 0);
}

TEST_CASE("a microsurface with a tile repeats with that period and keeps its measured statistics")
{
    GaussianMicrosurfaceOptions o;
    o.sigma_h = 0.04;
    o.min_wavelength = 0.05;
    o.max_wavelength = 0.4;
    o.tile = 1.6;
    auto s = GaussianMicrosurface::create(o);
    REQUIRE(s);
    CHECK(s->tile() == 1.6);
    for (double x : {0.0, 0.37, 1.11})
        for (double y : {0.0, 0.52}) {
            CHECK(s->height(x + 1.6, y) == doctest::Approx(s->height(x, y)).epsilon(1e-9));
            CHECK(s->height(x, y - 3.2) == doctest::Approx(s->height(x, y)).epsilon(1e-9));
        }
    // Heights measured over a grid of one tile (exact for a lattice spectrum).
    const int n = 256;
    double h2 = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double h = s->height(1.6 * i / n, 1.6 * j / n);
            h2 += h * h;
        }
    CHECK(std::sqrt(h2 / (n * n)) == doctest::Approx(0.04).epsilon(0.03));
    o.tile = 0.3;  // shorter than the longest wavelength
    auto bad = GaussianMicrosurface::create(o);
    REQUIRE_FALSE(bad);
    CHECK(bad.error().message.find("tile") != std::string::npos);
}
