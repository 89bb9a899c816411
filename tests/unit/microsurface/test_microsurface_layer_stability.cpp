// SPDX-License-Identifier: Apache-2.0
// A microsurface material's layers (microsurface_albedo.h) stay finite and in
// range on sweeps of everything a renderer can hand them: view and light
// angles from 0 through 90 degrees to below the surface, any azimuths,
// unresolved slope covariances from 0 to 1e3 (degenerate and strongly
// anisotropic ones too), resolved slopes up to 1e3, for a slope map alone,
// a weighted sum and a product of heights and slopes, in every
// representation render uses; and on textured displacements (flat, scales,
// steep steps) from a point footprint to an infinite one, with the shading
// and the masking correlated or not. Every channel of V x layers must lie in V
// times the layers' range: for a sum, the weighted sum of the maps'
// per-channel ranges; for a product, the product of the ranges; and V in
// [0, 1].
#include "cmfilter/microsurface/displacement_texture.h"
#include "cmfilter/microsurface/height_moment_table.h"
#include "cmfilter/microsurface/microsurface_albedo.h"

#include "microsurface_test_support.h"
#include "slope_layer_test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <iterator>
#include <limits>
#include <utility>
#include <cmath>
#include <string>
#include <vector>

using namespace cmfilter;
using namespace cmfilter_test;

