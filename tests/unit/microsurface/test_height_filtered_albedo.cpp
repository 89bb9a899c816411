// SPDX-License-Identifier: Apache-2.0
// The height-filtered albedo of a microsurface footprint
// (height_filtered_albedo.h) against independent computations, none of them
// calling the functions under test:
//   - Smith's Lambda as Smith's integral, Lambda = (1/mu) int_mu^inf (q - mu)
//     p(q) dq with p the N(0, sigma_s^2) slope density and mu = cot theta,
//     by Simpson's rule, with sigma_s^2 = sum a^2 (2 pi <f, d>)^2 / 2 summed
//     over the surface's cosines here;
//   - V = (1 + Lambda_o) / (1 + Lambda_o + Lambda_i) (eq. 13);
//   - D_h (eq. 16), (L + 1) Phi(x)^L phi(x) in x = h / sigma_h, tabulated on
//     a fine grid (trapezoid weights), and from it <C_h, D_h> (eq. 14), D_h's
//     mean and central deviation, with C_h a piecewise-linear map evaluated
//     by hand;
//   - the Gaussian of eqs. 17-18 as a brute-force convolution of C_h with
//     the normal density;
//   - the resolved surface's shadowing of a point, Phi(h / sigma_h)^Lambda
//     (eq. 2), from erfc and the Lambda above.
#include "cmfilter/microsurface/height_color.h"
#include "cmfilter/microsurface/height_filtered_albedo.h"
#include "cmfilter/microsurface/height_moment_table.h"
#include "cmfilter/microsurface/microsurface_footprint.h"

#include "microsurface_test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace cmfilter;
using namespace cmfilter_test;

namespace {

// Smith's Lambda by Simpson's rule over q in [mu, mu + 40 sigma_s] (the
// slope density is below e^-800 beyond), theta = 0 (mu infinite) masking
// nothing and theta = 90 degrees (mu = 0) everything.
double smith_lambda_simpson(double theta, double sigma_s)
{
    if (theta <= 0) return 0;
    if (theta >= kPi / 2) return kInf;
    const double mu = 1 / std::tan(theta);
    if (sigma_s == 0) return 0;
    const int intervals = 100000;  // even
    const double step = 40 * sigma_s / intervals;
    double sum = 0;
    for (int k = 0; k <= intervals; ++k) {
        const double q = mu + k * step;
        const double f = (q - mu) * std::exp(-0.5 * (q / sigma_s) * (q / sigma_s)) / (sigma_s * std::sqrt(2 * kPi));
        const double simpson = (k == 0 || k == intervals) ? 1 : (k % 2 == 1 ? 4 : 2);
        sum += simpson * f;
    }
    return sum * step / 3 / mu;
}

// The whole surface's slope deviation along the azimuth, from its cosines.
double surface_sigma_s(const GaussianMicrosurface& surface, double azimuth)
{
    double variance = 0;
    for (const GaussianMicrosurface::Cosine& k : surface.cosines()) {
        const double slope = 2 * kPi * (k.fx * std::cos(azimuth) + k.fy * std::sin(azimuth));
        variance += 0.5 * k.amplitude * k.amplitude * slope * slope;
    }
    return std::sqrt(variance);
}

// The height at a point, from the surface's cosines.
double surface_height(const GaussianMicrosurface& surface, double x, double y)
{
    double h = 0;
    for (const GaussianMicrosurface::Cosine& k : surface.cosines())
        h += k.amplitude * std::cos(2 * kPi * (k.fx * x + k.fy * y) + k.phase);
    return h;
}

// ln Phi(x) from erfc, through the complement on the right.
double log_phi_cdf(double x)
{
    return x > 0 ? std::log1p(-0.5 * std::erfc(x / std::sqrt(2.0))) : std::log(0.5 * std::erfc(-x / std::sqrt(2.0)));
}

// D_h for the Lambda sum L (infinite: 1e100, as the library documents) and
// sigma_h, on x = h / sigma_h in [-12, 12 + sqrt(2 ln(L + 1))] with step
// 1e-4: heights and trapezoid weights, and what they give.
struct HeightQuadrature {
    std::vector<double> heights, weights;
    double total = 0;  // the weights' sum before normalising: 1 if the grid holds D_h
    double mean = 0, sigma = 0;

