// SPDX-License-Identifier: Apache-2.0
// The Monte-Carlo noise sigma table (noise_sigma_bake.h): checked against the
// law of total variance, the analytic Gabor variance and an independent
// brute-force measurement between table nodes; the table file round trip.
#include "cmfilter/noise/noise_image.h"
#include "cmfilter/noise/noise_sigma_bake.h"
#include "cmfilter/noise/noise_sigma_table_file.h"
#include "cmfilter/noise/noise_spec.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

using namespace cmfilter;

namespace {

constexpr double kZ95 = 1.959963984540054;

FractalNoise noise_from(const std::string& text)
{
    auto spec = parse_noise_spec(text);
    REQUIRE(spec);
    auto noise = make_noise(*spec);
    REQUIRE(noise);
    return *noise;
}

// Mean and unbiased variance of xs, and the 95% half-width of that variance
// from the sample fourth moment: 1.96 sqrt((m4 - m2^2) / n).
struct VarianceCi {
    double mean = 0, variance = 0, half_width = 0;
};

VarianceCi variance_ci(const std::vector<double>& xs)
{
    const double n = static_cast<double>(xs.size());
    VarianceCi r;
    for (double x : xs) r.mean += x;
    r.mean /= n;
    double m2 = 0, m4 = 0;
    for (double x : xs) {
        const double d2 = (x - r.mean) * (x - r.mean);
        m2 += d2;
        m4 += d2 * d2;
    }
    m2 /= n;
    m4 /= n;
    r.variance = m2 * n / (n - 1);
    r.half_width = kZ95 * std::sqrt((m4 - m2 * m2) / n);
    return r;
}

}  // namespace

TEST_CASE("law of total variance holds between independent sample sets at three LODs")
{
    // Var f = Var_c(E[f | c]) + E_c[Var(f | c)] for footprint centres c uniform
    // over one period of the noise (a 2-octave lacunarity-2 gradient fBm has
    // period 256, the domain the centres cover, so c + offset is uniform too).
    // Gaussian footprints: S independent samples each, so the footprint sample
    // means m_j have Var_j(m_j) = Var(E[f | c]) + E[v] / S; hence
    //   total = Var_j(m_j) + (1 - 1/S) mean_j v_j.
    // Left: the global variance of one sample set; right: footprints of an
    // independent set. Tolerance: the combined 95% interval, left and right
    // half-widths in quadrature (independent sets), the right one the sum of
    // its two terms' half-widths (they share samples: a bound on any
    // correlation).
    const FractalNoise noise = noise_from("fbm:base=gradient,octaves=2,seed=3");
    const NoiseGlobalStats global = measure_global_stats(noise, 1 << 18, 11, 2);
    const int s = 32, f = 1 << 15;
    for (double lod : {-3.0, -0.5, 1.5}) {
        CAPTURE(lod);
        const double w = noise.base_period() * std::exp2(lod);
        const auto fps = sample_footprints(noise, FootprintShape::Gaussian, w, s, 99, 7, 0, f, 2);
        std::vector<double> means;
        for (const auto& fp : fps) means.push_back(fp.mean);
        const VarianceCi between = variance_ci(means);
        const SigmaEstimate within = estimate_sigma(fps, s);
        const double right = between.variance + (1.0 - 1.0 / s) * within.mean_variance;
        const double right_hw = between.half_width + within.variance_half_width;
        const double tol = std::sqrt(global.variance_half_width * global.variance_half_width + right_hw * right_hw);
        CAPTURE(global.variance);
        CAPTURE(right);
        CAPTURE(tol);
        CHECK(std::abs(global.variance - right) <= tol);
        // The split is not degenerate: both parts carry variance at these LODs.
        CHECK(within.mean_variance > 0.02 * global.variance);
        CHECK(between.variance > 0.02 * global.variance);
    }
}

TEST_CASE("Gabor noise global variance matches the analytic variance within its confidence interval")
{
    // Var n = lambda K^2 / (12 a^2) (1 + exp(-2 pi F0^2 / a^2)) (gabor_noise.h).
    // 20000 samples over 256 x 256 units: about 1.8 units apart, beyond the
    // kernel's correlation length 1 / a = 1.25, so the samples are close to
    // independent and the iid 95% interval applies.
    const FractalNoise noise = noise_from("gabor:seed=4");
    const NoiseGlobalStats g = measure_global_stats(noise, 20000, 5, 2);
    const double analytic = GaborNoise::analytic_variance(GaborNoiseOptions{});
    CAPTURE(g.variance);
    CAPTURE(g.variance_half_width);
    CHECK(std::abs(g.variance - analytic) <= g.variance_half_width);
    // The weights are symmetric about 0, so n is: skewness 0 (tolerance 0.1,
    // about 5 standard errors sqrt(6 / N) = 0.017). Campbell's theorem gives
    // the fourth cumulant lambda E[w^4] integral g^4 > 0: excess kurtosis is
    // positive (measured 0.29; its standard error sqrt(24 / N) = 0.035).
    CHECK(std::abs(g.skewness) < 0.1);
    CHECK(g.excess_kurtosis > 0);
}

