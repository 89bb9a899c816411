// SPDX-License-Identifier: Apache-2.0
// The slope-filtered colour <C_s, D_s> of eq. 20 (slope_color.h) against
// independent computations: the exact D_s colour against a brute-force
// midpoint sum of eq. 20's definition over a Cartesian grid of slopes; both
// colours of a map linear in s against the map at D_s's mean; the Gaussian
// colour of a map sampling a quadratic against the quadratic's closed-form
// mean under the Gaussian of D_s's moments; and every colour finite and
// inside the map's range over sweeps to theta = 90 degrees, vanishing and
// huge spreads, near-singular covariances and large mean slopes.
#include "cmfilter/microsurface/light_weighted_slope_map.h"
#include "cmfilter/microsurface/slope_color.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace cmfilter;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A steepness map over [0, 90] degrees with sharp steps.
SteepnessColorMap steps()
{
    SteepnessColorMap map;
    map.by_angle.vmin = 0, map.by_angle.vmax = 90;
    map.by_angle.texels = {{0.1, 0.4, 0.05}, {0.1, 0.4, 0.05}, {0.5, 0.45, 0.4},
                           {0.9, 0.1, 0.1},  {0.2, 0.2, 0.2},  {0.2, 0.2, 0.9}};
    return map;
}

// 6 x 6 random texels over [-1.5, 1.5]^2.
SlopeVectorColorMap random_vector_map()
{
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0, 1);
    SlopeVectorColorMap map;
    map.width = map.height = 6;
    map.s_max = 1.5;
    for (int i = 0; i < 36; ++i) map.texels.push_back({unit(rng), unit(rng), unit(rng)});
    return map;
}

// Eq. 20 by brute force: the midpoint rule over an n x n grid covering 9
// standard deviations of the slopes about their mean, each slope weighted by
// max(0, <omega_o, n(s)>) / <z, n(s)> p(s) from the facet normal and the
// Gaussian density, normalised by the weights' sum.
// With a light l, each weight is also multiplied by the facet's cosine to it,
// clamped at 0 (the shading correlated with the colour,
// light_weighted_slope_map.h).
template <typename Map>
Rgb brute_force_color(const Map& map, const SlopeGaussian& g, double theta, double phi, int n,
                      const LightDirection* light = nullptr)
{
    const double ox = std::sin(theta) * std::cos(phi), oy = std::sin(theta) * std::sin(phi), oz = std::cos(theta);
    const double det = g.xx * g.yy - g.xy * g.xy;
    const double sx = std::sqrt(g.xx), sy = std::sqrt(g.yy);
    const double hx = 18 * sx / n, hy = 18 * sy / n;
    Rgb sum;
    double total = 0;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const double x = g.mean_x - 9 * sx + (i + 0.5) * hx, y = g.mean_y - 9 * sy + (j + 0.5) * hy;
            const double len = std::sqrt(1 + x * x + y * y);
            double w = std::max(0.0, (ox * -x + oy * -y + oz) / len) / (1 / len);
            if (light) w *= std::max(0.0, (light->x * -x + light->y * -y + light->z) / len);
            const double dx = x - g.mean_x, dy = y - g.mean_y;
            const double q = (g.yy * dx * dx - 2 * g.xy * dx * dy + g.xx * dy * dy) / det;
            const double weight = w * std::exp(-0.5 * q);
            sum += weight * map.evaluate(x, y);
            total += weight;
        }
    }
    return (1 / total) * sum;
}

double largest_channel_difference(const Rgb& a, const Rgb& b)
{
    return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

bool inside(const Rgb& c, const Rgb& lo, const Rgb& hi)
{
    const double slack = 1e-12;
    for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(c[i]) || c[i] < lo[i] - slack || c[i] > hi[i] + slack) return false;
    }
    return true;
}

template <typename Texels>
void texel_range(const Texels& texels, Rgb& lo, Rgb& hi)
{
    lo = hi = texels.front();
    for (const Rgb& t : texels) {
        lo = {std::min(lo.r, t.r), std::min(lo.g, t.g), std::min(lo.b, t.b)};
        hi = {std::max(hi.r, t.r), std::max(hi.g, t.g), std::max(hi.b, t.b)};
    }
}

}  // namespace