namespace {

SteepnessColorMap steepness_map()
{
    SteepnessColorMap map;
    map.by_angle.vmin = 5;
    map.by_angle.vmax = 70;
    map.by_angle.wrap = WrapMode::Clamp;
    map.by_angle.texels = {{0.10, 0.35, 0.05}, {0.20, 0.40, 0.08}, {0.40, 0.38, 0.30}, {0.75, 0.74, 0.72}};
    return map;
}

// A steepness map that repeats beyond its domain (every angle maps somewhere
// inside it).
SteepnessColorMap repeating_steepness_map()
{
    SteepnessColorMap map = steepness_map();
    map.by_angle.vmin = 10;
    map.by_angle.vmax = 30;
    map.by_angle.wrap = WrapMode::Repeat;
    return map;
}

SlopeVectorColorMap vector_map()
{
    SlopeVectorColorMap map;
    map.width = 4;
    map.height = 3;
    map.s_max = 0.8;
    map.texels = {{0.9, 0.1, 0.1},    {0.7, 0.5, 0.1}, {0.3, 0.8, 0.2}, {0.1, 0.6, 0.6},
                  {0.2, 0.2, 0.9},    {0.5, 0.1, 0.7}, {0.5, 0.5, 0.5}, {0.05, 0.05, 0.05},
                  {0.95, 0.95, 0.95}, {0.6, 0.3, 0.0}, {0.0, 0.4, 0.8}, {0.3, 0.3, 0.1}};
    return map;
}

// A material and the range its layers combine into (before V).
struct Case {
    std::string name;
    MicrosurfaceColors material;
    ColorRange range;
};

std::vector<Case> cases()
{
    std::vector<Case> out;
    for (const SlopeMap& map :
         {SlopeMap{steepness_map()}, SlopeMap{repeating_steepness_map()}, SlopeMap{vector_map()}}) {
        MicrosurfaceColors m;
        m.slope = map;
        out.push_back({"slope map " + std::to_string(map.index()), m, slope_range(map)});
    }
    const ColorRange heights = color_range(microsurface_test_map());
    {
        // k1 C_h + k2 C_s.
        MicrosurfaceColors m;
        m.height = microsurface_test_layer(2, 16, 0.05);
        m.slope = SlopeMap{vector_map()};
        m.combine.mode = CombineMode::Sum;
        m.combine.height = 0.6;
        m.combine.slope = 1.4;
        const ColorRange s = slope_range(*m.slope);
        out.push_back({"sum", m, {0.6 * heights.lo + 1.4 * s.lo, 0.6 * heights.hi + 1.4 * s.hi}});
    }
    {
        // C_h C_s.
        MicrosurfaceColors m;
        m.height = microsurface_test_layer(2, 16, 0.05);
        m.slope = SlopeMap{steepness_map()};
        m.combine.mode = CombineMode::Product;
        const ColorRange s = slope_range(*m.slope);
        const auto times = [](const Rgb& a, const Rgb& b) { return Rgb{a.r * b.r, a.g * b.g, a.b * b.b}; };
        out.push_back({"product", m, {times(heights.lo, s.lo), times(heights.hi, s.hi)}});
    }
    return out;
}

struct Representation {
    const char* name;
    HeightRepresentation heights;
    SlopeRepresentation slopes;
};

// What render pairs (naive, gaussian, gaussian-exact, exact).
const Representation kNaive{"naive", HeightRepresentation::Naive, SlopeRepresentation::Naive};
const Representation kGaussian{"gaussian", HeightRepresentation::PaperFit, SlopeRepresentation::Gaussian};
const Representation kGaussianExact{"gaussian-exact", HeightRepresentation::ExactMoments,
                                    SlopeRepresentation::Gaussian};
const Representation kExact{"exact", HeightRepresentation::Exact, SlopeRepresentation::Exact};

const double kThetas[] = {0, 1e-6, 30, 60, 85, 89, 89.999, 90, 91};

// Unresolved slope covariances (xx, xy, yy): none, vanishing, moderate,
// anisotropic, degenerate (rank 1, along an axis and diagonal), nearly
// singular, huge and huge-anisotropic.
struct Covariance {
    double xx, xy, yy;
};
const Covariance kCovariances[] = {{0, 0, 0}, {1e-14, 0, 1e-14}, {0.04, 0.01, 0.09}, {1, 0, 1},     {2, 0, 1e-8},
                                   {1, 0, 0}, {0.5, 0.5, 0.5},   {1, 0.9999999, 1},  {1e3, 0, 1e3}, {1e3, -300, 1e-3}};

struct Slope {
    double x, y;
};

// The footprint: a resolved height, an unresolved height spread, the slope
// covariance, and a resolved surface of its own.
MicrosurfaceFootprint footprint(const Covariance& c, double resolved_variance)
{
    MicrosurfaceFootprint f;
    f.mean_height = 0.011;
    f.sigma_h = 0.006;
    f.slope_xx = c.xx;
    f.slope_xy = c.xy;
    f.slope_yy = c.yy;
    f.resolved_sigma_h = 0.004;
    f.resolved_xx = f.resolved_yy = resolved_variance;
    return f;
}

struct Directions {
    double theta_o, theta_i, phi_o, phi_i;  // degrees, radians
};

// Every view angle with every light angle (`all_pairs`), or each view angle
// with one light angle and each light angle with one view angle (cycling
// through the other list); at the azimuths phi_o = 0 with the light on the
// viewer's side and phi_o = 2.1 with the light opposite.
std::vector<Directions> directions(bool all_pairs)
{
    const std::size_t n = std::size(kThetas);
    std::vector<std::pair<double, double>> pairs;
    for (std::size_t i = 0; i < n; ++i) {
        if (all_pairs) {
            for (std::size_t j = 0; j < n; ++j) pairs.push_back({kThetas[i], kThetas[j]});
        } else {
            pairs.push_back({kThetas[i], kThetas[(i + 3) % n]});
            pairs.push_back({kThetas[(i + 5) % n], kThetas[i]});
        }
    }
    std::vector<Directions> out;
    for (const auto& [o, i] : pairs) {
        out.push_back({o, i, 0.0, 0.0});
        out.push_back({o, i, 2.1, 2.1 + 3.14159265358979});
    }
    return out;
}

// Sweeps one representation over every material, covariance (the resolved
// surface's slopes alternately none and rough), resolved slope and
// direction; returns the number of footprints checked.
int sweep(const Representation& r, const std::vector<Directions>& all_directions, const std::vector<Slope>& slopes,
          MaskingShadowing masking)
{
    const HeightMomentTable table = *HeightMomentTable::create();
    MicrosurfaceLayerOptions options;
    options.heights = r.heights;
    options.slopes = r.slopes;
    options.masking = masking;
    AlbedoCounts counts;
    int checked = 0, failures = 0;
    for (const Case& k : cases()) {
        for (std::size_t ci = 0; ci < std::size(kCovariances); ++ci) {
            const Covariance& c = kCovariances[ci];
            const double resolved = ci % 2 ? 0.3 : 0.0;
            const MicrosurfaceFootprint f = footprint(c, resolved);
            for (const Slope& s : slopes) {
                for (const Directions& dir : all_directions) {
                    const HeightDirections d{degrees(dir.theta_o), dir.phi_o, degrees(dir.theta_i), dir.phi_i};
                    const MicrosurfaceLayers a =
                        microsurface_layers(k.material, f, ResolvedSlope{s.x, s.y}, d, options, table, counts);
                    ++checked;
                    const bool ok = std::isfinite(a.visibility) && a.visibility >= 0 && a.visibility <= 1 &&
                                    is_finite(a.shadowed) && std::isfinite(a.mean) && std::isfinite(a.sigma) &&
                                    within_scaled_range(a.shadowed, k.range, a.visibility, 1e-6);
                    if (!ok && ++failures <= 5) {
                        CAPTURE(k.name);
                        CAPTURE(r.name);
                        CAPTURE(c.xx);
                        CAPTURE(c.xy);
                        CAPTURE(c.yy);
                        CAPTURE(resolved);
                        CAPTURE(s.x);
                        CAPTURE(s.y);
                        CAPTURE(dir.theta_o);
                        CAPTURE(dir.theta_i);
                        CAPTURE(dir.phi_o);
                        CAPTURE(dir.phi_i);
                        CAPTURE(a.visibility);
                        CAPTURE(a.shadowed.r);
                        CAPTURE(a.shadowed.g);
                        CAPTURE(a.shadowed.b);
                        CHECK(ok);
                    }
                }
            }
        }
    }
    CHECK(failures == 0);
    return checked;
}

const std::vector<Slope> kAllSlopes = {{0, 0}, {0.3, -0.2}, {5, 0}, {-40, 25}, {1e3, 0}, {-1e3, 1e3}};

}  // namespace