namespace {

// Independent brute force for the test below: its own generator
// (std::mt19937_64, another seed), plain uniform (not stratified) box
// samples and std::normal_distribution Gaussian offsets.
SigmaEstimate brute_force_sigma(const FractalNoise& noise, FootprintShape shape, double w, int footprints, int samples,
                                std::uint64_t seed)
{
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> centre(0.0, 256.0 * noise.base_period()), unit(-0.5, 0.5);
    std::normal_distribution<double> normal(0.0, 0.5 * w);
    std::vector<FootprintMoments> fps;
    std::vector<double> f(static_cast<std::size_t>(samples));
    for (int j = 0; j < footprints; ++j) {
        const double cx = centre(rng), cy = centre(rng);
        for (auto& v : f) {
            const double dx = shape == FootprintShape::Box ? w * unit(rng) : normal(rng);
            const double dy = shape == FootprintShape::Box ? w * unit(rng) : normal(rng);
            v = noise(cx + dx, cy + dy);
        }
        double mean = 0, ss = 0;
        for (double v : f) mean += v;
        mean /= samples;
        for (double v : f) ss += (v - mean) * (v - mean);
        fps.push_back({mean, ss / (samples - 1)});
    }
    return estimate_sigma(fps, samples);
}

}  // namespace

TEST_CASE("table values between nodes reproduce a brute-force measurement")
{
    // Tolerance: 2% of sigma or the combined 95% interval (table half-width,
    // the larger of its two nodes', and the brute force's, in quadrature),
    // whichever is larger: linear interpolation in LOD over a 0.25 step plus
    // Monte-Carlo noise on both sides.
    const FractalNoise noise = noise_from("fbm:base=gradient,octaves=2,seed=8");
    NoiseSigmaBakeOptions o;
    o.relative_half_width = 0.01;  // test speed; the CLI default is 0.005
    o.max_footprints = 8192;
    o.global_samples = 4096;
    o.threads = 2;
    auto bake = bake_noise_sigma(noise, o);
    REQUIRE(bake);
    CHECK(bake->lod_first == doctest::Approx(-5.0));  // 1/16 of the finest period 1/2
    CHECK(bake->rows.back().lod == doctest::Approx(2.0));
    for (FootprintShape shape : {FootprintShape::Box, FootprintShape::Gaussian}) {
        auto table = bake->table(shape);
        REQUIRE(table);
        for (std::size_t k : {std::size_t{2}, std::size_t{13}, std::size_t{25}}) {
            const double lod = bake->rows[k].lod + 0.5 * bake->lod_step;
            const std::string shape_name = to_string(shape);
            CAPTURE(shape_name);
            CAPTURE(lod);
            const auto& a = shape == FootprintShape::Box ? bake->rows[k].box : bake->rows[k].gaussian;
            const auto& b = shape == FootprintShape::Box ? bake->rows[k + 1].box : bake->rows[k + 1].gaussian;
            const SigmaEstimate brute = brute_force_sigma(noise, shape, std::exp2(lod), 8192, 64, 12345 + k);
            const double got = table->sigma_at(lod);
            const double ci = std::hypot(std::max(a.half_width, b.half_width), brute.half_width);
            CAPTURE(got);
            CAPTURE(brute.sigma);
            CHECK(std::abs(got - brute.sigma) <= std::max(0.02 * brute.sigma, ci));
        }
    }
}

TEST_CASE("bake reaches its confidence target and is deterministic per seed")
{
    const FractalNoise noise = noise_from("value:seed=2");
    NoiseSigmaBakeOptions o;
    o.lod_step = 1.0;
    o.global_samples = 4096;
    o.max_footprints = 1 << 16;
    o.threads = 2;
    auto a = bake_noise_sigma(noise, o);
    o.threads = 1;
    auto b = bake_noise_sigma(noise, o);
    REQUIRE(a);
    REQUIRE(b);
    REQUIRE(a->rows.size() == b->rows.size());
    for (std::size_t k = 0; k < a->rows.size(); ++k) {
        CAPTURE(a->rows[k].lod);
        for (const SigmaEstimate* e : {&a->rows[k].box, &a->rows[k].gaussian})
            CHECK((e->half_width <= 0.005 * e->sigma || e->footprints == o.max_footprints));
        CHECK(a->rows[k].box.sigma == b->rows[k].box.sigma);  // bit for bit, any thread count
        CHECK(a->rows[k].gaussian.sigma == b->rows[k].gaussian.sigma);
    }
    // sigma grows with the footprint (more of the noise unresolved inside it).
    CHECK(a->rows.front().box.sigma < a->rows.back().box.sigma);
}

