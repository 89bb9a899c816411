// SPDX-License-Identifier: Apache-2.0
// The exact height-filtered colour <C_h, D_h> (height_color.h) and the
// normal quantile under it, against independent computations: the quantile
// against bisection on erfc; the colour of a two-node ramp map against
// E[ramp(h)] = int (1 - Phi(t / sigma_h)^(L+1)) dt / (p1 - p0) over the
// ramp, by the trapezoid rule in t.
#include "cmfilter/microsurface/height_color.h"
#include "cmfilter/math/normal_distribution.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace cmfilter;

namespace {

// E[ramp(h)] for a ramp from 0 at p0 to 1 at p1 and h ~ D_h: the tail
// integral int_p0^p1 (1 - Phi(t / sigma_h)^(L+1)) dt / (p1 - p0), by the
// trapezoid rule.
double ramp_tail_mean(double p0, double p1, double sigma_h, double L)
{
    const int n = 20000;
    double sum = 0;
    for (int k = 0; k <= n; ++k) {
        const double t = p0 + (p1 - p0) * k / n;
        const double tail = -std::expm1((L + 1) * std::log(0.5 * std::erfc(-t / (sigma_h * std::sqrt(2.0)))));
        sum += (k == 0 || k == n) ? 0.5 * tail : tail;
    }
    return sum / n;
}

}  // namespace

TEST_CASE("the normal quantile inverts erfc to 1e-13 from 1e-300 to 1 - 1e-16")
{
    for (double p : {1e-300, 1e-100, 1e-20, 1e-8, 0.001, 0.02, 0.3, 0.5, 0.7, 0.98, 0.999, 1 - 1e-9, 1 - 1e-15}) {
        CAPTURE(p);
        const double x = normal_quantile(p);
        // Bisection on Phi (its complement on the right), independent of the approximation.
        double lo = -40, hi = 40;
        for (int k = 0; k < 200; ++k) {
            const double mid = 0.5 * (lo + hi);
            const bool below = p < 0.5 ? 0.5 * std::erfc(-mid / std::sqrt(2.0)) < p
                                       : 0.5 * std::erfc(mid / std::sqrt(2.0)) > 1 - p;
            (below ? lo : hi) = mid;
        }
        const double ref = 0.5 * (lo + hi);
        CHECK(std::abs(x - ref) <= 1e-13 * (1 + std::abs(ref)));
    }
    CHECK(std::isinf(normal_quantile(0)));
    CHECK(std::isinf(normal_quantile(1)));
    CHECK(std::isnan(normal_quantile(1.5)));
}

TEST_CASE("exact height colour of a ramp map matches the tail integral of D_h")
{
    // Two texels (black, white) over [-0.1, 0.1]: nodes at -0.05 and 0.05,
    // C_h a ramp between them, clamped beyond.
    ColorMap map;
    map.texels = {Rgb{0, 0, 0}, Rgb{1, 1, 1}};
    map.vmin = -0.1;
    map.vmax = 0.1;
    const double p0 = -0.05, p1 = 0.05;
    for (double sigma_h : {0.02, 0.05, 0.3})
        for (double L : {0.0, 0.7, 5.0, 100.0, 1e4}) {
            CAPTURE(sigma_h);
            CAPTURE(L);
            const double expected = ramp_tail_mean(p0, p1, sigma_h, L);
            const Rgb got = exact_height_color(map, sigma_h, L);
            CHECK(got.r == doctest::Approx(expected).epsilon(1e-6).scale(1e-6));
            CHECK(got.g == got.r);
        }
    // A flat surface sees height 0; a constant map stays constant.
    CHECK(exact_height_color(map, 0, 3).r == doctest::Approx(0.5));
    ColorMap grey;
    grey.texels = {Rgb{0.3, 0.3, 0.3}};
    CHECK(exact_height_color(grey, 0.2, 50).r == doctest::Approx(0.3).epsilon(1e-12));
}

TEST_CASE("exact height colour about a resolved mean height reads the map at the offset heights")
{
    ColorMap map;
    map.texels = {Rgb{0, 0, 0}, Rgb{1, 1, 1}};
    map.vmin = -0.1;
    map.vmax = 0.1;
    for (double offset : {-0.03, 0.045})
        for (double L : {0.0, 2.0, 300.0}) {
            CAPTURE(offset);
            CAPTURE(L);
            const double sigma_h = 0.03;
            CHECK(exact_height_color(map, sigma_h, L, offset).r ==
                  doctest::Approx(ramp_tail_mean(-0.05 - offset, 0.05 - offset, sigma_h, L)).epsilon(1e-6).scale(1e-6));
        }
    CHECK(exact_height_color(map, 0, 3, 0.025).r == doctest::Approx(0.75));
}
