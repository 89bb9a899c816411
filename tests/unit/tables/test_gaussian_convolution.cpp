// SPDX-License-Identifier: Apache-2.0
// eq. 10: the closed-form convolution against brute-force quadrature
// (tests/support/reference_convolution.h) and against properties that hold
// for any correct Gaussian filter.
#include "cmfilter/tables/gaussian_convolution.h"

#include "unit_test_support.h"

#include <doctest/doctest.h>

#include <random>

using namespace cmfilter;
using cmfilter_test::MapPair;
using cmfilter_test::random_map;
using cmfilter_test::ReferenceMap;

namespace {

double max_abs_diff(const Rgb& a, const cmfilter_test::Rgb3& b)
{
    return std::max({std::fabs(a.r - b[0]), std::fabs(a.g - b[1]), std::fabs(a.b - b[2])});
}

}  // namespace

TEST_CASE("gaussian convolution matches brute-force quadrature for every wrap mode")
{
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (WrapMode wrap : {WrapMode::Clamp, WrapMode::Repeat, WrapMode::Mirror}) {
        for (int n : {1, 2, 7, 64, 256}) {
            const MapPair p = random_map(rng, n, wrap, -0.5, 1.5);
            double worst = 0;
            for (int trial = 0; trial < 40; ++trial) {
                const double v = -2.0 + 5.0 * unit(rng);  // well beyond the domain too
                // sigma from far below a texel to several domain widths
                const double sigma = std::pow(10.0, -5.0 + 5.7 * unit(rng));
                worst = std::max(worst, max_abs_diff(gaussian_convolution(p.map, v, sigma),
                                                     cmfilter_test::reference_convolution(p.ref, v, sigma)));
            }
            CAPTURE(to_string(wrap));
            CAPTURE(n);
            // Both sides are double computations of the same integral; 1e-9 leaves
            // room for rounding in the quadrature's sums, far inside the 1e-6 the
            // float tables promise.
            CHECK(worst < 1e-9);
        }
    }
}

TEST_CASE("sigma = 0 gives the map itself")
{
    std::mt19937_64 rng(7);
    const MapPair p = random_map(rng, 16, WrapMode::Clamp, 0, 1);
    for (double v = -0.2; v <= 1.2; v += 0.013)
        CHECK(max_abs_diff(gaussian_convolution(p.map, v, 0.0), cmfilter_test::reference_map_value(p.ref, v)) < 1e-15);
}

TEST_CASE("a constant map stays constant at every sigma")
{
    ColorMap map;
    map.texels.assign(33, Rgb{0.25, 0.5, 2.0});
    for (WrapMode wrap : {WrapMode::Clamp, WrapMode::Repeat, WrapMode::Mirror}) {
        map.wrap = wrap;
        for (double sigma : {0.0, 1e-4, 0.01, 0.3, 2.0, 40.0})
            for (double v : {-3.0, 0.0, 0.37, 1.0, 5.5}) {
                const Rgb c = gaussian_convolution(map, v, sigma);
                // Steps between equal texels are exactly zero; only the Fourier
                // path rounds (a few ulps of 2.0).
                CHECK(std::fabs(c.r - 0.25) < 1e-13);
                CHECK(std::fabs(c.g - 0.5) < 1e-13);
                CHECK(std::fabs(c.b - 2.0) < 1e-13);
            }
    }
}

TEST_CASE("a linear map stays linear away from its clamped ends")
{
    // C0(v) = v on [u_0, u_{n-1}]: texel i holds its own centre value.
    ColorMap map;
    const int n = 64;
    for (int i = 0; i < n; ++i) {
        const double u = (i + 0.5) / n;
        map.texels.push_back({u, 1.0 - u, 0.5 * u});
    }
    const double first = 0.5 / n, last = 1.0 - 0.5 / n;
    for (double sigma : {0.001, 0.01, 0.03})
        for (double v = first + 10 * sigma; v <= last - 10 * sigma; v += 0.01) {
            const Rgb c = gaussian_convolution(map, v, sigma);
            // A symmetric kernel preserves a linear function exactly; 1e-12
            // allows for the rounding of a sum of a few hundred steps.
            CHECK(std::fabs(c.r - v) < 1e-12);
            CHECK(std::fabs(c.g - (1.0 - v)) < 1e-12);
            CHECK(std::fabs(c.b - 0.5 * v) < 1e-12);
        }
}

