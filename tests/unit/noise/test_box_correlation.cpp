// SPDX-License-Identifier: Apache-2.0
// Box correlations (box_correlation.h): the closed forms for gradient, value
// and Gabor noise, and the Monte-Carlo measurement, against brute force, the
// regression slope of footprint means (by midpoint quadrature) on centre
// values; and the interpolation's promises (1 at a point, C1, 0 past the cutoff).
#include "cmfilter/noise/box_correlation.h"
#include "cmfilter/noise/gabor_box_correlation.h"
#include "cmfilter/noise/gabor_noise.h"
#include "cmfilter/noise/gradient_noise.h"
#include "cmfilter/noise/lattice_box_correlation.h"
#include "cmfilter/noise/value_noise.h"

#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

using namespace cmfilter;

namespace {

struct Slope {
    double beta = 0, standard_error = 0;
};

// The least-squares slope of T (mean of the term over a square of side
// k * period, Q x Q midpoint quadrature) on C (the term at the square's
// centre), over `footprints` centres uniform in [0, 256 period)^2, with the
// slope's standard error from the residuals.
Slope brute_force_slope(const std::function<double(double, double)>& term, double period, double k, int footprints,
                        int q, std::uint64_t seed)
{
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> centre(0.0, 256.0 * period);
    std::vector<double> t(static_cast<std::size_t>(footprints)), c(static_cast<std::size_t>(footprints));
    const double side = k * period;
    for (int f = 0; f < footprints; ++f) {
        const double x = centre(rng), y = centre(rng);
        double sum = 0;
        for (int a = 0; a < q; ++a)
            for (int b = 0; b < q; ++b) sum += term(x + side * ((a + 0.5) / q - 0.5), y + side * ((b + 0.5) / q - 0.5));
        t[static_cast<std::size_t>(f)] = sum / (q * q);
        c[static_cast<std::size_t>(f)] = term(x, y);
    }
    double tm = 0, cm = 0;
    for (int f = 0; f < footprints; ++f) {
        tm += t[static_cast<std::size_t>(f)];
        cm += c[static_cast<std::size_t>(f)];
    }
    tm /= footprints;
    cm /= footprints;
    double scc = 0, stc = 0;
    for (int f = 0; f < footprints; ++f) {
        const double dc = c[static_cast<std::size_t>(f)] - cm;
        scc += dc * dc;
        stc += dc * (t[static_cast<std::size_t>(f)] - tm);
    }
    Slope s;
    s.beta = stc / scc;
    double residual = 0;
    for (int f = 0; f < footprints; ++f) {
        const double r = (t[static_cast<std::size_t>(f)] - tm) - s.beta * (c[static_cast<std::size_t>(f)] - cm);
        residual += r * r;
    }
    s.standard_error = std::sqrt(residual / (footprints - 2) / scc);
    return s;
}

}  // namespace

TEST_CASE("gradient noise box correlation matches the brute-force regression slope")
{
    const GradientNoise noise(11);
    const auto term = [&](double x, double y) { return noise(x, y); };
    const BoxCorrelation beta = gradient_noise_box_correlation();
    for (double k : {0.25, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0}) {
        // Midpoint quadrature with 32^2 nodes errs by O((k / 32)^2) of the
        // noise's curvature: under 0.3% of the slope here.
        const Slope s = brute_force_slope(term, 1.0, k, 3000, 32, 5);
        CAPTURE(k);
        CAPTURE(s.beta);
        CAPTURE(s.standard_error);
        CAPTURE(beta(k));
        CHECK(std::fabs(beta(k) - s.beta) <= 4 * s.standard_error + 0.003);
    }
    // Past k = 4 the box holds the autocorrelation's whole support, whose
    // integral is 0: exactly nothing is left.
    CHECK(beta(4.0) == 0.0);
    CHECK(beta(100.0) == 0.0);
}

TEST_CASE("value noise box correlation matches the brute-force regression slope")
{
    const BoxCorrelation beta = value_noise_box_correlation();
    // The closed form is the mean over lattice draws. Within one period of
    // one seed (65536 lattice values) the slope of footprints a few periods
    // wide still varies from seed to seed (about +-0.03 at k = 4): value noise
    // keeps power at frequency 0, so wide footprints average few independent
    // draws' worth of that power. Hence one seed for k <= 2, and the mean over
    // eight seeds, with their spread in the tolerance, for the slow tail at
    // k = 4 and 8, past the cutoff (where the filtered mean no longer uses
    // the samples).
    for (int j : {12, 16, 20, 24, 28}) {
        const double k = std::exp2(BoxCorrelation::grid_log2(j));
        const double sample = beta.samples()[static_cast<std::size_t>(j)];
        const int seeds = k > 2 ? 8 : 1;
        std::vector<double> slopes;
        double standard_error = 0;
        for (int seed = 0; seed < seeds; ++seed) {
            const ValueNoise noise(static_cast<std::uint64_t>(12 + seed));
            const auto term = [&](double x, double y) { return noise(x, y); };
            const Slope s = brute_force_slope(term, 1.0, k, k > 2 ? 1000 : 2000, 32, 6);
            slopes.push_back(s.beta);
            standard_error = s.standard_error;
        }
        double mean = 0, spread = 0;
        for (double b : slopes) mean += b / seeds;
        for (double b : slopes) spread += (b - mean) * (b - mean);
        if (seeds > 1) standard_error = std::sqrt(spread / (seeds - 1) / seeds);
        CAPTURE(k);
        CAPTURE(mean);
        CAPTURE(standard_error);
        CAPTURE(sample);
        CHECK(std::fabs(sample - mean) <= 4 * standard_error + 0.003);
    }
    CHECK(beta.cutoff() > 4.0);
    CHECK(beta(beta.cutoff()) == 0.0);
}