TEST_CASE("noise sigma table file round trip and CSV")
{
    const FractalNoise noise = noise_from("gradient:seed=1");
    NoiseSigmaBakeOptions o;
    o.lod_step = 1.0;
    o.max_footprints = 1024;
    o.global_samples = 1024;
    auto bake = bake_noise_sigma(noise, o);
    REQUIRE(bake);
    const auto dir = std::filesystem::temp_directory_path();
    const std::string exr = (dir / "cmfilter-test-sigma.exr").string(),
                      csv = (dir / "cmfilter-test-sigma.csv").string();
    REQUIRE(write_noise_sigma_table(exr, *bake, "gradient:seed=1", 1.0));
    REQUIRE(write_noise_sigma_csv(csv, *bake, 1.0));
    for (FootprintShape shape : {FootprintShape::Box, FootprintShape::Gaussian}) {
        auto loaded = read_noise_sigma_table(exr, shape);
        REQUIRE(loaded);
        CHECK(loaded->noise_spec == "gradient:seed=1");
        CHECK(loaded->table.lod_first() == bake->lod_first);
        REQUIRE(loaded->table.sigmas().size() == bake->rows.size());
        for (std::size_t k = 0; k < bake->rows.size(); ++k) {
            const double want = shape == FootprintShape::Box ? bake->rows[k].box.sigma : bake->rows[k].gaussian.sigma;
            // Stored as float32: relative rounding 2^-24.
            CHECK(loaded->table.sigmas()[k] == doctest::Approx(want).epsilon(1e-7));
        }
    }
    std::ifstream in(csv);
    std::string header;
    std::getline(in, header);
    CHECK(header.rfind("lod,width,box_sigma,box_ci", 0) == 0);
    int lines = 0;
    for (std::string line; std::getline(in, line);) ++lines;
    CHECK(lines == static_cast<int>(bake->rows.size()));
    std::remove(exr.c_str());
    std::remove(csv.c_str());
}

TEST_CASE("reading a file that is not a noise sigma table names its kind")
{
    NoiseImageOptions o;
    o.width = o.height = 4;
    const std::string path = (std::filesystem::temp_directory_path() / "cmfilter-test-not-sigma.exr").string();
    REQUIRE(write_noise_image(path, o));
    auto loaded = read_noise_sigma_table(path, FootprintShape::Box);
    REQUIRE_FALSE(loaded);
    CHECK(loaded.error().kind == ErrorKind::BadInput);
    CHECK(loaded.error().message.find("is not a cmfilter noise sigma table (cmfilter:kind is 'noise-image'") !=
          std::string::npos);
    std::remove(path.c_str());
}

TEST_CASE("within-footprint variance is unbiased for both footprints on a linear function")
{
    // f(x, y) = x: inside a box of width w its variance is w^2 / 12; inside
    // N(c, (w/2)^2 I) it is (w/2)^2, everywhere, so any bias of the estimator
    // shows. For the stratified box the S/(S-1) estimator would be high by
    // about 1/(S-1) = 1.6%; the collapsed-strata one errs high by the squared
    // differences of paired cells' means, (w/8)^2 / S^2 per pair in
    // expectation: 32 (w/8)^2 / S^2 = 0.15% of the variance here.
    // Tolerance: the 95% interval of the mean variance, plus that expected
    // excess for the box.
    BaseNoise linear;
    linear.evaluate = [](double x, double) { return x; };
    FractalOptions one;
    one.octaves = 1;
    auto noise = FractalNoise::create(linear, one, 1);
    REQUIRE(noise);
    const double w = 0.5;
    const int s = 64;
    for (FootprintShape shape : {FootprintShape::Box, FootprintShape::Gaussian}) {
        const std::string shape_name = to_string(shape);
        CAPTURE(shape_name);
        const auto fps = sample_footprints(*noise, shape, w, s, 3, 0, 0, 4096, 2);
        const SigmaEstimate e = estimate_sigma(fps, s);
        const double want = shape == FootprintShape::Box ? w * w / 12 : w * w / 4;
        const double bias_bound = shape == FootprintShape::Box ? (s / 2) * (w / 8) * (w / 8) / (s * double(s)) : 0.0;
        CAPTURE(e.mean_variance);
        CAPTURE(want);
        CHECK(std::abs(e.mean_variance - want) <= e.variance_half_width + bias_bound);
    }
}