    Rgb colour(const ColorMap& map, double offset) const
    {
        Rgb sum;
        for (std::size_t k = 0; k < heights.size(); ++k)
            sum += weights[k] * reference_map_color(map, offset + heights[k]);
        return sum;
    }
};

HeightQuadrature height_quadrature(double lambda_sum, double sigma_h)
{
    const double L = std::min(lambda_sum, 1e100);
    const double step = 1e-4, lo = -12, hi = 12 + std::sqrt(2 * std::log1p(L));
    const int n = static_cast<int>(std::ceil((hi - lo) / step));
    HeightQuadrature q;
    for (int k = 0; k <= n; ++k) {
        const double x = lo + k * step;
        const double log_density = std::log1p(L) + (L > 0 ? L * log_phi_cdf(x) : 0.0) - 0.5 * x * x -
                                   0.5 * std::log(2 * kPi);
        const double w = std::exp(log_density) * step * ((k == 0 || k == n) ? 0.5 : 1.0);
        q.heights.push_back(sigma_h * x);
        q.weights.push_back(w);
        q.total += w;
    }
    for (double& w : q.weights) w /= q.total;
    for (std::size_t k = 0; k < q.heights.size(); ++k) q.mean += q.weights[k] * q.heights[k];
    double variance = 0;
    for (std::size_t k = 0; k < q.heights.size(); ++k)
        variance += q.weights[k] * (q.heights[k] - q.mean) * (q.heights[k] - q.mean);
    q.sigma = std::sqrt(variance);
    return q;
}

// (C_h * N(0, sigma^2))(mean) by the trapezoid rule over +-10 sigma.
Rgb gaussian_reference(const ColorMap& map, double mean, double sigma)
{
    if (sigma == 0) return reference_map_color(map, mean);
    const int n = 40000;
    const double step = 20.0 / n;
    Rgb sum;
    for (int k = 0; k <= n; ++k) {
        const double z = -10 + k * step;
        const double w = std::exp(-0.5 * z * z) / std::sqrt(2 * kPi) * step * ((k == 0 || k == n) ? 0.5 : 1.0);
        sum += w * reference_map_color(map, mean + sigma * z);
    }
    return sum;
}

double largest_difference(const Rgb& a, const Rgb& b)
{
    return std::max({std::fabs(a.r - b.r), std::fabs(a.g - b.g), std::fabs(a.b - b.b)});
}

// The colour table's own lookup error about (mean, sigma): its largest
// difference from the brute-force convolution on a 5 x 5 grid of half value
// cells and +-10% in sigma around the point (within the table's sigma range).
double local_table_error(const ColorLayer& m, double mean, double sigma)
{
    const TableAxes& ax = m.table.axes();
    const double half_cell = 0.5 * (ax.value_last() - ax.value_first()) / (ax.values - 1);
    double worst = 0;
    for (int i = -2; i <= 2; ++i)
        for (int j = -2; j <= 2; ++j) {
            const double v = mean + i * half_cell, s = std::clamp(sigma * (1 + 0.05 * j), 0.0, ax.sigma_max);
            worst = std::max(worst, largest_difference(m.table.lookup(v, s), gaussian_reference(m.map, v, s)));
        }
    return worst;
}

}  // namespace

