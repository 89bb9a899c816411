// SPDX-License-Identifier: Apache-2.0
// The Lafortune model against the paper's formula written out in the test
// (lafortune_test_support.h): the value is uz times f, the lobe axis is C
// times the view, another view rescales it as the paper's C would, both
// variants, and every value finite for random lights and views.
#include "cmfilter/stack/lafortune_fit.h"
#include "cmfilter/stack/lafortune_model.h"

#include "lafortune_test_support.h"

#include <doctest/doctest.h>

#include <cfloat>
#include <cmath>
#include <random>

using namespace cmfilter;
using namespace cmfilter_test;

namespace {

Vec3 random_direction(std::mt19937_64& rng, double min_z)
{
    std::uniform_real_distribution<double> zd(min_z, 1), phi(0, 6.283185307179586);
    const double z = zd(rng), r = std::sqrt(1 - z * z), p = phi(rng);
    return {r * std::cos(p), r * std::sin(p), z};
}

// One texel of a luminance fit (one channel, base colour `base`) holding
// the paper's lobes C at view v as the library stores them (a = C * v).
LafortuneFit luminance_texel(double rho, const std::vector<PaperLobe>& lobes, const Vec3& v, double base)
{
    LafortuneFit fit;
    fit.variant = LafortuneVariant::Luminance;
    fit.width = fit.height = 1;
    fit.channels = 1;
    fit.lobes = static_cast<int>(lobes.size());
    fit.view = v;
    fit.parameters.push_back(static_cast<float>(rho));
    for (const PaperLobe& l : lobes)
        for (double x : {l.cx * v.x, l.cy * v.y, l.cz * v.z, l.n}) fit.parameters.push_back(static_cast<float>(x));
    fit.parameters.push_back(static_cast<float>(base));
    fit.lobe_counts.push_back(static_cast<unsigned char>(lobes.size()));
    return fit;
}

}  // namespace

TEST_CASE("lafortune model: an image holds uz times the paper's f, at the fitted view and at another")
{
    std::mt19937_64 rng(11);
    const Vec3 v = normalize(Vec3{0.35, -0.25, 0.9});
    // A retro-reflective-ish lobe, a mirror lobe (Cx = Cy = -Cz) and an
    // anisotropic one.
    const std::vector<PaperLobe> lobes = {{0.9, 0.9, 0.95, 6}, {-1.1, -1.1, 1.1, 25}, {-0.4, -1.3, 0.8, 3}};
    const double rho = 0.15, base = 0.8;
    const LafortuneFit fit = luminance_texel(rho, lobes, v, base);
    for (int trial = 0; trial < 200; ++trial) {
        const Vec3 u = random_direction(rng, 0.0);
        float value = 0;
        lafortune_texel_value(fit, 0, u, v, &value);
        const double expected = base * u.z * paper_reflectance(rho, lobes, u, v);
        CHECK(value == doctest::Approx(expected).epsilon(1e-5));
        // Another view: the paper's C (every component of v non-zero) at w.
        const Vec3 w = random_direction(rng, 0.2);
        lafortune_texel_value(fit, 0, u, w, &value);
        CHECK(value == doctest::Approx(base * u.z * paper_reflectance(rho, lobes, u, w)).epsilon(1e-5));
    }
    // At a grazing light (uz = 0) nothing, whatever f is; at the pole f.
    float value = -1;
    lafortune_texel_value(fit, 0, {1, 0, 0}, v, &value);
    CHECK(value == 0.0f);
    lafortune_texel_value(fit, 0, {0, 0, 1}, v, &value);
    CHECK(value == doctest::Approx(base * paper_reflectance(rho, lobes, {0, 0, 1}, v)).epsilon(1e-5));
    // A lobe whose dot product is negative adds nothing.
    CHECK(lafortune_lobe({0.5, 0, -1}, 7.5, normalize(Vec3{0.1, 0, 1})) == 0.0);
    CHECK(lafortune_lobe({0.5, 0, 1}, 2, {0, 0, 1}) == doctest::Approx(1.0));
    CHECK(lafortune_lobe({0, 0, 0}, 1, {0, 0, 1}) == 0.0);
}

TEST_CASE("lafortune model: rgb texels are per channel, and relight_lafortune covers every texel")
{
    LafortuneFit fit;
    fit.variant = LafortuneVariant::Rgb;
    fit.width = 2;
    fit.height = 1;
    fit.channels = 3;
    fit.lobes = 2;
    fit.lobe_counts.assign(6, 2);
    const std::vector<AxisTexel> texels = {
        {0.2, {scaled_axis({0.3, 0.1, 1}, 0.5, 20), scaled_axis({-0.4, 0.2, 1}, 0.2, 4)}, {20, 4}},
        {0.1, {scaled_axis({0, -0.5, 1}, 0.7, 60), scaled_axis({0.6, 0.6, 1}, 0.1, 2)}, {60, 2}},
        {0.4, {scaled_axis({0.2, 0.2, 1}, 0.3, 9), {0, 0, 0}}, {9, 1}},
    };
    // Texel t channel c holds texels[(t + c) % 3].
    for (int t = 0; t < 2; ++t)
        for (int c = 0; c < 3; ++c) {
            const AxisTexel& x = texels[(t + c) % 3];
            fit.parameters.push_back(static_cast<float>(x.rho));
            for (int i = 0; i < 2; ++i)
                for (double p : {x.axes[i].x, x.axes[i].y, x.axes[i].z, x.exponents[i]})
                    fit.parameters.push_back(static_cast<float>(p));
        }
    REQUIRE(fit.parameters.size() == fit.texels() * fit.stride());
    for (const Vec3& u : fibonacci_lights(30, 0.05)) {
        const std::vector<float> relit = relight_lafortune(fit, u, 2);
        REQUIRE(relit.size() == 6);
        for (int t = 0; t < 2; ++t)
            for (int c = 0; c < 3; ++c)
                CHECK(relit[t * 3 + c] == doctest::Approx(texels[(t + c) % 3].value(u)).epsilon(1e-5));
    }
    CHECK(fit.lobe_histogram() == std::vector<long long>{0, 0, 6});
}

TEST_CASE("lafortune model: finite for random lights and views above the horizon, sharp lobes, large axes, "
          "negative bases")
{
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> coord(-3, 3), exponent(1, 500);
    for (int trial = 0; trial < 300; ++trial) {
        LafortuneFit fit;
        fit.variant = LafortuneVariant::Luminance;
        fit.width = fit.height = 1;
        fit.channels = 3;
        fit.lobes = 7;
        // A fitted view with tiny components: another view rescales them
        // by up to 1e6.
        fit.view = trial % 2 ? normalize(Vec3{1e-6 * (trial % 7), -2e-6, 1}) : random_direction(rng, 0.05);
        fit.parameters.push_back(static_cast<float>(coord(rng)));
        for (int i = 0; i < 7; ++i)
            for (double p : {coord(rng), coord(rng), coord(rng), exponent(rng)})
                fit.parameters.push_back(static_cast<float>(p));
        for (int c = 0; c < 3; ++c) fit.parameters.push_back(static_cast<float>(coord(rng)));
        fit.lobe_counts.push_back(7);
        for (int k = 0; k < 20; ++k) {
            const Vec3 u = random_direction(rng, 0.0), w = random_direction(rng, 1e-3);
            float out[3];
            lafortune_texel_value(fit, 0, u, w, out);
            for (float x : out) CHECK(std::isfinite(x));
            lafortune_texel_value(fit, 0, u, fit.view, out);
            for (float x : out) CHECK(std::isfinite(x));
        }
    }
}
