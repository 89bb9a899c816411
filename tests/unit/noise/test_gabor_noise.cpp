// SPDX-License-Identifier: Apache-2.0
// Gabor noise (Lagae et al. 2009): the analytic variance against brute-force
// measurement over many independent samples, with a Monte-Carlo confidence
// interval computed from the samples themselves; determinism and validation.
#include "cmfilter/noise/gabor_noise.h"

#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace cmfilter;

TEST_CASE("gabor noise variance matches the analytic formula within its Monte-Carlo interval")
{
    struct Case {
        const char* name;
        GaborNoiseOptions options;
    };
    GaborNoiseOptions isotropic;  // defaults: K 1, a 0.8, F0 1, lambda 8
    GaborNoiseOptions anisotropic;
    anisotropic.orientation = 0.6;
    anisotropic.amplitude = 2.5;
    GaborNoiseOptions low_frequency;  // exp(-2 pi F0^2 / a^2) = 0.41: the second term matters
    low_frequency.frequency = 0.3;
    low_frequency.impulse_density = 3.0;
    for (const Case& c :
         {Case{"isotropic", isotropic}, Case{"anisotropic", anisotropic}, Case{"low frequency", low_frequency}}) {
        CAPTURE(c.name);
        auto noise = GaborNoise::create(c.options, 17);
        REQUIRE(noise);
        // Points uniform over a square of side 1e5: neighbours lie ~500 units
        // apart, hundreds of kernel radii (1.9 units), so the samples are
        // independent draws of the stationary process.
        const int count = 30000;
        std::mt19937_64 rng(5);
        std::uniform_real_distribution<double> coord(-5e4, 5e4);
        std::vector<double> v(count);
        double sum = 0;
        for (double& s : v) {
            s = (*noise)(coord(rng), coord(rng));
            sum += s;
        }
        const double mean = sum / count;
        double m2 = 0, m4 = 0;  // central moments about the known mean 0
        for (double s : v) {
            m2 += s * s / count;
            m4 += s * s * s * s / count;
        }
        const double expected = noise->variance();
        // sd of the sample second moment: sqrt((m4 - m2^2) / N); 5 sd (the
        // truncation bias, < 1.4e-6 relative, is far below it).
        const double sd = std::sqrt((m4 - m2 * m2) / count);
        CAPTURE(m2);
        CAPTURE(expected);
        CAPTURE(sd);
        CHECK(std::fabs(m2 - expected) < 5 * sd);
        CHECK(std::fabs(mean) < 5 * std::sqrt(expected / count));
        // The interval is tight enough to mean something: under 5% of the variance.
        CHECK(5 * sd < 0.05 * expected);
    }
}

TEST_CASE("gabor noise is deterministic per seed and differs between seeds")
{
    auto a = GaborNoise::create({}, 3), b = GaborNoise::create({}, 3), c = GaborNoise::create({}, 4);
    REQUIRE(a);
    REQUIRE(b);
    REQUIRE(c);
    int differ = 0;
    for (int i = 0; i < 50; ++i) {
        const double x = 0.73 * i - 11.0, y = -2.1 * i + 0.4;
        CHECK((*a)(x, y) == (*b)(x, y));
        differ += (*a)(x, y) != (*c)(x, y);
    }
    CHECK(differ == 50);
}

TEST_CASE("gabor noise options are validated with the bad value named")
{
    GaborNoiseOptions o;
    o.bandwidth = -1;
    auto r = GaborNoise::create(o, 0);
    REQUIRE_FALSE(r);
    CHECK(r.error().kind == ErrorKind::BadInput);
    CHECK(r.error().message.find("bandwidth") != std::string::npos);
    CHECK(r.error().message.find("-1") != std::string::npos);

    o = {};
    o.impulse_density = 0;
    r = GaborNoise::create(o, 0);
    REQUIRE_FALSE(r);
    CHECK(r.error().message.find("impulse density") != std::string::npos);

    o = {};
    o.bandwidth = 1e-3;  // 2.25e6 per unit lambda per cell: too many impulses
    r = GaborNoise::create(o, 0);
    REQUIRE_FALSE(r);
    CHECK(r.error().message.find("impulses per cell") != std::string::npos);
}
