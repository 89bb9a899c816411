// SPDX-License-Identifier: Apache-2.0
// A microsurface material's layers (microsurface_albedo.h) against
// independent computations: the combinations of sec. 6 (a weighted sum, a
// product, absent layers) by hand; the slope layer of a footprint that
// resolves nothing against a Monte Carlo average of eq. 20 over the
// microsurface's own slopes; the visibility of a material without a height
// map against eq. 13 with Smith's Lambda integrated numerically from its
// definition; and the naive method against the map at a brute-force mean
// gradient over a small footprint.
#include "cmfilter/color/ciede2000.h"
#include "cmfilter/microsurface/height_moment_table.h"
#include "cmfilter/microsurface/microsurface_albedo.h"
#include "cmfilter/microsurface/microsurface_footprint.h"

#include "microsurface_test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace cmfilter;
using namespace cmfilter_test;

namespace {

// A steepness map over [0, 60] degrees: grass on the flat to rock and snow
// on the steep (clamp beyond 60).
SteepnessColorMap steepness_map()
{
    SteepnessColorMap map;
    map.by_angle.vmin = 0;
    map.by_angle.vmax = 60;
    map.by_angle.wrap = WrapMode::Clamp;
    map.by_angle.texels = {{0.08, 0.30, 0.04}, {0.15, 0.35, 0.06}, {0.35, 0.33, 0.20},
                           {0.45, 0.40, 0.35}, {0.60, 0.58, 0.55}, {0.90, 0.92, 0.95}};
    return map;
}

// 5 x 5 texels over [-1.2, 1.2]^2, a hue wheel-like pattern: red towards +x,
// blue towards +y, a grey centre.
SlopeVectorColorMap vector_map()
{
    SlopeVectorColorMap map;
    map.width = map.height = 5;
    map.s_max = 1.2;
    for (int j = 0; j < 5; ++j) {
        for (int i = 0; i < 5; ++i) {
            const double x = (i - 2) / 2.0, y = (2 - j) / 2.0;  // -1 .. 1, row 0 at +y
            map.texels.push_back({0.4 + 0.35 * x, 0.4 - 0.15 * (x + y) / 2, 0.4 + 0.35 * y});
        }
    }
    return map;
}

// A microsurface material with only a slope map.
MicrosurfaceColors slope_material(const SlopeMap& map)
{
    MicrosurfaceColors m;
    m.slope = map;
    return m;
}

// The footprint of edges 1000 x 1000 texture units: every wavelength (at
// most 0.4) is unresolved, so its slopes are the whole microsurface's.
constexpr double kFar = 1000;

MicrosurfaceFootprint far_footprint(const GaussianMicrosurface& s, ResolvedSlope& slope)
{
    slope = resolved_slope(s, 0.3, 0.7, kFar, 0, 0, kFar);
    return filter_microsurface(s, 0.3, 0.7, kFar, 0, 0, kFar);
}

// sigma_s along (cos a, sin a) of the microsurface itself, from its cosines:
// sum a_k^2 (2 pi <f_k, d>)^2 / 2.
double spectral_sigma_s(const GaussianMicrosurface& s, double azimuth)
{
    double variance = 0;
    for (const GaussianMicrosurface::Cosine& c : s.cosines()) {
        const double g = 2 * kPi * (c.fx * std::cos(azimuth) + c.fy * std::sin(azimuth));
        variance += c.amplitude * c.amplitude * g * g / 2;
    }
    return std::sqrt(variance);
}

// Smith's Lambda from its definition (eq. 3): for slopes q ~ N(0, sigma^2)
// along the direction's azimuth and mu = cot theta,
//   Lambda = 1/mu int_mu^inf (q - mu) p(q) dq = sigma/mu int_0^inf t phi(mu/sigma + t) dt,
// by Simpson's rule over t in [0, 14] (phi below e^-98 beyond).
double lambda_by_integration(double theta, double sigma)
{
    if (theta == 0) return 0;
    const double mu = std::cos(theta) / std::sin(theta), k = mu / sigma;
    const int n = 4000;
    const double h = 14.0 / n;
    double sum = 0;
    for (int i = 0; i <= n; ++i) {
        const double t = i * h;
        const double f = t * std::exp(-0.5 * (k + t) * (k + t)) / std::sqrt(2 * kPi);
        sum += (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2)) * f;
    }
    return sigma / mu * sum * h / 3;
}