TEST_CASE("gabor noise box correlation matches the brute-force regression slope, isotropic and oriented")
{
    for (bool oriented : {false, true}) {
        GaborNoiseOptions options;
        if (oriented) options.orientation = 0.6;
        auto noise = GaborNoise::create(options, 21);
        REQUIRE(noise);
        const auto term = [&](double x, double y) { return (*noise)(x, y); };
        const BoxCorrelation beta = gabor_noise_box_correlation(options);
        for (double k : {0.35, 0.7}) {
            // 16 midpoint nodes over at most 0.7 wavelengths: quadrature error < 0.5%.
            const Slope s = brute_force_slope(term, noise->period(), k, 500, 16, 7);
            CAPTURE(oriented);
            CAPTURE(k);
            CAPTURE(s.beta);
            CAPTURE(s.standard_error);
            CAPTURE(beta(k));
            CHECK(std::fabs(beta(k) - s.beta) <= 4 * s.standard_error + 0.005);
        }
    }
}

TEST_CASE("measured box correlation agrees with the closed form for gradient noise")
{
    const GradientNoise noise(13);
    auto measured = measure_box_correlation([&](double x, double y) { return noise(x, y); }, 1.0);
    REQUIRE(measured);
    const BoxCorrelation exact = gradient_noise_box_correlation();
    // 9216 pairs: each sample's standard error is about 1 / 96; allow 4 of them.
    for (int j = 0; j < BoxCorrelation::grid_count; ++j) {
        const double k = std::exp2(BoxCorrelation::grid_log2(j));
        CAPTURE(k);
        CHECK(std::fabs(measured->samples()[static_cast<std::size_t>(j)] -
                        exact.samples()[static_cast<std::size_t>(j)]) < 4.0 / 96);
    }
}

TEST_CASE("box correlation is one at a point, passes through its samples, bends smoothly and ends at its cutoff")
{
    for (const BoxCorrelation& beta : {value_noise_box_correlation(), gradient_noise_box_correlation()}) {
        CHECK(beta(0.0) == 1.0);
        CHECK(beta(-1.0) == 1.0);
        CHECK(1.0 - beta(1e-12) < 1e-6);  // held below 2^-12
        const double cutoff = beta.cutoff();
        for (int j = 0; j < BoxCorrelation::grid_count; ++j) {
            const double k = std::exp2(BoxCorrelation::grid_log2(j));
            if (k >= cutoff / std::sqrt(2.0)) break;  // the taper's half octave
            CAPTURE(k);
            CHECK(beta(k) == doctest::Approx(beta.samples()[static_cast<std::size_t>(j)]).epsilon(1e-12));
        }
        // No jumps, and no kinks sharper than a C1 curve sampled every 1/64
        // octave allows: over steps of 1/256 octave from far below the first
        // sample to past the cutoff, the value moves by at most 0.01 and the
        // slope (per octave) changes by at most 0.1 between neighbours.
        const double h = 1.0 / 256;
        double previous_slope = 0;
        for (double l = -8; l < std::log2(cutoff) + 1; l += h) {
            const double a = beta.at_log2(l), b = beta.at_log2(l + h);
            CAPTURE(l);
            CHECK(std::fabs(b - a) < 0.01);
            const double slope = (b - a) / h;
            if (l > -8) CHECK(std::fabs(slope - previous_slope) < 0.1);
            previous_slope = slope;
        }
        CHECK(beta(cutoff) == 0.0);
        CHECK(beta(2 * cutoff) == 0.0);
        CHECK(std::fabs(beta(cutoff * (1 - 1e-9))) < 1e-9);
    }
}

TEST_CASE("box correlation samples are validated with the bad value named")
{
    auto short_grid = BoxCorrelation::from_grid(std::vector<double>(3, 0.5));
    REQUIRE_FALSE(short_grid);
    CHECK(short_grid.error().message.find("needs 37 samples, got 3") != std::string::npos);
    std::vector<double> samples(BoxCorrelation::grid_count, 0.5);
    samples[4] = std::nan("");
    auto nan = BoxCorrelation::from_grid(samples);
    REQUIRE_FALSE(nan);
    CHECK(nan.error().message.find("sample 4 must be finite") != std::string::npos);
    samples[4] = 1.5;
    REQUIRE_FALSE(BoxCorrelation::from_grid(samples));
    samples[4] = 0.5;
    samples[0] = 0.0;
    auto flat = BoxCorrelation::from_grid(samples);
    REQUIRE_FALSE(flat);
    CHECK(flat.error().message.find("must start above 0") != std::string::npos);
}
