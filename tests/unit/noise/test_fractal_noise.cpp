// SPDX-License-Identifier: Apache-2.0
// fBm and turbulence over a base noise, their filtered mean over a footprint,
// and the per-LOD sigma table a FilteredNoise looks up.
#include "cmfilter/noise/filtered_noise.h"
#include "cmfilter/noise/gradient_noise.h"

#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace cmfilter;

namespace {

BaseNoise gradient_base(std::uint64_t seed)
{
    const GradientNoise g(seed);
    BaseNoise base;
    base.evaluate = [g](double x, double y) { return g(x, y); };
    base.mean_abs = measure_mean_abs(base.evaluate, 1.0);
    return base;
}

FractalNoise make_fractal(FractalSum sum, int octaves = 6, double lacunarity = 2.0, double gain = 0.5)
{
    FractalOptions o;
    o.octaves = octaves;
    o.lacunarity = lacunarity;
    o.gain = gain;
    o.sum = sum;
    auto f = FractalNoise::create(gradient_base(4), o, 77);
    REQUIRE(f);
    return *f;
}

}  // namespace

TEST_CASE("fbm variance is the gain-weighted sum of octave variances")
{
    // Var f = sum_i gain^(2i) Var t_i + 2 sum_{i<j} gain^(i+j) Cov(t_i, t_j);
    // the domain shifts decorrelate the octaves, so the covariances vanish.
    // Both sides come from the same sample points, so their difference is the
    // sample covariance sum alone; with independent octaves each sample
    // covariance has sd sqrt(Var t_i Var t_j / N): the check allows 5 sd of
    // the weighted sum (sds added, a bound on any correlation between them).
    for (double lacunarity : {2.0, 1.93}) {
        CAPTURE(lacunarity);
        const FractalNoise f = make_fractal(FractalSum::Fbm, 5, lacunarity, 0.6);
        const int n = f.options().octaves, count = 100000;
        std::mt19937_64 rng(3);
        std::uniform_real_distribution<double> coord(0.0, 256.0);
        std::vector<double> s(n, 0.0), s2(n, 0.0);
        std::vector<std::vector<double>> cross(n, std::vector<double>(n, 0.0));
        double sf = 0, sf2 = 0;
        for (int k = 0; k < count; ++k) {
            const double x = coord(rng), y = coord(rng);
            std::vector<double> t(n);
            for (int i = 0; i < n; ++i) t[i] = f.octave(i, x, y);
            const double total = f(x, y);
            sf += total;
            sf2 += total * total;
            for (int i = 0; i < n; ++i) {
                s[i] += t[i];
                for (int j = 0; j < n; ++j) cross[i][j] += t[i] * t[j];
            }
        }
        double sum_var = 0, allowance = 0;
        std::vector<double> var(n);
        for (int i = 0; i < n; ++i) var[i] = cross[i][i] / count - (s[i] / count) * (s[i] / count);
        for (int i = 0; i < n; ++i) {
            sum_var += std::pow(0.6, 2 * i) * var[i];
            for (int j = i + 1; j < n; ++j)
                allowance += 2 * std::pow(0.6, i + j) * 5 * std::sqrt(var[i] * var[j] / count);
        }
        const double var_f = sf2 / count - (sf / count) * (sf / count);
        CAPTURE(var_f);
        CAPTURE(sum_var);
        CAPTURE(allowance);
        CHECK(std::fabs(var_f - sum_var) < allowance);
        CHECK(allowance < 0.05 * sum_var);  // and the allowance is tight
    }
}

TEST_CASE("turbulence is non-negative with mean the gain-weighted mean of the absolute base")
{
    const FractalNoise f = make_fractal(FractalSum::Turbulence, 4, 2.0, 0.5);
    // An independent E|n| of the base: plain uniform random sampling (the library
    // measures it on a jittered grid).
    const GradientNoise g(4);
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> coord(0.0, 256.0);
    const int count = 100000;
    double abs_sum = 0, abs2 = 0, f_sum = 0;
    for (int k = 0; k < count; ++k) {
        const double a = std::fabs(g(coord(rng), coord(rng)));
        abs_sum += a;
        abs2 += a * a;
        const double v = f(coord(rng), coord(rng));
        CHECK(v >= 0.0);
        f_sum += v;
    }
    const double mean_abs = abs_sum / count;
    const double sd_abs = std::sqrt(abs2 / count - mean_abs * mean_abs);
    // Two estimates of E|n|, each with Monte-Carlo sd <= sd|n| / sqrt(N) (the
    // jittered grid does better) and a seed-realisation spread of a few percent
    // (test_lattice_noise.cpp), here the same seed: 5 sd plus 1%.
    CHECK(std::fabs(f.base().mean_abs - mean_abs) < 5 * sd_abs / std::sqrt(count) + 0.01 * mean_abs);
    const double expected = mean_abs * (1 + 0.5 + 0.25 + 0.125);
    // The fractal mean from its own samples: sd of the sum <= sum of octave sds.
    CHECK(std::fabs(f_sum / count - expected) < 5 * sd_abs * 1.875 / std::sqrt(count) + 0.01 * expected);
}

