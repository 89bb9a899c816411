// SPDX-License-Identifier: Apache-2.0
// Gradient (Perlin) and value noise: determinism per seed, zeros at the
// lattice, documented bounds, and mean / variance against independent
// quadrature of the ensemble formulas (docs/noise.md):
//     Var n = integral over a cell of sum_c w_c(p)^2 E[<g, p - c>^2]  (gradient)
//     Var n = E[v^2] (integral_0^1 fade(t)^2 + (1 - fade(t))^2 dt)^D  (value)
// where the lattice draws are independent with zero mean, so cross terms vanish.
#include "cmfilter/noise/gradient_noise.h"
#include "cmfilter/noise/value_noise.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

using namespace cmfilter;

namespace {

// Test-side twin of the fade, from Perlin 2002: 6t^5 - 15t^4 + 10t^3.
double fade(double t) { return t * t * t * (10 - 15 * t + 6 * t * t); }

// Corner weight along one axis: fade(t) for the upper corner, 1 - fade(t) for the lower.
double axis_weight(double t, int corner) { return corner ? fade(t) : 1 - fade(t); }

const std::vector<std::array<double, 3>>& edge_gradients()
{
    static const std::vector<std::array<double, 3>> g = {{1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0},
                                                         {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
                                                         {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}};
    return g;
}

struct Moments {
    double mean = 0, variance = 0;
};

template <typename Sample>
Moments sample_moments(int count, Sample&& sample)
{
    double sum = 0, sum2 = 0;
    for (int i = 0; i < count; ++i) {
        const double v = sample();
        sum += v;
        sum2 += v * v;
    }
    const double mean = sum / count;
    return {mean, sum2 / count - mean * mean};
}

}  // namespace

TEST_CASE("lattice noises are deterministic per seed and differ between seeds")
{
    const GradientNoise a(7), b(7), c(8);
    const ValueNoise va(7), vb(7), vc(8);
    int differ = 0, vdiffer = 0;
    for (int i = 0; i < 100; ++i) {
        const double x = 0.37 * i + 0.11, y = 1.7 * i - 3.2, z = 0.05 * i;
        CHECK(a(x, y) == b(x, y));  // same seed: bit-identical
        CHECK(a(x, y, z) == b(x, y, z));
        CHECK(va(x, y) == vb(x, y));
        CHECK(va(x, y, z) == vb(x, y, z));
        differ += a(x, y) != c(x, y);
        vdiffer += va(x, y) != vc(x, y);
    }
    // Equal values at an off-lattice point under two seeds need equal gradients
    // at all four corners by chance: a few coincidences at most.
    CHECK(differ > 90);
    CHECK(vdiffer > 90);
}

TEST_CASE("gradient noise is zero at every lattice point")
{
    const GradientNoise noise(3);
    for (int i = -20; i <= 20; i += 3)
        for (int j = -300; j <= 300; j += 37) {
            CHECK(noise(i, j) == 0.0);  // exact: only the own corner has weight, at offset 0
            CHECK(noise(i, j, i - j) == 0.0);
        }
}

TEST_CASE("lattice noises repeat every 256 units")
{
    const GradientNoise g(11);
    const ValueNoise v(11);
    for (double x : {0.3, 17.8, -5.25})
        for (double y : {0.9, 100.1}) {
            // The shifted coordinate rounds differently in its last bits: 1e-12.
            CHECK(std::fabs(g(x, y) - g(x + 256, y - 512)) < 1e-12);
            CHECK(std::fabs(v(x, y, 2.5) - v(x - 256, y, 2.5 + 256)) < 1e-12);
        }
}

TEST_CASE("gradient noise envelope maxima match the documented bounds")
{
    // |n(p)| <= E(p) = sum_c w_c(p) max_g |<g, p - c>| for any gradient draw.
    // 2-D, 8 unit gradients: E is maximal at the cell centre, sqrt(2)/2.
    const double pi = 3.14159265358979323846;
    double max2 = 0;
    for (int i = 0; i <= 100; ++i)
        for (int j = 0; j <= 100; ++j) {
            const double x = i / 100.0, y = j / 100.0;
            double e = 0;
            for (int cx = 0; cx < 2; ++cx)
                for (int cy = 0; cy < 2; ++cy) {
                    double best = 0;
                    for (int k = 0; k < 8; ++k)
                        best = std::max(best,
                                        std::fabs(std::cos(k * pi / 4) * (x - cx) + std::sin(k * pi / 4) * (y - cy)));
                    e += axis_weight(x, cx) * axis_weight(y, cy) * best;
                }
            max2 = std::max(max2, e);
        }
    // The grid contains the centre, where E = 4 (1/4) sqrt(1/2) exactly; 1e-12 is rounding.
    CHECK(std::fabs(max2 - std::sqrt(0.5)) < 1e-12);
    CHECK(max2 <= GradientNoise::bound_2d + 1e-12);

    // 3-D, 12 edge gradients: grid search, then a pattern search from the best node.
    auto envelope3 = [](const std::array<double, 3>& p) {
        double e = 0;
        for (int c = 0; c < 8; ++c) {
            const int cx = c & 1, cy = (c >> 1) & 1, cz = c >> 2;
            double best = 0;
            for (const auto& g : edge_gradients())
                best = std::max(best, std::fabs(g[0] * (p[0] - cx) + g[1] * (p[1] - cy) + g[2] * (p[2] - cz)));
            e += axis_weight(p[0], cx) * axis_weight(p[1], cy) * axis_weight(p[2], cz) * best;
        }
        return e;
    };
    std::array<double, 3> best_p{0.5, 0.5, 0.5};
    double best = envelope3(best_p);
    CHECK(std::fabs(best - 1.0) < 1e-12);  // the centre: 8 (1/8) (1/2 + 1/2)
    for (int i = 0; i <= 24; ++i)
        for (int j = 0; j <= 24; ++j)
            for (int k = 0; k <= 24; ++k) {
                const std::array<double, 3> p{i / 24.0, j / 24.0, k / 24.0};
                const double e = envelope3(p);
                if (e > best) best = e, best_p = p;
            }
    for (double step = 0.02; step > 1e-7;) {
        bool improved = false;
        for (int axis = 0; axis < 3; ++axis)
            for (double s : {-step, step}) {
                auto p = best_p;
                p[axis] = std::clamp(p[axis] + s, 0.0, 1.0);
                const double e = envelope3(p);
                if (e > best) best = e, best_p = p, improved = true;
            }
        if (!improved) step /= 2;
    }
    CAPTURE(best);
    CHECK(best > 1.03);                      // the maximum lies off the centre...
    CHECK(best <= GradientNoise::bound_3d);  // ...and under the documented bound
}

TEST_CASE("lattice noises stay within their bounds over random points")
{
    std::mt19937_64 rng(1234);
    std::uniform_real_distribution<double> coord(-300.0, 300.0);
    const GradientNoise g(5);
    const ValueNoise v(5);
    double max_g2 = 0, max_g3 = 0, max_v2 = 0, max_v3 = 0;
    for (int i = 0; i < 200000; ++i) {
        const double x = coord(rng), y = coord(rng), z = coord(rng);
        max_g2 = std::max(max_g2, std::fabs(g(x, y)));
        max_g3 = std::max(max_g3, std::fabs(g(x, y, z)));
        max_v2 = std::max(max_v2, std::fabs(v(x, y)));
        max_v3 = std::max(max_v3, std::fabs(v(x, y, z)));
    }
    CAPTURE(max_g2);
    CAPTURE(max_g3);
    CHECK(max_g2 <= GradientNoise::bound_2d);
    CHECK(max_g3 <= GradientNoise::bound_3d);
    CHECK(max_v2 <= ValueNoise::bound);
    CHECK(max_v3 <= ValueNoise::bound);
    // The bounds are not loose: random points come within 15% of them.
    CHECK(max_g2 > 0.85 * GradientNoise::bound_2d);
    CHECK(max_v2 > 0.85 * ValueNoise::bound);
}

TEST_CASE("lattice noise mean and variance match the ensemble formulas")
{
    // Ensemble variances by midpoint quadrature over one cell (polynomial
    // integrands, error ~ h^2 ~ 1e-6 with 1000 nodes per axis in 2-D, ~3e-4 with
    // 60 in 3-D), using E[g g^T] of each gradient set over the 256 hash values:
    // 2-D: 8 unit vectors, 32 hashes each: E[g g^T] = I / 2.
    // 3-D: h mod 12: edges 0-3 get 22 hashes, 4-11 get 21: E[g_k^2] = 172, 172, 168 / 256.
    const int n2 = 1000;
    double var_g2 = 0, value_weight_1d = 0;
    for (int i = 0; i < n2; ++i) {
        const double t = (i + 0.5) / n2;
        value_weight_1d += (std::pow(axis_weight(t, 0), 2) + std::pow(axis_weight(t, 1), 2)) / n2;
        for (int j = 0; j < n2; ++j) {
            const double s = (j + 0.5) / n2;
            for (int c = 0; c < 4; ++c) {
                const int cx = c & 1, cy = c >> 1;
                const double w = axis_weight(t, cx) * axis_weight(s, cy);
                var_g2 += w * w * 0.5 * ((t - cx) * (t - cx) + (s - cy) * (s - cy)) / (double(n2) * n2);
            }
        }
    }
    std::array<double, 3> second{0, 0, 0};
    for (std::size_t e = 0; e < 12; ++e)
        for (int k = 0; k < 3; ++k)
            second[k] += edge_gradients()[e][k] * edge_gradients()[e][k] * (e < 4 ? 22.0 : 21.0) / 256.0;
    const int n3 = 60;
    double var_g3 = 0;
    for (int i = 0; i < n3; ++i)
        for (int j = 0; j < n3; ++j)
            for (int k = 0; k < n3; ++k) {
                const double p[3] = {(i + 0.5) / n3, (j + 0.5) / n3, (k + 0.5) / n3};
                for (int c = 0; c < 8; ++c) {
                    const int cc[3] = {c & 1, (c >> 1) & 1, c >> 2};
                    double w = 1, q = 0;
                    for (int a = 0; a < 3; ++a) {
                        w *= axis_weight(p[a], cc[a]);
                        q += second[a] * (p[a] - cc[a]) * (p[a] - cc[a]);
                    }
                    var_g3 += w * w * q / (double(n3) * n3 * n3);
                }
            }
    double value_second = 0;  // E[v^2] over the 256 equally likely lattice values
    for (int h = 0; h < 256; ++h) value_second += std::pow(2.0 * h / 255.0 - 1.0, 2) / 256.0;
    const double var_v2 = value_second * value_weight_1d * value_weight_1d;
    const double var_v3 = var_v2 * value_weight_1d;

    // Samples uniform over one period (256 units per axis), pooled over 16
    // seeds. The period mean is exactly 0 for both noises (each lattice term
    // integrates to 0: odd gradient terms; value terms sum 2h/255 - 1 over
    // every h equally often), so the sample mean may stray only by Monte-Carlo
    // error: 5 sd / sqrt(N).
    // One seed's period variance differs from the ensemble's: the hash
    // perm[perm[i] + j] makes every lattice row a shifted copy of one sequence
    // of 256, far fewer independent draws than 65536 (measured spread across
    // seeds: 3.5% sd for 2-D gradient noise, the worst). Pooling 16 seeds
    // brings that to ~0.9%, Monte-Carlo error adds sqrt(2 / N) = 0.3%: 4% is
    // over 4 sd.
    const int seeds = 16, per_seed = 16000, count = seeds * per_seed;
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> coord(0.0, 256.0);
    auto pooled = [&](auto&& sample_one_seed) {
        int n = 0;
        std::uint64_t seed = 0;
        std::function<double()> draw;
        return sample_moments(count, [&] {
            if (n++ % per_seed == 0) draw = sample_one_seed(seed++);
            return draw();
        });
    };
    struct Case {
        const char* name;
        Moments m;
        double expected_variance;
    };
    const Case cases[] = {
        {"gradient 2-D", pooled([&](std::uint64_t s) -> std::function<double()> {
             return [&, g = GradientNoise(s)] { return g(coord(rng), coord(rng)); };
         }),
         var_g2},
        {"gradient 3-D", pooled([&](std::uint64_t s) -> std::function<double()> {
             return [&, g = GradientNoise(s)] { return g(coord(rng), coord(rng), coord(rng)); };
         }),
         var_g3},
        {"value 2-D", pooled([&](std::uint64_t s) -> std::function<double()> {
             return [&, v = ValueNoise(s)] { return v(coord(rng), coord(rng)); };
         }),
         var_v2},
        {"value 3-D", pooled([&](std::uint64_t s) -> std::function<double()> {
             return [&, v = ValueNoise(s)] { return v(coord(rng), coord(rng), coord(rng)); };
         }),
         var_v3},
    };
    for (const Case& c : cases) {
        const std::string name = c.name;
        CAPTURE(name);
        CAPTURE(c.m.variance);
        CAPTURE(c.expected_variance);
        CHECK(std::fabs(c.m.mean) < 5 * std::sqrt(c.expected_variance / count));
        CHECK(std::fabs(c.m.variance / c.expected_variance - 1) < 0.04);
    }
}
