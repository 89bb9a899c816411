// SPDX-License-Identifier: Apache-2.0
// The cosine-series rows of clamp maps (cosine_series_rows.h) against
// brute-force quadrature (tests/support/reference_convolution.h): wherever the
// series claims a bound below 1e-10 its rows must match to float rounding,
// and where the bound is larger the true error must stay below it.
#include "cmfilter/tables/cosine_series_rows.h"

#include "unit_test_support.h"

#include <doctest/doctest.h>

#include <random>

using namespace cmfilter;
using cmfilter_test::MapPair;

namespace {

// Random texels; with hard_edges the red channel is 0/1 stripes 5 texels wide.
MapPair random_clamp_map(std::mt19937_64& rng, int n, double vmin, double vmax, bool hard_edges)
{
    MapPair p = cmfilter_test::random_map(rng, n, WrapMode::Clamp, vmin, vmax);
    if (hard_edges)
        for (int i = 0; i < n; ++i) p.map.texels[i].r = p.ref.texels[i][0] = (i / 5) % 2 ? 1.0 : 0.0;
    return p;
}

// Largest |row - quadrature| over every node of one row.
double row_error(const MapPair& p, const CosineSeriesRows& series, double first, double step, int count, double sigma)
{
    std::vector<float> row(3 * count), other(3 * count);
    series.evaluate(sigma, row.data(), sigma, other.data());
    double worst = 0;
    for (int i = 0; i < count; ++i) {
        const auto ref = cmfilter_test::reference_convolution(p.ref, first + i * step, sigma);
        for (int c = 0; c < 3; ++c) {
            worst = std::max(worst, std::fabs(row[3 * i + c] - ref[c]));
            // Both rows of a pair are computed alike (the second from the
            // imaginary parts of the shared transforms).
            worst = std::max(worst, std::fabs(other[3 * i + c] - ref[c]));
        }
    }
    return worst;
}

}  // namespace

TEST_CASE("cosine-series rows match quadrature wherever their bound is below 1e-10")
{
    std::mt19937_64 rng(11);
    struct Case {
        int n;
        double vmin, vmax, margin, sigma_max;
        int count;
        bool hard_edges;
    };
    const Case cases[] = {
        {256, 0.0, 1.0, 0.75, 0.25, 256, false},  // the default table of a smooth map
        {256, 0.0, 1.0, 0.75, 0.25, 97, true},    // hard edges, an odd node count
        {7, -3.0, 5.0, 0.0, 2.0, 40, false},      // few texels, no margin, offset domain
        {64, 1000.0, 1000.5, 0.1, 0.01, 300, true},
        {1, 0.0, 1.0, 0.75, 0.25, 16, false},  // a constant map has no kinks
    };
    for (const Case& c : cases) {
        const MapPair p = random_clamp_map(rng, c.n, c.vmin, c.vmax, c.hard_edges);
        const double first = c.vmin - c.margin;
        const double step = (c.vmax + c.margin - first) / (c.count - 1);
        CosineSeriesRows series(p.map, first, step, c.count, c.sigma_max);
        series.compute_coefficients(2);
        int tested = 0;
        for (int j = 1; j <= 24; ++j) {
            const double sigma = c.sigma_max * j / 24.0;
            if (series.error_bound(sigma) > 1e-10) continue;
            ++tested;
            CAPTURE(c.n);
            CAPTURE(c.count);
            CAPTURE(sigma);
            // float32 output: rounding of values up to 4 is below 2.4e-7.
            CHECK(row_error(p, series, first, step, c.count, sigma) < 3e-7);
        }
        // The bound admits most of the rows of these tables.
        CHECK(tested >= 12);
    }
}

TEST_CASE("the cosine-series error bound is an upper bound where it is not negligible")
{
    std::mt19937_64 rng(12);
    const MapPair p = random_clamp_map(rng, 256, 0.0, 1.0, true);
    const int count = 64;
    const double first = -0.75, step = 2.5 / (count - 1);
    CosineSeriesRows series(p.map, first, step, count, 0.25);
    series.compute_coefficients(1);
    int tested = 0;
    for (double sigma = 0.001; sigma < 0.25; sigma *= 1.15) {
        const double bound = series.error_bound(sigma);
        if (bound < 1e-5 || bound > 1.0) continue;
        ++tested;
        CAPTURE(sigma);
        CAPTURE(bound);
        CHECK(row_error(p, series, first, step, count, sigma) <= bound + 3e-7);
    }
    CHECK(tested >= 2);
}

TEST_CASE("the error bound is infinite for sigma <= 0 and above sigma_max")
{
    std::mt19937_64 rng(13);
    const MapPair p = random_clamp_map(rng, 16, 0.0, 1.0, false);
    CosineSeriesRows series(p.map, 0.0, 0.1, 11, 0.5);
    CHECK(std::isinf(series.error_bound(0.0)));
    CHECK(std::isinf(series.error_bound(0.6)));
    CHECK(std::isfinite(series.error_bound(0.5)));
}