TEST_CASE("repeat with a very large sigma gives the map's mean colour")
{
    std::mt19937_64 rng(3);
    const MapPair p = random_map(rng, 100, WrapMode::Repeat, 2.0, 3.0);
    double mean[3] = {0, 0, 0};
    for (const auto& t : p.ref.texels)
        for (int ch = 0; ch < 3; ++ch) mean[ch] += t[ch] / 100.0;
    for (double sigma : {5.0, 50.0, 1e4})
        for (double v : {-10.0, 2.0, 2.77, 1e3}) {
            const Rgb c = gaussian_convolution(p.map, v, sigma);
            // Harmonic 1 is damped by exp(-2 pi^2 sigma^2) < 1e-200 at sigma = 5.
            CHECK(std::fabs(c.r - mean[0]) < 1e-12);
            CHECK(std::fabs(c.g - mean[1]) < 1e-12);
            CHECK(std::fabs(c.b - mean[2]) < 1e-12);
        }
}

TEST_CASE("the Fourier and step-sum evaluations agree where they hand over")
{
    // Around sigma = 0.2 period the periodic evaluation switches method; both
    // sides of the switch must match quadrature.
    std::mt19937_64 rng(11);
    for (WrapMode wrap : {WrapMode::Repeat, WrapMode::Mirror}) {
        const MapPair p = random_map(rng, 32, wrap, 0, 1);
        for (double sigma = 0.05; sigma < 0.6; sigma += 0.0137)
            for (double v : {-0.3, 0.1, 0.55, 0.999}) {
                CAPTURE(sigma);
                CHECK(max_abs_diff(gaussian_convolution(p.map, v, sigma),
                                   cmfilter_test::reference_convolution(p.ref, v, sigma)) < 1e-9);
            }
    }
}

TEST_CASE("mirror maps are symmetric about both ends of the domain")
{
    std::mt19937_64 rng(5);
    const MapPair p = random_map(rng, 20, WrapMode::Mirror, 0, 1);
    for (double sigma : {0.0, 0.02, 0.2, 1.5})
        for (double x : {0.01, 0.1, 0.33}) {
            const Rgb a = gaussian_convolution(p.map, -x, sigma), b = gaussian_convolution(p.map, x, sigma);
            const Rgb c = gaussian_convolution(p.map, 1 + x, sigma), d = gaussian_convolution(p.map, 1 - x, sigma);
            CHECK(std::fabs(a.r - b.r) < 1e-12);
            CHECK(std::fabs(c.g - d.g) < 1e-12);
        }
}

TEST_CASE("the kink-block expansion matches quadrature from its threshold up")
{
    // Sigma from just below GaussianConvolution::kBlockMinSigma texels (step
    // sum) to 100 texels (one or two wide blocks), for every wrap mode.
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (WrapMode wrap : {WrapMode::Clamp, WrapMode::Repeat, WrapMode::Mirror}) {
        const MapPair p = random_map(rng, 256, wrap, 0, 1);
        const double texel = 1.0 / 256;
        double worst = 0;
        for (double s_texels : {0.9, 1.0, 1.1, 2.5, 7.5, 16.0, 33.3, 64.0, 100.0})
            for (int trial = 0; trial < 6; ++trial) {
                const double v = -0.5 + 2.0 * unit(rng);
                const double sigma = s_texels * texel;
                worst = std::max(worst, max_abs_diff(gaussian_convolution(p.map, v, sigma),
                                                     cmfilter_test::reference_convolution(p.ref, v, sigma)));
            }
        CAPTURE(to_string(wrap));
        // The expansion's remainder bound is 2.9e-15 s |kappa| per kink; with
        // s <= 100 and random texels (sum |kappa| < 1500) that is < 5e-10.
        CHECK(worst < 2e-9);
    }
}