TEST_CASE("the albedo of an unresolved footprint matches Smith's integral and quadratures of D_h")
{
    const GaussianMicrosurface surface = test_microsurface(0.008, 64, 3);
    // Edges of a million units (2.5 million longest wavelengths), not a
    // multiple of the tile: every cosine averages out.
    const MicrosurfaceFootprint f = filter_microsurface(surface, 0.61, -1.7, 1e6 + 0.37, 0.0, 0.0, 1e6 + 0.59);
    CHECK(std::fabs(f.mean_height) < 1e-9);
    CHECK(f.sigma_h == doctest::Approx(0.008).epsilon(1e-9));
    const ColorLayer heights = microsurface_test_layer(40, 64, 0.008);
    auto moment_table = HeightMomentTable::create();
    REQUIRE(moment_table);
    const double slope = steepest_map_slope(heights.map);
    AlbedoCounts counts;
    // (theta_o, phi_o, theta_i, phi_i): head-on (L = 0) to both grazing (L in the thousands).
    struct Case {
        double theta_o, phi_o, theta_i, phi_i;
    };
    const Case cases[] = {{0, 0, 0, 0},         {35, 0.3, 50, 2.0},   {70, 1.1, 20, -2.5},      {80, -0.4, 85, 0.9},
                          {88, 2.8, 89.5, 0.1}, {89.9, 0.5, 60, 1.5}, {89.999, 0.2, 89.99, 1.0}};
    double largest_l = 0;
    for (const Case& c : cases) {
        CAPTURE(c.theta_o);
        CAPTURE(c.theta_i);
        const HeightDirections d{degrees(c.theta_o), c.phi_o, degrees(c.theta_i), c.phi_i};
        const double so = surface_sigma_s(surface, c.phi_o), si = surface_sigma_s(surface, c.phi_i);
        CHECK(f.sigma_s(c.phi_o) == doctest::Approx(so).epsilon(1e-9));
        const double lo = smith_lambda_simpson(d.theta_o, so), li = smith_lambda_simpson(d.theta_i, si);
        const double L = lo + li, V = (1 + lo) / (1 + lo + li);
        largest_l = std::max(largest_l, L);
        CAPTURE(L);
        const HeightQuadrature q = height_quadrature(L, f.sigma_h);
        CHECK(q.total == doctest::Approx(1).epsilon(1e-6));  // the grid holds all of D_h

        const HeightAlbedo exact =
            height_filtered_albedo(heights, f, d, HeightRepresentation::Exact, *moment_table, counts);
        CHECK(exact.lambda_sum == doctest::Approx(L).epsilon(1e-6));
        CHECK(exact.visibility == doctest::Approx(V).epsilon(1e-6));
        CHECK(exact.resolved_visibility == doctest::Approx(1).epsilon(1e-12));  // nothing resolved
        const Rgb expected = V * q.colour(heights.map, f.mean_height);
        CAPTURE(expected.r);
        CAPTURE(exact.albedo.r);
        CHECK(largest_difference(exact.albedo, expected) < 1e-6);
        CHECK(exact.mean == doctest::Approx(q.mean).epsilon(1e-5).scale(0.008));
        CHECK(exact.sigma == doctest::Approx(q.sigma).epsilon(1e-5));

        // Exact moments: V times the Gaussian of D_h's own mean and deviation.
        // Allowed: the colour table's lookup error there and the moment
        // table's (1e-4 of sigma_h in mean and sigma) times the map's slope.
        const HeightAlbedo moments =
            height_filtered_albedo(heights, f, d, HeightRepresentation::ExactMoments, *moment_table, counts);
        const double table_error = local_table_error(heights, f.mean_height + q.mean, q.sigma);
        CAPTURE(table_error);
        CHECK(table_error < 1e-4);
        const Rgb gaussian_exact = V * gaussian_reference(heights.map, f.mean_height + q.mean, q.sigma);
        CHECK(largest_difference(moments.albedo, gaussian_exact) <= 2 * table_error + slope * 2e-4 * 0.008 + 1e-7);
        CHECK(moments.visibility == doctest::Approx(V).epsilon(1e-6));

        // The paper's fit (eqs. 17-18) of D_h's moments, as printed.
        const double fit_mean = 0.39 * 0.008 * std::log(4.75 * L + 1);
        const double fit_sigma = 0.008 / (1 + 0.26 * std::log(1.13 * L + 1));
        const HeightAlbedo paper =
            height_filtered_albedo(heights, f, d, HeightRepresentation::PaperFit, *moment_table, counts);
        CHECK(paper.mean == doctest::Approx(f.mean_height + fit_mean).epsilon(1e-6));
        CHECK(paper.sigma == doctest::Approx(fit_sigma).epsilon(1e-6));
        const double fit_error = local_table_error(heights, f.mean_height + fit_mean, fit_sigma);
        CHECK(largest_difference(paper.albedo, V * gaussian_reference(heights.map, f.mean_height + fit_mean,
                                                                      fit_sigma)) <= 2 * fit_error + 1e-7);

        // Naive: the resolved mean's colour, unmasked.
        const HeightAlbedo naive =
            height_filtered_albedo(heights, f, d, HeightRepresentation::Naive, *moment_table, counts);
        CHECK(largest_difference(naive.albedo, reference_map_color(heights.map, f.mean_height)) < 1e-12);
        CHECK(naive.visibility == 1);
    }
    CHECK(largest_l > 1000);  // the sweep reached strongly masked footprints
}