double max_channel_difference(const Rgb& a, const Rgb& b)
{
    return std::max({std::fabs(a.r - b.r), std::fabs(a.g - b.g), std::fabs(a.b - b.b)});
}

Rgb evaluate(const SlopeMap& map, double sx, double sy)
{
    return std::visit([&](const auto& m) { return m.evaluate(sx, sy); }, map);
}

std::string text(const Rgb& c)
{
    std::ostringstream s;
    s << std::setprecision(9) << "(" << c.r << ", " << c.g << ", " << c.b << ")";
    return s.str();
}

struct Gradients {
    std::vector<double> x, y;
};

// The microsurface's gradient at n uniform random points of its tile (the
// surface repeats with it: the tile's slopes are all of its slopes).
Gradients sample_gradients(const GaussianMicrosurface& s, int n, std::uint64_t seed)
{
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    Gradients g;
    g.x.resize(static_cast<std::size_t>(n));
    g.y.resize(static_cast<std::size_t>(n));
    for (std::size_t i = 0; i < g.x.size(); ++i) {
        const double px = s.tile() * unit(rng), py = s.tile() * unit(rng);
        s.gradient(px, py, g.x[i], g.y[i]);
    }
    return g;
}

// C_s at each sampled slope (the colours do not depend on the view).
std::vector<Rgb> slope_colors(const SlopeMap& map, const Gradients& g)
{
    std::vector<Rgb> colours(g.x.size());
    for (std::size_t i = 0; i < g.x.size(); ++i) colours[i] = evaluate(map, g.x[i], g.y[i]);
    return colours;
}

// Eq. 20 over the sampled slopes: C_s(s) weighted by max(0, cos t - sin t <s, d>).
Rgb monte_carlo_slope_color(const std::vector<Rgb>& colours, const Gradients& g, double theta, double phi)
{
    const double c = std::cos(theta), s = std::sin(theta), dx = std::cos(phi), dy = std::sin(phi);
    Rgb sum;
    double total = 0;
    for (std::size_t i = 0; i < g.x.size(); ++i) {
        const double w = std::max(0.0, c - s * (g.x[i] * dx + g.y[i] * dy));
        sum += w * colours[i];
        total += w;
    }
    return (1 / total) * sum;
}

}  // namespace

// ---- the combinations -----------------------------------------------------------

TEST_CASE("combine_point_color is the weighted sum or the product of the layers present")
{
    const Rgb base{0.2, 0.5, 0.9}, height{0.6, 0.1, 0.3}, slope{0.7, 0.8, 0.05};
    ColorCombination sum;
    sum.mode = CombineMode::Sum;
    sum.base = 0.25, sum.height = 1.5, sum.slope = 0.75;
    ColorCombination product;
    product.mode = CombineMode::Product;
    for (int k = 0; k < 3; ++k) {
        CAPTURE(k);
        const Rgb all = combine_point_color(sum, base, height, slope);
        CHECK(all[k] == doctest::Approx(0.25 * base[k] + 1.5 * height[k] + 0.75 * slope[k]).epsilon(1e-14));
        const Rgb no_base = combine_point_color(sum, std::nullopt, height, slope);
        CHECK(no_base[k] == doctest::Approx(1.5 * height[k] + 0.75 * slope[k]).epsilon(1e-14));
        const Rgb slope_only = combine_point_color(sum, std::nullopt, std::nullopt, slope);
        CHECK(slope_only[k] == doctest::Approx(0.75 * slope[k]).epsilon(1e-14));
        const Rgb base_height = combine_point_color(sum, base, height, std::nullopt);
        CHECK(base_height[k] == doctest::Approx(0.25 * base[k] + 1.5 * height[k]).epsilon(1e-14));

        const Rgb p = combine_point_color(product, base, height, slope);
        CHECK(p[k] == doctest::Approx(base[k] * height[k] * slope[k]).epsilon(1e-14));
        const Rgb p_no_height = combine_point_color(product, base, std::nullopt, slope);
        CHECK(p_no_height[k] == doctest::Approx(base[k] * slope[k]).epsilon(1e-14));
        const Rgb p_height = combine_point_color(product, std::nullopt, height, std::nullopt);
        CHECK(p_height[k] == doctest::Approx(height[k]).epsilon(1e-14));
    }
    // The product's weights, whatever they hold, are not used.
    product.base = product.height = product.slope = 7;
    const Rgb p = combine_point_color(product, base, std::nullopt, slope);
    CHECK(p.r == doctest::Approx(base.r * slope.r).epsilon(1e-14));
}