TEST_CASE("filtered mean is the point value for a point and the octave mean past the cutoff")
{
    for (FractalSum sum : {FractalSum::Fbm, FractalSum::Turbulence}) {
        const FractalNoise f = make_fractal(sum);
        const double finest = f.octave_period(f.options().octaves - 1);
        const double cutoff = f.term_correlation().cutoff();
        double mean_sum = 0;
        for (int i = 0; i < f.options().octaves; ++i) mean_sum += f.octave_amplitude(i) * f.octave_mean();
        for (double x : {0.3, 17.25, 140.9})
            for (double y : {5.5, 99.01}) {
                // A point keeps every octave whole: the same sum, exactly.
                CHECK(f.mean_over_footprint(x, y, 0.0) == f(x, y));
                // A footprint 1/4096 of the finest period: the box mean moves by
                // O(w^2) of the curvature, far below 1e-5.
                CHECK(std::fabs(f.mean_over_footprint(x, y, finest / 4096) - f(x, y)) < 1e-5);
                // Every octave past its cutoff: the octave means, exactly.
                CHECK(f.mean_over_footprint(x, y, cutoff * f.base_period()) == mean_sum);
                CHECK(f.mean_over_footprint(x, y, 1e6) == mean_sum);
            }
        if (sum == FractalSum::Fbm) CHECK(mean_sum == 0.0);
        else CHECK(mean_sum > 0.1);
    }
}

TEST_CASE("filtered mean leaves a residual uncorrelated with every octave it evaluates")
{
    // The filtered mean is the least-squares prediction of the footprint's
    // box mean T from the octaves' centre values, so the residual T - mean_w
    // must be uncorrelated with each t_i(x) (the normal equations). T by
    // 32 x 32 midpoint quadrature, 1500 footprints; |corr| within 4 standard
    // errors (1 / sqrt(1500)) plus the quadrature's share.
    for (FractalSum sum : {FractalSum::Fbm, FractalSum::Turbulence}) {
        const FractalNoise f = make_fractal(sum, 3);
        for (double w : {0.25, 0.5, 1.0}) {
            std::mt19937_64 rng(99);
            std::uniform_real_distribution<double> centre(0.0, 256.0);
            const int n = 1500, q = 32;
            std::vector<double> residual(n);
            std::vector<std::vector<double>> term(3, std::vector<double>(n));
            for (int k = 0; k < n; ++k) {
                const double x = centre(rng), y = centre(rng);
                double box = 0;
                for (int a = 0; a < q; ++a)
                    for (int b = 0; b < q; ++b) box += f(x + w * ((a + 0.5) / q - 0.5), y + w * ((b + 0.5) / q - 0.5));
                residual[static_cast<std::size_t>(k)] = box / (q * q) - f.mean_over_footprint(x, y, w);
                for (int i = 0; i < 3; ++i)
                    term[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] = f.octave(i, x, y);
            }
            for (int i = 0; i < 3; ++i) {
                if (f.resolved_fraction(i, w) == 0.0) continue;  // not evaluated
                const auto& t = term[static_cast<std::size_t>(i)];
                double rm = 0, tm = 0;
                for (int k = 0; k < n; ++k) {
                    rm += residual[static_cast<std::size_t>(k)];
                    tm += t[static_cast<std::size_t>(k)];
                }
                rm /= n;
                tm /= n;
                double srr = 0, stt = 0, srt = 0;
                for (int k = 0; k < n; ++k) {
                    const double dr = residual[static_cast<std::size_t>(k)] - rm,
                                 dt = t[static_cast<std::size_t>(k)] - tm;
                    srr += dr * dr;
                    stt += dt * dt;
                    srt += dr * dt;
                }
                const double corr = srt / std::sqrt(srr * stt);
                CAPTURE(to_string(sum));
                CAPTURE(w);
                CAPTURE(i);
                CAPTURE(corr);
                CHECK(std::fabs(corr) < 4.0 / std::sqrt(double(n)) + 0.02);
            }
        }
    }
}

TEST_CASE("filtered mean is continuous in the footprint width")
{
    // |d mean / d ln w| <= sum_i gain^i |t_i - mu| max|d beta / d log2 k| / ln 2
    //                  <= 2 (0.71 + 0.71) 1.5 / 0.69 ~ 6.2 (beta falls from 1
    // to 0 over about two octaves, its taper at most 0.05 over half of one),
    // so a step from w to w (1 + 1e-6) moves the mean by at most ~6.2e-6: a
    // jump above 1e-5 anywhere would be popping.
    for (FractalSum sum : {FractalSum::Fbm, FractalSum::Turbulence}) {
        const FractalNoise f = make_fractal(sum);
        double worst = 0;
        for (double x : {0.37, 45.2})
            for (double lw = -9; lw <= 3; lw += 0.01) {
                const double w = std::exp2(lw);
                worst = std::max(worst, std::fabs(f.mean_over_footprint(x, 1.3 * x, w * (1 + 1e-6)) -
                                                  f.mean_over_footprint(x, 1.3 * x, w)));
            }
        CAPTURE(worst);
        CHECK(worst < 1e-5);
    }
}