TEST_CASE("naive microsurface layers stay finite and in range on every angle, spread and resolved slope")
{
    CHECK(sweep(kNaive, directions(true), kAllSlopes, MaskingShadowing::Uncorrelated) > 0);
}

TEST_CASE("gaussian microsurface layers stay finite and in range on every angle, spread and resolved slope")
{
    CHECK(sweep(kGaussian, directions(true), kAllSlopes, MaskingShadowing::Uncorrelated) > 0);
}

TEST_CASE("gaussian-exact microsurface layers with correlated masking stay finite and in range on every sweep")
{
    CHECK(sweep(kGaussianExact, directions(true), kAllSlopes, MaskingShadowing::DirectionCorrelated) > 0);
}

TEST_CASE("exact microsurface layers stay finite and in range on every view and light angle, spread and resolved slope")
{
    // D_s's colour exactly costs 4096 map lookups: each angle once with
    // the other list's, and three resolved slopes (none, moderate, huge).
    CHECK(sweep(kExact, directions(false), {{0, 0}, {0.3, -0.2}, {-1e3, 1e3}}, MaskingShadowing::Uncorrelated) > 0);
}

TEST_CASE("the base layer combined with any probe's layers stays finite and in range")
{
    // V in [0, 1] and shadowed in V x [lo, hi] give a sum in [0, k0 C0 + hi]
    // and a product in [0, C0 hi].
    const Rgb base{0.3, 0.55, 0.8};
    ColorCombination sum;
    sum.mode = CombineMode::Sum;
    sum.base = 0.5;
    ColorCombination product;
    product.mode = CombineMode::Product;
    for (const double v : {0.0, 1e-300, 0.25, 1.0}) {
        for (const double scale : {0.0, 1e-300, 0.5, 1.0}) {
            const Rgb shadowed = (v * scale) * Rgb{0.9, 0.4, 0.1};
            const Rgb s = combine_microsurface_albedo(sum, v, shadowed, base);
            const Rgb p = combine_microsurface_albedo(product, v, shadowed, base);
            CHECK(is_finite(s));
            CHECK(is_finite(p));
            for (int c = 0; c < 3; ++c) {
                CHECK(s[c] >= 0);
                CHECK(s[c] <= 0.5 * base[c] + Rgb{0.9, 0.4, 0.1}[c] + 1e-12);
                CHECK(p[c] >= 0);
                CHECK(p[c] <= base[c] * Rgb{0.9, 0.4, 0.1}[c] + 1e-12);
            }
        }
    }
}

