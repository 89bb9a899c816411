// SPDX-License-Identifier: Apache-2.0
// The least-squares colours through a map's breakpoints
// (colormap/breakpoint_colors.h) against a dense solve of the same normal
// equations built here from the hat functions' definition (Eigen), the
// interpolant where the breakpoints are all of a piecewise-linear map's, the
// driver's weights against a direct count, and the selection with fitted
// colours against its tolerance measured here over every driver value.
#include "cmfilter/colormap/breakpoint_colors.h"
#include "cmfilter/colormap/map_breakpoints.h"

#include "cmfilter/color/ciede2000.h"

#include <Eigen/Dense>
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace cmfilter;

namespace {

ColorMap smooth_map()
{
    ColorMap m;
    for (int i = 0; i < 64; ++i) {
        const double u = i / 63.0;
        m.texels.push_back({u * u, std::sin(3 * u) * 0.5 + 0.5, 1 - u});
    }
    return m;
}

std::vector<float> driver()
{
    std::vector<float> v;
    for (int i = 0; i < 3000; ++i) v.push_back(static_cast<float>(0.5 + 0.45 * std::sin(0.37 * i)));
    return v;
}

// phi_k(f): the hat of breakpoint k, 1 below t_0 for k = 0, above t_K for k = K.
double hat(const std::vector<double>& t, std::size_t k, double f)
{
    const std::size_t K = t.size() - 1;
    if (f <= t[0]) return k == 0 ? 1.0 : 0.0;
    if (f >= t[K]) return k == K ? 1.0 : 0.0;
    if (k > 0 && f >= t[k - 1] && f <= t[k]) return (f - t[k - 1]) / (t[k] - t[k - 1]);
    if (k < K && f >= t[k] && f <= t[k + 1]) return (t[k + 1] - f) / (t[k + 1] - t[k]);
    return 0.0;
}

}  // namespace

TEST_CASE("breakpoint colours: the least-squares colours solve the weighted normal equations")
{
    const ColorMap map = smooth_map();
    const std::vector<float> values = driver();
    const DriverWeights w = driver_weights(values, 0.05, 0.95, 256);
    // Breakpoints off the map's knots, one below and one above every driver value.
    const std::vector<double> t = {0.02, 0.21, 0.33, 0.5, 0.61, 0.8, 0.97};
    const std::vector<Rgb> got = breakpoint_colors(map, t, &w);
    const std::size_t n = t.size();
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
    Eigen::MatrixXd b = Eigen::MatrixXd::Zero(n, 3);
    double total = 0;
    for (std::size_t i = 0; i < w.values.size(); ++i) {
        const double f = w.values[i], s = w.shares[i];
        total += s;
        const Rgb y = map.evaluate(f);
        for (std::size_t j = 0; j < n; ++j) {
            for (std::size_t k = 0; k < n; ++k) A(j, k) += s * hat(t, j, f) * hat(t, k, f);
            for (int c = 0; c < 3; ++c) b(j, c) += s * hat(t, j, f) * y[c];
        }
    }
    for (std::size_t j = 0; j < n; ++j) {
        const Rgb at = map.evaluate(t[j]);
        A(j, j) += 1e-9 * total;
        for (int c = 0; c < 3; ++c) b(j, c) += 1e-9 * total * at[c];
    }
    const Eigen::MatrixXd x = A.ldlt().solve(b);
    for (std::size_t j = 0; j < n; ++j)
        for (int c = 0; c < 3; ++c) CHECK(got[j][c] == doctest::Approx(x(j, c)).epsilon(1e-9));
    // Better than the interpolant in the weighted squared error it minimises.
    const std::vector<Rgb> interpolated = breakpoint_colors(map, t);
    double fitted = 0, through = 0;
    for (std::size_t i = 0; i < w.values.size(); ++i) {
        const Rgb y = map.evaluate(w.values[i]);
        const Rgb d1 = y - breakpoint_curve(t, got, w.values[i]),
                  d2 = y - breakpoint_curve(t, interpolated, w.values[i]);
        fitted += w.shares[i] * (d1.r * d1.r + d1.g * d1.g + d1.b * d1.b);
        through += w.shares[i] * (d2.r * d2.r + d2.g * d2.g + d2.b * d2.b);
    }
    CHECK(fitted < 0.8 * through);
}

TEST_CASE("breakpoint colours: through every breakpoint of a piecewise-linear map they are its own colours")
{
    ColorMap map;
    const double g[8] = {0.1, 0.1, 0.4, 0.9, 0.2, 0.2, 0.7, 0.3};
    for (double v : g) map.texels.push_back({v, 1 - v, 0.5 * v});
    auto t = map_breakpoints(map, 0, 1);
    REQUIRE(t);
    std::vector<float> values;
    for (int i = 0; i < 500; ++i) values.push_back(static_cast<float>(i / 499.0));
    const DriverWeights w = driver_weights(values, 0, 1);
    const std::vector<Rgb> got = breakpoint_colors(map, *t, &w);
    for (std::size_t k = 0; k < t->size(); ++k) {
        const Rgb at = map.evaluate((*t)[k]);
        for (int c = 0; c < 3; ++c) CHECK(got[k][c] == doctest::Approx(at[c]).epsilon(1e-7));
    }
}

TEST_CASE("breakpoint colours: the driver's weights are its binned values and their shares")
{
    const std::vector<float> values = {0.0f, 0.1f, 0.12f, 0.5f, 0.99f, 1.0f, 1.0f, 0.5f};
    const DriverWeights w = driver_weights(values, 0, 1, 4);  // bins [0, .25) [.25, .5) [.5, .75) [.75, 1]
    REQUIRE(w.values.size() == 3);
    CHECK(w.values[0] == doctest::Approx((0.0 + 0.1 + 0.12) / 3));
    CHECK(w.shares[0] == doctest::Approx(3.0 / 8));
    CHECK(w.values[1] == doctest::Approx(0.5));
    CHECK(w.shares[1] == doctest::Approx(2.0 / 8));
    CHECK(w.values[2] == doctest::Approx((0.99 + 1 + 1) / 3));
    CHECK(w.shares[2] == doctest::Approx(3.0 / 8));
    CHECK(driver_weights({}, 0, 1).empty());
}

TEST_CASE("breakpoint selection: fitted colours keep fewer breakpoints within the tolerance, measured here")
{
    const ColorMap map = smooth_map();
    const std::vector<float> values = driver();
    BreakpointSelectionOptions o;
    o.maps = {&map};
    o.lo = *std::min_element(values.begin(), values.end());
    o.hi = *std::max_element(values.begin(), values.end());
    o.driver = &values;
    o.tolerance_de = 0.3;
    auto through = select_breakpoints(o);
    REQUIRE(through);
    CHECK(through->color_weights.empty());
    o.fit_colors = true;
    auto fitted = select_breakpoints(o);
    REQUIRE(fitted);
    REQUIRE_FALSE(fitted->color_weights.empty());
    CHECK(fitted->breakpoints.size() < through->breakpoints.size());
    const std::vector<Rgb> c = breakpoint_colors(map, fitted->breakpoints, &fitted->color_weights);
    double sum = 0;
    for (float v : values) sum += ciede2000_linear_rgb(map.evaluate(v), breakpoint_curve(fitted->breakpoints, c, v));
    const double mean = sum / values.size();
    CHECK(mean <= 0.3 * 1.01);
    CHECK(fitted->max_mean_de == doctest::Approx(mean).epsilon(0.01));
}