TEST_CASE(
    "combine_microsurface_albedo shadows the base layer by the mean visibility in a sum, multiplies it in a product")
{
    const Rgb base{0.3, 0.6, 0.15}, shadowed{0.21, 0.04, 0.33};
    const double v = 0.7;
    ColorCombination sum;
    sum.mode = CombineMode::Sum;
    sum.base = 0.4, sum.height = 2, sum.slope = 3;  // the layer weights are already inside `shadowed`
    ColorCombination product;
    product.mode = CombineMode::Product;
    const Rgb s = combine_microsurface_albedo(sum, v, shadowed, base);
    const Rgb p = combine_microsurface_albedo(product, v, shadowed, base);
    const Rgb none_sum = combine_microsurface_albedo(sum, v, shadowed, std::nullopt);
    const Rgb none_product = combine_microsurface_albedo(product, v, shadowed, std::nullopt);
    for (int k = 0; k < 3; ++k) {
        CAPTURE(k);
        // sum: k0 C0-bar mean(V) + mean(V (k1 <C_h> + k2 <C_s>)).
        CHECK(s[k] == doctest::Approx(0.4 * 0.7 * base[k] + shadowed[k]).epsilon(1e-14));
        // product: C0-bar mean(V <C_h> <C_s>).
        CHECK(p[k] == doctest::Approx(base[k] * shadowed[k]).epsilon(1e-14));
        CHECK(none_sum[k] == shadowed[k]);
        CHECK(none_product[k] == shadowed[k]);
    }
}

TEST_CASE("microsurface_layers sums or multiplies C_h of the resolved height and C_s of the resolved slope, naively")
{
    MicrosurfaceColors m;
    m.height = microsurface_test_layer(2, 16, 0.05);
    const SlopeMap slope_map = vector_map();
    m.slope = slope_map;
    const HeightMomentTable table = *HeightMomentTable::create();
    MicrosurfaceLayerOptions options;
    options.heights = HeightRepresentation::Naive;
    options.slopes = SlopeRepresentation::Naive;
    const MicrosurfaceFootprint f = hand_footprint(0.012, 0.004, 0.3);
    const ResolvedSlope slope{0.35, -0.6};
    const HeightDirections d{degrees(40), 0.3, degrees(25), 2.0};
    const Rgb h = reference_map_color(m.height->map, 0.012), s = evaluate(slope_map, 0.35, -0.6);
    AlbedoCounts counts;

    m.combine.mode = CombineMode::Sum;
    m.combine.height = 0.3, m.combine.slope = 1.25;
    const MicrosurfaceLayers sum = microsurface_layers(m, f, slope, d, options, table, counts);
    CHECK(sum.visibility == 1);
    for (int k = 0; k < 3; ++k) CHECK(sum.shadowed[k] == doctest::Approx(0.3 * h[k] + 1.25 * s[k]).epsilon(1e-6));

    m.combine.mode = CombineMode::Product;
    const MicrosurfaceLayers product = microsurface_layers(m, f, slope, d, options, table, counts);
    CHECK(product.visibility == 1);
    for (int k = 0; k < 3; ++k) CHECK(product.shadowed[k] == doctest::Approx(h[k] * s[k]).epsilon(1e-6));

    // Without the height map, the slope layer alone (weighted in a sum).
    m.height.reset();
    m.combine.mode = CombineMode::Sum;
    const MicrosurfaceLayers alone = microsurface_layers(m, f, slope, d, options, table, counts);
    for (int k = 0; k < 3; ++k) CHECK(alone.shadowed[k] == doctest::Approx(1.25 * s[k]).epsilon(1e-12));
}

// ---- a footprint that resolves nothing ------------------------------------------