TEST_CASE("the exact D_s colour matches a brute-force sum of eq. 20 over a slope grid")
{
    const SteepnessColorMap steep = steps();
    const SlopeVectorColorMap vector = random_vector_map();
    const SlopeGaussian shapes[] = {{0, 0, 0.04, 0, 0.04}, {0.25, -0.15, 0.36, 0.12, 0.16}, {0, 0, 0.64, -0.1, 0.25}};
    double worst = 0;
    for (const SlopeGaussian& g : shapes) {
        for (double degrees : {0.0, 30.0, 60.0, 80.0, 89.9}) {
            for (double phi : {0.0, 2.0, 4.5}) {
                CAPTURE(g.xx);
                CAPTURE(degrees);
                CAPTURE(phi);
                const double theta = degrees * kPi / 180;
                const double a = largest_channel_difference(exact_slope_color(steep, g, {theta, phi}),
                                                            brute_force_color(steep, g, theta, phi, 800));
                const double b = largest_channel_difference(exact_slope_color(vector, g, {theta, phi}),
                                                            brute_force_color(vector, g, theta, phi, 800));
                CHECK(a <= 2e-4);
                CHECK(b <= 2e-4);
                worst = std::max({worst, a, b});
            }
        }
    }
    MESSAGE("largest channel difference: " << worst);
}

TEST_CASE("both slope colours of a map linear in s are the map at D_s's mean")
{
    // Two by two texels over [-20, 20]^2, C(s) = (0.5 + 0.01 s_x, 0.5 + 0.01 s_y,
    // 0.5 + 0.005 (s_x - s_y)) at the centres (+-10, +-10): bilinear
    // interpolation reproduces it exactly between them.
    SlopeVectorColorMap map;
    map.width = map.height = 2;
    map.s_max = 20;
    const auto linear = [](double x, double y) { return Rgb{0.5 + 0.01 * x, 0.5 + 0.01 * y, 0.5 + 0.005 * (x - y)}; };
    map.texels = {linear(-10, 10), linear(10, 10), linear(-10, -10), linear(10, -10)};
    const SlopeGaussian shapes[] = {{0, 0, 0.09, 0, 0.09}, {0.4, -0.3, 0.5, 0.2, 0.3}, {1.5, 0.2, 0.04, 0.01, 0.09}};
    for (const SlopeGaussian& g : shapes) {
        for (double degrees : {0.0, 45.0, 75.0, 89.9, 90.0}) {
            for (double phi : {0.3, 3.0}) {
                CAPTURE(g.mean_x);
                CAPTURE(degrees);
                CAPTURE(phi);
                const ViewAngles view{degrees * kPi / 180, phi};
                const SlopeMoments m = exact_slope_moments(g, view);
                const Rgb expected = linear(m.mean_x, m.mean_y);
                CHECK(largest_channel_difference(exact_slope_color(map, g, view), expected) <= 1e-12);
                CHECK(largest_channel_difference(gaussian_slope_color(map, g, view), expected) <= 1e-12);
            }
        }
    }
}

TEST_CASE("the Gaussian slope colour of a sampled quadratic is the quadratic's mean under D_s's moments")
{
    // q(s) = 0.1 + 0.05 s_x^2 + 0.1 s_x s_y + 0.02 s_y^2 + 0.03 s_y sampled on
    // 1024 x 1024 texels over [-8, 8]^2, spacing h = 1/64. Bilinear
    // interpolation L reproduces the linear and the s_x s_y terms and
    // overestimates each square c x^2 by (x - x_i)(x_{i+1} - x) c in [0, c h^2 / 4],
    // so 0 <= L - q <= 0.07 h^2 / 4 inside the texel centres, and a rule with
    // positive weights summing to 1 that is exact for quadratics (n >= 2
    // points) gives E[q] = q(mean) + 0.05 xx + 0.1 xy + 0.02 yy plus that.
    SlopeVectorColorMap map;
    map.width = map.height = 1024;
    map.s_max = 8;
    const auto q = [](double x, double y) { return 0.1 + 0.05 * x * x + 0.1 * x * y + 0.02 * y * y + 0.03 * y; };
    for (int j = 0; j < map.height; ++j) {
        for (int i = 0; i < map.width; ++i) {
            const double x = -8 + (i + 0.5) * 16.0 / 1024, y = 8 - (j + 0.5) * 16.0 / 1024;
            const double v = q(x, y);
            map.texels.push_back({v, v, v});
        }
    }
    const SlopeGaussian g{0.2, -0.1, 0.3, 0.15, 0.2};
    for (double degrees : {0.0, 50.0, 85.0}) {
        for (int n : {2, 3, 6}) {
            CAPTURE(degrees);
            CAPTURE(n);
            const ViewAngles view{degrees * kPi / 180, 0.7};
            const SlopeMoments m = exact_slope_moments(g, view);
            const double expected = q(m.mean_x, m.mean_y) + 0.05 * m.xx + 0.1 * m.xy + 0.02 * m.yy;
            const double excess = gaussian_slope_color(map, g, view, {n}).g - expected;
            CHECK(excess >= -1e-12);
            CHECK(excess <= 0.07 / (64.0 * 64.0) / 4 + 1e-12);
        }
    }
}