TEST_CASE(
    "resolved fraction is one at a point, the same function of w / p_i for every octave, and zero past the cutoff")
{
    const FractalNoise f = make_fractal(FractalSum::Fbm, 3);
    const double cutoff = f.term_correlation().cutoff();
    for (int i = 0; i < 3; ++i) {
        const double p = f.octave_period(i);
        CHECK(f.resolved_fraction(i, 0.0) == 1.0);
        CHECK(f.resolved_fraction(i, cutoff * p) == 0.0);
        for (double k : {0.1, 0.5, 1.0, 1.7})
            CHECK(f.resolved_fraction(i, k * p) == doctest::Approx(f.resolved_fraction(0, k * f.octave_period(0))));
        // Falls from 1 while the footprint grows to two periods (gradient
        // noise: the correlation is positive and decreasing there).
        double previous = 1.0;
        for (double t = -6; t <= 1; t += 1.0 / 64) {
            const double a = f.resolved_fraction(i, p * std::exp2(t));
            CHECK(a <= previous + 1e-12);
            previous = a;
        }
    }
}

TEST_CASE("fractal options are validated with the bad value named")
{
    FractalOptions o;
    o.lacunarity = 1.0;
    auto r = FractalNoise::create(gradient_base(1), o, 0);
    REQUIRE_FALSE(r);
    CHECK(r.error().kind == ErrorKind::BadInput);
    CHECK(r.error().message.find("lacunarity") != std::string::npos);
    o = {};
    o.octaves = 0;
    r = FractalNoise::create(gradient_base(1), o, 0);
    REQUIRE_FALSE(r);
    CHECK(r.error().message.find("octaves must be in [1, 64], got 0") != std::string::npos);
}

TEST_CASE("noise sigma table interpolates linearly in LOD and holds its ends")
{
    auto t = NoiseSigmaTable::create(-4.0, 0.5, {0.0, 0.1, 0.3, 0.35});
    REQUIRE(t);
    CHECK(t->lod_last() == -2.5);
    // Nodes and midpoints: exact in binary up to rounding of one lerp (1e-15).
    CHECK(t->sigma_at(-4.0) == 0.0);
    CHECK(std::fabs(t->sigma_at(-3.5) - 0.1) < 1e-15);
    CHECK(std::fabs(t->sigma_at(-3.25) - 0.2) < 1e-15);
    CHECK(std::fabs(t->sigma_at(-2.625) - 0.3375) < 1e-15);
    CHECK(t->sigma_at(-100.0) == 0.0);
    CHECK(t->sigma_at(-2.5) == 0.35);
    CHECK(t->sigma_at(7.0) == 0.35);
    CHECK(std::isnan(t->sigma_at(std::nan(""))));

    auto bad = NoiseSigmaTable::create(0.0, 0.0, {1.0});
    REQUIRE_FALSE(bad);
    CHECK(bad.error().message.find("LOD step") != std::string::npos);
    bad = NoiseSigmaTable::create(0.0, 1.0, {1.0, -0.5});
    REQUIRE_FALSE(bad);
    CHECK(bad.error().message.find("sigma 1") != std::string::npos);
}

TEST_CASE("filtered noise looks the sigma table up at log2 of width over base period")
{
    FractalOptions o;
    o.octaves = 3;
    BaseNoise base = gradient_base(2);
    base.period = 4.0;  // a base noise with features 4 units wide
    auto f = FractalNoise::create(base, o, 1);
    REQUIRE(f);
    auto table = NoiseSigmaTable::create(-3.0, 1.0, {0.0, 0.2, 0.4, 0.5, 0.55});
    REQUIRE(table);
    const FilteredNoise filtered(*f, *table);
    CHECK(filtered.lod(4.0) == 0.0);
    CHECK(filtered.unresolved_sigma(4.0) == 0.5);                                       // LOD 0: node 3
    CHECK(filtered.unresolved_sigma(1.0) == 0.2);                                       // LOD -2: node 1
    CHECK(std::fabs(filtered.unresolved_sigma(4.0 * std::sqrt(2.0)) - 0.525) < 1e-12);  // LOD 1/2
    CHECK(filtered.unresolved_sigma(0.0) == 0.0);  // a point: LOD -inf, the first node
    CHECK(filtered.mean_over_footprint(1.5, 2.5, 0.25) == f->mean_over_footprint(1.5, 2.5, 0.25));
    // filter() gives both at once, from one log2 of the width.
    for (double w : {0.0, 0.01, 0.25, 4.0 * std::sqrt(2.0), 100.0}) {
        const FilteredNoise::Parameters p = filtered.filter(1.5, 2.5, w);
        CHECK(p.mean == f->mean_over_footprint(1.5, 2.5, w));
        CHECK(p.sigma == doctest::Approx(filtered.unresolved_sigma(w)).epsilon(1e-14));
    }
}