// The exact slope layer over a far footprint is eq. 20's D_s colour for the
// Gaussian of the whole microsurface's slopes. Against it: the same average
// taken over the microsurface's actual slopes at 200k random points of its
// tile. The two differ by the Monte Carlo error and by how far a sum of 256
// cosines is from Gaussian. The Monte Carlo error of a weighted mean of
// colours is about std(C_s) / sqrt(N_eff): std(C_s) <= 0.3 per channel on
// these maps, and the weight (cot t - <s, d>)_+ keeps 59% of the slopes at
// 80 degrees (sigma_s ~ 0.8), so N_eff >~ 80k and the error about 1e-3 per
// channel: up to 0.2 CIEDE2000 on the darkest colours (L* ~ 30, where
// dL*/dY is largest), less elsewhere; the exact method's 8 panels add at most
// 0.17 (docs/slope.md). Measured with this implementation: mean 0.07 and max
// 0.09 (steepness), mean 0.15 and max 0.21 (vector) over the 12 cases each.
// The bounds (mean 0.3, each case 0.6) leave room for the sampling's spread,
// while an unweighted average of C_s is 1.5 to 3.8 (steepness) and 14 to 22
// (vector) away at 60 and 80 degrees, and a view direction of the wrong sign
// 27 to 39 (vector).
TEST_CASE("the exact slope layer of a far footprint matches eq. 20 averaged over the microsurface's own slopes")
{
    const GaussianMicrosurface surface = test_microsurface(0.02, 256, 5);
    ResolvedSlope slope;
    const MicrosurfaceFootprint f = far_footprint(surface, slope);
    const Gradients gradients = sample_gradients(surface, 200000, 17);
    const HeightMomentTable table = *HeightMomentTable::create();
    MicrosurfaceLayerOptions options;
    options.heights = HeightRepresentation::Exact;
    options.slopes = SlopeRepresentation::Exact;
    AlbedoCounts counts;
    for (const SlopeMap& map : {SlopeMap{steepness_map()}, SlopeMap{vector_map()}}) {
        CAPTURE(map.index());
        const MicrosurfaceColors m = slope_material(map);
        const std::vector<Rgb> colours = slope_colors(map, gradients);
        double sum = 0, worst = 0;
        int cases = 0;
        for (const double theta_deg : {0.0, 60.0, 80.0}) {
            for (const double phi : {0.4, 2.5}) {
                for (const double theta_i_deg : {20.0, 50.0}) {
                    CAPTURE(theta_deg);
                    CAPTURE(phi);
                    const HeightDirections d{degrees(theta_deg), phi, degrees(theta_i_deg), 1.1};
                    const MicrosurfaceLayers a = microsurface_layers(m, f, slope, d, options, table, counts);
                    REQUIRE(a.visibility > 0);
                    const Rgb layer = (1 / a.visibility) * a.shadowed;
                    const Rgb expected = monte_carlo_slope_color(colours, gradients, degrees(theta_deg), phi);
                    const double de = ciede2000_linear_rgb(layer, expected);
                    CAPTURE(text(layer));
                    CAPTURE(text(expected));
                    CHECK(de < 0.6);
                    sum += de;
                    worst = std::max(worst, de);
                    ++cases;
                }
            }
        }
        MESSAGE("mean CIEDE2000 " << sum / cases << ", max " << worst);
        CHECK(sum / cases < 0.3);
    }
}