TEST_CASE("the exact colour at huge and infinite Lambda sums is that of the highest heights")
{
    // sigma_h 0.001: at L = 1e100 the heights seen lie about 21 sigma_h above
    // the offset, within one linear segment of the map, where no tail is cut.
    const ColorMap map = microsurface_test_map();
    for (double L : {1e6, 1e12, 1e15, 1e17, 1e18, 1e20, 1e50, 1e100, kInf})
        for (double offset : {-0.018, 0.002}) {
            CAPTURE(L);
            CAPTURE(offset);
            const HeightQuadrature q = height_quadrature(L, 0.001);
            CHECK(q.total == doctest::Approx(1).epsilon(1e-6));
            const Rgb expected = q.colour(map, offset);
            const Rgb got = exact_height_color(map, 0.001, L, offset);
            CAPTURE(expected.r);
            CAPTURE(got.r);
            CHECK(largest_difference(got, expected) < 1e-6);
        }
    // Through the albedo: a view at exactly 90 degrees has Lambda_o infinite,
    // so V = 1 (eq. 13's limit) and the colour is that of L = 1e100.
    const ColorLayer heights = microsurface_test_layer(4, 8, 0.01);
    auto moment_table = HeightMomentTable::create();
    REQUIRE(moment_table);
    AlbedoCounts counts;
    const HeightAlbedo a = height_filtered_albedo(heights, hand_footprint(0.002, 0.001, 0.3),
                                                  {kPi / 2, 0.3, degrees(40), 1.2}, HeightRepresentation::Exact,
                                                  *moment_table, counts);
    CHECK(a.visibility == 1);
    CHECK(a.lambda_sum == kInf);
    const Rgb expected = height_quadrature(kInf, 0.001).colour(heights.map, 0.002);
    CHECK(largest_difference(a.albedo, expected) < 1e-6);
}

TEST_CASE("a point footprint gives C_h at the point's height, shadowed only by the resolved surface")
{
    // A point resolves everything: no unresolved heights or slopes, so D_h
    // is the height itself and nothing is masked (Lambda_o + Lambda_i = 0,
    // V = 1); every representation gives C_h(h(x)). Only the resolved
    // surface's own shadowing of the point remains (every representation
    // but naive): Smith's V_r = Phi(h / sigma_h)^Lambda(theta_i) (eq. 2) for
    // the whole surface's sigma_h and slopes, 1 with the light overhead.
    const GaussianMicrosurface surface = test_microsurface(0.008, 64, 3);
    const ColorLayer heights = microsurface_test_layer(4, 16, 0.008);
    auto moment_table = HeightMomentTable::create();
    REQUIRE(moment_table);
    AlbedoCounts counts;
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> at(-5, 5);
    const HeightDirections directions[] = {{0, 0, 0, 0},
                                           {degrees(60), 0.5, 0, 0},
                                           {degrees(60), 0.5, degrees(75), 2},
                                           {degrees(89), -1, degrees(30), 0.2}};
    for (int k = 0; k < 40; ++k) {
        const double u = at(rng), v = at(rng);
        const MicrosurfaceFootprint f = filter_microsurface(surface, u, v, 0, 0, 0, 0);
        const double h = surface_height(surface, u, v);
        CAPTURE(u);
        CAPTURE(v);
        CHECK(f.mean_height == doctest::Approx(h).epsilon(1e-12).scale(0.008));
        CHECK(f.sigma_h == 0);
        CHECK((f.slope_xx == 0 && f.slope_xy == 0 && f.slope_yy == 0));
        const Rgb colour = reference_map_color(heights.map, h);
        for (const HeightDirections& d : directions) {
            const double lambda_r = smith_lambda_simpson(d.theta_i, surface_sigma_s(surface, d.phi_i));
            const double shadowing = std::pow(0.5 * std::erfc(-h / (0.008 * std::sqrt(2.0))), lambda_r);
            for (HeightRepresentation r : {HeightRepresentation::Naive, HeightRepresentation::PaperFit,
                                           HeightRepresentation::ExactMoments, HeightRepresentation::Exact}) {
                CAPTURE(static_cast<int>(r));
                CAPTURE(d.theta_o);
                CAPTURE(d.theta_i);
                const HeightAlbedo a = height_filtered_albedo(heights, f, d, r, *moment_table, counts);
                CHECK(a.lambda_sum == 0);
                CHECK(a.visibility == 1);
                const double vr = r == HeightRepresentation::Naive ? 1.0 : shadowing;
                if (d.theta_i == 0) CHECK(vr == 1);
                CHECK(a.resolved_visibility == doctest::Approx(vr).epsilon(1e-7));
                // The tables' sigma = 0 row has a node on every texel centre:
                // C0 itself but for float32 storage.
                const bool tabled = r == HeightRepresentation::PaperFit || r == HeightRepresentation::ExactMoments;
                CHECK(largest_difference(a.albedo, vr * colour) <= (tabled ? 1e-6 : 1e-7));
            }
        }
    }
}