namespace {

// Displacements: the bundled snake's scales, a flat image and a 4 x 4 one of
// steep random steps.
std::vector<std::pair<std::string, DisplacementTexture>> displacements()
{
    std::vector<std::pair<std::string, DisplacementTexture>> out;
    DisplacementOptions o;
    o.path = std::string(CMFILTER_SOURCE_DIR) + "/examples/scenes/snake-scales.exr";
    auto snake = DisplacementTexture::load(o);
    REQUIRE(snake);
    out.push_back({"snake", *snake});
    o.path = "flat";
    auto flat = DisplacementTexture::from_texels(std::vector<float>(16, 0.25f), 4, 4, o);
    REQUIRE(flat);
    out.push_back({"flat", *flat});
    o.path = "steps";
    o.height_scale = 3;
    auto steps = DisplacementTexture::from_texels(
        {0.1f, 0.9f, 0.0f, 0.4f, 0.7f, 0.2f, 1.0f, 0.3f, 0.0f, 0.5f, 0.6f, 0.95f, 0.35f, 0.05f, 0.8f, 0.15f}, 4, 4, o);
    REQUIRE(steps);
    out.push_back({"steps", *steps});
    return out;
}

}  // namespace

// Every representation render uses on a displacement, with the shading and
// masking correlated or not, over pieces from a point to infinite, at
// ordinary and far-off positions, on every view and light angle: V in [0, 1],
// V x the slope layer in V times the map's range, everything finite.
TEST_CASE("displacement layers stay finite and in range on every angle, footprint and correlation")
{
    const HeightMomentTable table = *HeightMomentTable::create();
    const double inf = std::numeric_limits<double>::infinity();
    const FootprintPiece pieces[] = {
        {0.3, 0.6, 0, 0, 0, 0},    {0.3, 0.6, 0.004, 0, 0, 0.002}, {0.3, 0.6, 0.2, 0.05, -0.01, 0.03},
        {0.5, 0.5, 1, 0, 0, 1},    {1e5, -3e4, 2.5, 1, 0, 0.01},   {0.1, 0.2, 1e3, 0, 0, 1e3},
        {0.1, 0.2, inf, 0, 0, inf}};
    AlbedoCounts counts;
    int checked = 0, failures = 0;
    for (const auto& [name, texture] : displacements())
        for (const SlopeMap& map : {SlopeMap{steepness_map()}, SlopeMap{vector_map()}}) {
            MicrosurfaceColors m;
            m.slope = map;
            const ColorRange range = slope_range(map);
            for (const Representation& r : {kNaive, kGaussian, kGaussianExact, kExact})
                for (const SlopeShading shading : {SlopeShading::Uncorrelated, SlopeShading::Correlated})
                    for (const MaskingShadowing masking :
                         {MaskingShadowing::Uncorrelated, MaskingShadowing::DirectionCorrelated}) {
                        MicrosurfaceLayerOptions options;
                        options.heights = r.heights;
                        options.slopes = r.slopes;
                        options.slope_shading = shading;
                        options.masking = masking;
                        for (const FootprintPiece& p : pieces) {
                            const DisplacementFootprint d = texture.footprint(p.u, p.v, p.e1u, p.e1v, p.e2u, p.e2v);
                            MicrosurfaceFootprint f;
                            f.mean_height = d.mean_height;
                            f.sigma_h = d.sigma_h;
                            f.slope_xx = d.slope_xx;
                            f.slope_xy = d.slope_xy;
                            f.slope_yy = d.slope_yy;
                            // The exact method samples 4096 points per piece: fewer directions for it.
                            for (const Directions& dir : directions(r.slopes != SlopeRepresentation::Exact)) {
                                const HeightDirections hd{degrees(dir.theta_o), dir.phi_o, degrees(dir.theta_i),
                                                          dir.phi_i};
                                const MicrosurfaceLayers a =
                                    microsurface_layers(m, f, ResolvedSlope{d.slope_x, d.slope_y}, hd, options, table,
                                                        counts, &texture, &p);
                                ++checked;
                                const bool ok = std::isfinite(a.visibility) && a.visibility >= 0 && a.visibility <= 1 &&
                                                is_finite(a.shadowed) &&
                                                within_scaled_range(a.shadowed, range, a.visibility, 1e-6);
                                if (!ok && ++failures <= 5) {
                                    // A copy: CAPTURE's lambda cannot capture a structured binding.
                                    const std::string displacement = name;
                                    CAPTURE(displacement);
                                    CAPTURE(r.name);
                                    CAPTURE(static_cast<int>(shading));
                                    CAPTURE(static_cast<int>(masking));
                                    CAPTURE(p.u);
                                    CAPTURE(p.e1u);
                                    CAPTURE(dir.theta_o);
                                    CAPTURE(dir.theta_i);
                                    CAPTURE(a.visibility);
                                    CAPTURE(a.shadowed.r);
                                    CHECK(ok);
                                }
                            }
                        }
                    }
        }
    CHECK(failures == 0);
    CHECK(checked > 10000);
}