// With no height map V is eq. 13's, for the unresolved slopes along each
// direction's azimuth: all of the microsurface's far away. sigma_s comes
// from the cosines (the footprint's own rounding leaves (1 - s_k^2) with
// s_k <= 1 / (pi 312): a relative 1e-5 on sigma, within the tolerance).
TEST_CASE("without a height map the visibility of a far footprint is eq. 13 with Lambdas integrated from eq. 3")
{
    const GaussianMicrosurface surface = test_microsurface(0.015, 128, 3);
    ResolvedSlope slope;
    const MicrosurfaceFootprint f = far_footprint(surface, slope);
    const HeightMomentTable table = *HeightMomentTable::create();
    for (const SlopeMap& map : {SlopeMap{steepness_map()}, SlopeMap{vector_map()}}) {
        const MicrosurfaceColors m = slope_material(map);
        for (const auto slopes : {SlopeRepresentation::Gaussian, SlopeRepresentation::Exact}) {
            MicrosurfaceLayerOptions options;
            options.heights = HeightRepresentation::PaperFit;
            options.slopes = slopes;
            AlbedoCounts counts;
            for (const double theta_o : {0.0, 30.0, 60.0, 80.0, 88.0}) {
                for (const double theta_i : {0.0, 45.0, 70.0, 85.0}) {
                    for (const double phi_o : {0.2, 1.9}) {
                        const double phi_i = phi_o + 2.2;
                        CAPTURE(theta_o);
                        CAPTURE(theta_i);
                        CAPTURE(phi_o);
                        const double lo = lambda_by_integration(degrees(theta_o), spectral_sigma_s(surface, phi_o));
                        const double li = lambda_by_integration(degrees(theta_i), spectral_sigma_s(surface, phi_i));
                        const double expected = (1 + lo) / (1 + lo + li);
                        const HeightDirections d{degrees(theta_o), phi_o, degrees(theta_i), phi_i};
                        const MicrosurfaceLayers a = microsurface_layers(m, f, slope, d, options, table, counts);
                        CHECK(a.visibility == doctest::Approx(expected).epsilon(1e-4));
                        // The layer is shadowed by that V.
                        const Rgb layer = (1 / a.visibility) * a.shadowed;
                        CHECK(a.shadowed.g == doctest::Approx(expected * layer.g).epsilon(1e-4));
                    }
                }
            }
        }
    }
}

// ---- the naive method -----------------------------------------------------------

// The naive slope layer is C_s of the footprint's mean gradient, unshadowed.
// The mean gradient by brute force: the midpoint rule on a 128 x 128 grid of
// the parallelogram (cells of 1.6e-4 units against wavelengths >= 0.05: a
// relative error of (2 pi 1.6e-4 / 0.05)^2 / 24 ~ 4e-5 per cosine), so the
// colours agree to the map's steepest change times that, far below 1e-4.
TEST_CASE("the naive slope layer is the map at the brute-force mean gradient over a small footprint, with V = 1")
{
    const GaussianMicrosurface surface = test_microsurface(0.02, 256, 9);
    const HeightMomentTable table = *HeightMomentTable::create();
    MicrosurfaceLayerOptions options;
    options.heights = HeightRepresentation::Naive;
    options.slopes = SlopeRepresentation::Naive;
    struct Footprint {
        double u, v, e1u, e1v, e2u, e2v;
    };
    for (const Footprint& p : {Footprint{0.7, 1.3, 0.02, 0.005, -0.004, 0.015}, Footprint{2.9, 0.1, 0.01, 0, 0, 0.01},
                               Footprint{1.55, 2.45, 0.003, -0.03, 0.012, 0.002}}) {
        CAPTURE(p.u);
        const int n = 128;
        double gx = 0, gy = 0;
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                const double a = (i + 0.5) / n - 0.5, b = (j + 0.5) / n - 0.5;
                double dx, dy;
                surface.gradient(p.u + a * p.e1u + b * p.e2u, p.v + a * p.e1v + b * p.e2v, dx, dy);
                gx += dx;
                gy += dy;
            }
        }
        gx /= n * n;
        gy /= n * n;
        const ResolvedSlope slope = resolved_slope(surface, p.u, p.v, p.e1u, p.e1v, p.e2u, p.e2v);
        CHECK(slope.x == doctest::Approx(gx).epsilon(1e-3).scale(0.01));
        CHECK(slope.y == doctest::Approx(gy).epsilon(1e-3).scale(0.01));
        const MicrosurfaceFootprint f = filter_microsurface(surface, p.u, p.v, p.e1u, p.e1v, p.e2u, p.e2v);
        for (const SlopeMap& map : {SlopeMap{steepness_map()}, SlopeMap{vector_map()}}) {
            const MicrosurfaceColors m = slope_material(map);
            for (const double theta : {0.0, 45.0, 85.0}) {
                const HeightDirections d{degrees(theta), 0.8, degrees(60), 2.0};
                AlbedoCounts counts;
                const MicrosurfaceLayers a = microsurface_layers(m, f, slope, d, options, table, counts);
                CHECK(a.visibility == 1);
                CHECK(max_channel_difference(a.shadowed, evaluate(map, gx, gy)) < 1e-4);
            }
        }
    }
}