TEST_CASE("slope colours are finite and inside the map's range to 90 degrees, for any spread and mean")
{
    const SteepnessColorMap steep = steps();
    const SlopeVectorColorMap vector = random_vector_map();
    Rgb steep_lo, steep_hi, vector_lo, vector_hi;
    texel_range(steep.by_angle.texels, steep_lo, steep_hi);
    texel_range(vector.texels, vector_lo, vector_hi);
    int checked = 0;
    for (double theta : {0.0, 0.7, 1.4, 1.5707, kPi / 2, 3.0}) {
        for (double sigma : {0.0, 1e-200, 1e-8, 0.05, 1.0, 30.0, 1e100}) {
            for (double ratio : {1.0, 1e-9, 0.0}) {
                for (double mean : {0.0, 0.4, 3.0, -1e4}) {
                    for (double phi : {0.0, 2.4}) {
                        CAPTURE(theta);
                        CAPTURE(sigma);
                        CAPTURE(ratio);
                        CAPTURE(mean);
                        CAPTURE(phi);
                        const double sy = sigma * ratio;
                        const SlopeGaussian g{mean, 0.3 * mean, sigma * sigma, 0.7 * sigma * sy, sy * sy};
                        const ViewAngles view{theta, phi};
                        const ExactSlopeColorOptions coarse{8};
                        REQUIRE(inside(gaussian_slope_color(steep, g, view), steep_lo, steep_hi));
                        REQUIRE(inside(exact_slope_color(steep, g, view, coarse), steep_lo, steep_hi));
                        REQUIRE(inside(gaussian_slope_color(vector, g, view), vector_lo, vector_hi));
                        REQUIRE(inside(exact_slope_color(vector, g, view, coarse), vector_lo, vector_hi));
                        ++checked;
                    }
                }
            }
        }
    }
    CHECK(checked == 6 * 7 * 3 * 4 * 2);
}

namespace {

// <C lambda, D_s> / <lambda, D_s> by exact_slope_color over the two maps.
template <typename Map>
Rgb exact_lit_color(const Map& map, const SlopeGaussian& g, const ViewAngles& view, const LightDirection& light)
{
    const double lit = exact_slope_color(LightCosineSlopeMap{light}, g, view).r;
    return (1 / lit) * exact_slope_color(LightWeightedSlopeMap<Map>{&map, light}, g, view);
}

}  // namespace

TEST_CASE("the light-weighted exact slope colour matches a brute-force sum weighted by the facets' light cosine")
{
    const SteepnessColorMap steep = steps();
    const SlopeVectorColorMap vector = random_vector_map();
    const SlopeGaussian shapes[] = {{0, 0, 0.04, 0, 0.04}, {0.25, -0.15, 0.36, 0.12, 0.16}, {0, 0, 0.64, -0.1, 0.25}};
    double worst = 0;
    for (const SlopeGaussian& g : shapes)
        for (double view_degrees : {0.0, 60.0, 80.0})
            for (double light_degrees : {0.0, 45.0, 75.0}) {
                const double theta = view_degrees * kPi / 180, phi = 0.7;
                const LightDirection l = LightDirection::from_angles({light_degrees * kPi / 180, 2.5});
                CAPTURE(g.xx);
                CAPTURE(view_degrees);
                CAPTURE(light_degrees);
                const double a = largest_channel_difference(exact_lit_color(steep, g, {theta, phi}, l),
                                                            brute_force_color(steep, g, theta, phi, 800, &l));
                const double b = largest_channel_difference(exact_lit_color(vector, g, {theta, phi}, l),
                                                            brute_force_color(vector, g, theta, phi, 800, &l));
                CHECK(a <= 1e-3);
                CHECK(b <= 1e-3);
                worst = std::max({worst, a, b});
            }
    MESSAGE("largest channel difference: " << worst);
    // With the light overhead and a steepness map, the weighting leans to the flat colours: steep facets see
    // the light at cos(slope angle), so the lit colour moves from the steep colours towards the flat ones.
    const SlopeGaussian wide{0, 0, 0.64, 0, 0.64};
    const Rgb plain = exact_slope_color(steep, wide, {0, 0});
    const Rgb lit = exact_lit_color(steep, wide, {0, 0}, LightDirection{});
    const Rgb flat = steep.evaluate(0, 0);
    CHECK(std::abs(lit.g - flat.g) < std::abs(plain.g - flat.g));
}
