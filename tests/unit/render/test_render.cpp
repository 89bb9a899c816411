// SPDX-License-Identifier: Apache-2.0
// The renderer's pixel loop (render.h) on small scenes built in code: two
// references with different seeds agree (the check on the reference
// itself), results do not depend on the thread count, misses are background,
// and the footprint widths match their definitions, rms against a
// Monte-Carlo variance of a linear function over the parallelogram; the
// small-sigma shortcut colours a probe C0(mean) exactly where it applies; a
// region of the frame holds the frame's own pixels.
#include "cmfilter/color/color_config.h"
#include "cmfilter/colormap/color_map_loading.h"
#include "cmfilter/texture/anisotropic_probes.h"
#include "cmfilter/texture/footprint_width.h"
#include "cmfilter/noise/noise_spec.h"
#include "cmfilter/render/render.h"

#include "render_test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace cmfilter;

namespace {

// A ground plane to the horizon under a terrain-coloured 6-octave fBm, as in
// the bundled scenes, w x h pixels. The sigma table is a placeholder (these
// tests do not use the gaussian method's colours).
struct PlaneScene {
    Scene scene;
    std::vector<Material> materials;
};

PlaneScene plane_scene(int w, int h)
{
    PlaneScene s;
    s.scene.path = "test-scene";
    s.scene.camera.position = {0, 1.5, 0};
    s.scene.camera.look_at = {0, 0.9, 10};
    s.scene.camera.fov_degrees = 50;
    s.scene.camera.width = w;
    s.scene.camera.height = h;
    s.scene.light.direction = normalize(Vec3{0.4, 1, -0.3});
    s.scene.background = {0.55, 0.65, 0.8};
    Surface plane;
    plane.mapping.u_axis = {0.5, 0, 0};
    plane.mapping.v_axis = {0, 0, 0.5};
    s.scene.surfaces.push_back(plane);
    s.materials.push_back(cmfilter_test::terrain_fbm_material());
    return s;
}

}  // namespace

TEST_CASE("two references with different seeds differ by at most 0.2 mean CIEDE2000")
{
    const PlaneScene s = plane_scene(48, 27);
    RenderOptions options;
    options.method = RenderMethod::Reference;
    options.seed = 1;
    auto a = render(s.scene, s.materials, options);
    options.seed = 2;
    auto b = render(s.scene, s.materials, options);
    REQUIRE(a);
    REQUIRE(b);
    CHECK(a->samples == kReferenceSamples);
    const ErrorSummary d = cmfilter_test::render_difference(*a, *b);
    CAPTURE(d.mean);
    CAPTURE(d.max);
    CHECK(d.mean <= 0.2);
    CHECK(d.mean > 0.0);  // different seeds really sample differently
}

TEST_CASE("renders do not depend on the thread count and repeat with the same seed")
{
    const PlaneScene s = plane_scene(40, 24);
    for (RenderMethod method : {RenderMethod::Naive, RenderMethod::Gaussian, RenderMethod::Supersample}) {
        RenderOptions options;
        options.method = method;
        options.samples = 5;  // not a square: the N-rooks pattern
        options.seed = 9;
        options.threads = 1;
        auto one = render(s.scene, s.materials, options);
        options.threads = 2;
        auto two = render(s.scene, s.materials, options);
        auto again = render(s.scene, s.materials, options);
        REQUIRE(one);
        REQUIRE(two);
        REQUIRE(again);
        CHECK(one->rgb == two->rgb);
        CHECK(two->rgb == again->rgb);
        CHECK(one->sigma == two->sigma);
    }
}

TEST_CASE("a region's pixels are the whole frame's, bit for bit, for every method and thread count")
{
    // The frame's horizon crosses the regions, so edge coverage runs in them.
    const PlaneScene s = plane_scene(24, 14);
    const PixelRegion region{5, 3, 17, 11};
    for (RenderMethod method :
         {RenderMethod::Naive, RenderMethod::Gaussian, RenderMethod::Supersample, RenderMethod::Reference}) {
        CAPTURE(to_string(method));
        RenderOptions options;
        options.method = method;
        options.samples = 5;  // supersample: not a square, the N-rooks pattern
        options.seed = 3;
        options.threads = 1;
        auto frame = render(s.scene, s.materials, options);
        REQUIRE(frame);
        CHECK(frame->x0 == 0);
        CHECK(frame->frame_width == 24);
        for (int threads : {1, 2, 3}) {
            options.threads = threads;
            options.region = region;
            auto part = render(s.scene, s.materials, options);
            REQUIRE(part);
            REQUIRE(part->width == region.width());
            REQUIRE(part->height == region.height());
            CHECK(part->x0 == region.x0);
            CHECK(part->y0 == region.y0);
            CHECK(part->frame_width == 24);
            CHECK(part->frame_height == 14);
            std::size_t differing = 0;
            for (int y = region.y0; y < region.y1; ++y)
                for (int x = region.x0; x < region.x1; ++x) {
                    const std::size_t f = static_cast<std::size_t>(y * 24 + x);
                    const std::size_t r = static_cast<std::size_t>((y - region.y0) * region.width() + x - region.x0);
                    for (int c = 0; c < 3; ++c) differing += part->rgb[3 * r + c] != frame->rgb[3 * f + c];
                    differing += part->mean[r] != frame->mean[f];
                    differing += part->sigma[r] != frame->sigma[f];
                    differing += part->lod[r] != frame->lod[f];
                    differing += part->hit[r] != frame->hit[f];
                    if (!frame->covered.empty()) differing += part->covered[r] != frame->covered[f];
                }
            CAPTURE(threads);
            CHECK(differing == 0);
        }
    }
}

TEST_CASE("render refuses an empty region and one outside the frame, naming the field")
{
    const PlaneScene s = plane_scene(8, 6);
    RenderOptions options;
    options.method = RenderMethod::Naive;
    for (const PixelRegion& bad : {PixelRegion{2, 2, 2, 5}, PixelRegion{0, 3, 8, 1}, PixelRegion{0, 0, 9, 6},
                                   PixelRegion{-1, 0, 4, 4}, PixelRegion{0, 0, 8, 7}}) {
        options.region = bad;
        auto image = render(s.scene, s.materials, options);
        REQUIRE_FALSE(image);
        CAPTURE(image.error().message);
        CHECK(image.error().kind == ErrorKind::BadInput);
        CHECK(image.error().field == "RenderOptions::region");
        CHECK(image.error().message.find("RenderOptions::region " + to_string(bad)) == 0);
        CHECK(image.error().message.find("in the 8 x 6 frame") != std::string::npos);
    }
    options.region = PixelRegion{0, 0, 8, 6};  // the whole frame, as without a region
    auto whole = render(s.scene, s.materials, options);
    options.region.reset();
    auto plain = render(s.scene, s.materials, options);
    REQUIRE(whole);
    REQUIRE(plain);
    CHECK(whole->rgb == plain->rgb);
}

TEST_CASE("pixels that miss every surface are the background, for every method")
{
    PlaneScene s = plane_scene(16, 16);
    s.scene.camera.look_at = {0, 5, 10};  // looking up: the plane stays out of view
    s.scene.camera.fov_degrees = 20;
    for (RenderMethod method : {RenderMethod::Naive, RenderMethod::Gaussian, RenderMethod::Supersample}) {
        RenderOptions options;
        options.method = method;
        options.samples = 4;
        auto image = render(s.scene, s.materials, options);
        REQUIRE(image);
        for (std::size_t p = 0; p < image->hit.size(); ++p) {
            CHECK(image->hit[p] == 0);
            CHECK(image->rgb[3 * p] == static_cast<float>(s.scene.background.r));
            CHECK(image->rgb[3 * p + 2] == static_cast<float>(s.scene.background.b));
        }
    }
}

TEST_CASE("render rejects sample counts out of range and mismatched materials")
{
    const PlaneScene s = plane_scene(8, 8);
    RenderOptions options;
    options.method = RenderMethod::Supersample;
    options.samples = 0;
    auto zero = render(s.scene, s.materials, options);
    REQUIRE_FALSE(zero);
    CHECK(zero.error().message.find("RenderOptions::samples 0 is out of range") != std::string::npos);
    options.samples = 4;
    for (int probes : {0, 65}) {
        options.max_probes = probes;
        auto bad = render(s.scene, s.materials, options);
        REQUIRE_FALSE(bad);
        CHECK(bad.error().field == "RenderOptions::max_probes");
        CHECK_MESSAGE(bad.error().message.find("RenderOptions::max_probes " + std::to_string(probes) +
                                               " is out of range (expected 1 to 64)") != std::string::npos,
                      bad.error().message);
    }
    options.max_probes = 16;
    auto none = render(s.scene, {}, options);
    REQUIRE_FALSE(none);
    CHECK(none.error().message.find("0 materials for 1 surfaces") != std::string::npos);
}

TEST_CASE("footprint widths: rms gives the square with the same variance of a linear function")
{
    // Parallelogram c + s e1 + t e2, s, t uniform in [-1/2, 1/2]. For random
    // gradient directions g, Var(g . x) averaged over directions, by Monte
    // Carlo, against a square of width rms: |g|^2 w^2 / 12 (|g| = 1).
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> unit(-0.5, 0.5), angle(0.0, 6.283185307179586);
    const double e1u = 3.0, e1v = 0.4, e2u = -0.2, e2v = 0.25;
    double variance = 0;
    const int directions = 400, points = 4000;
    for (int d = 0; d < directions; ++d) {
        const double a = angle(rng), gx = std::cos(a), gy = std::sin(a);
        double sum = 0, sum2 = 0;
        for (int k = 0; k < points; ++k) {
            const double s = unit(rng), t = unit(rng);
            const double v = gx * (s * e1u + t * e2u) + gy * (s * e1v + t * e2v);
            sum += v;
            sum2 += v * v;
        }
        variance += (sum2 / points - (sum / points) * (sum / points)) / directions;
    }
    const double w = footprint_width(FootprintWidth::Rms, e1u, e1v, e2u, e2v);
    CHECK(variance == doctest::Approx(w * w / 12).epsilon(0.02));
    // The others by their definitions.
    CHECK(footprint_width(FootprintWidth::Major, 3, 4, 0, 1) == doctest::Approx(5.0));
    CHECK(footprint_width(FootprintWidth::Minor, 3, 4, 0, 1) == doctest::Approx(1.0));
    CHECK(footprint_width(FootprintWidth::Area, 2, 0, 1, 3) == doctest::Approx(std::sqrt(6.0)));
    CHECK(footprint_width(FootprintWidth::Rms, 3, 4, 0, 1) == doctest::Approx(std::sqrt(13.0)));
    auto bad = parse_footprint_width("wide");
    REQUIRE_FALSE(bad);
    CHECK(bad.error().message.find("'wide' is unknown") != std::string::npos);
}

TEST_CASE("anisotropic probes cut the footprint along its major edge into near-square pieces")
{
    // A square footprint: one probe, the footprint's own width.
    FootprintProbes square = footprint_probes(1, 0, 0, 1, 16, FootprintWidth::Rms);
    CHECK(square.count == 1);
    CHECK(square.width == doctest::Approx(footprint_width(FootprintWidth::Rms, 1, 0, 0, 1)));
    // 10 x 1, major edge the second: ceil(10) = 10 probes along it, each piece 1 x 1.
    FootprintProbes thin = footprint_probes(0, 1, 10, 0, 16, FootprintWidth::Rms);
    CHECK(thin.count == 10);
    CHECK(thin.step_u == 10.0);
    CHECK(thin.step_v == 0.0);
    CHECK(thin.width == doctest::Approx(1.0));
    // Capped: 100 x 1 with at most 16 probes, pieces 6.25 x 1.
    FootprintProbes capped = footprint_probes(100, 0, 0, 1, 16, FootprintWidth::Major);
    CHECK(capped.count == 16);
    CHECK(capped.width == doctest::Approx(6.25));
    // The probes' centres tile the major edge: offsets (j + 1/2) / n - 1/2 are
    // symmetric about the centre and n pieces of length major / n cover it.
    double sum = 0;
    for (int j = 0; j < capped.count; ++j) sum += (j + 0.5) / capped.count - 0.5;
    CHECK(std::fabs(sum) < 1e-12);
    // A degenerate footprint (a segment) takes every probe allowed.
    CHECK(footprint_probes(4, 0, 0, 0, 8, FootprintWidth::Rms).count == 8);
    // max_probes 1: the single footprint.
    CHECK(footprint_probes(100, 0, 0, 1, 1, FootprintWidth::Rms).count == 1);
}

TEST_CASE("exact refuses a noise driver, in render and in prepare_materials, naming the surface")
{
    PlaneScene s = plane_scene(8, 6);
    RenderOptions options;
    options.method = RenderMethod::Exact;
    auto image = render(s.scene, s.materials, options);
    REQUIRE_FALSE(image);
    CHECK(image.error().kind == ErrorKind::BadInput);
    CHECK(image.error().message.find("noise drivers have no exact filtering distribution") != std::string::npos);

    s.scene.surfaces[0].material.colormap.image_path = std::string(CMFILTER_SOURCE_DIR) + "/luts/terrain.png";
    s.scene.surfaces[0].material.colormap.domain_min = -0.68;
    s.scene.surfaces[0].material.colormap.domain_max = 0.68;
    s.scene.surfaces[0].material.driver.kind = DriverKind::Noise;
    s.scene.surfaces[0].material.driver.noise_spec = "fbm:base=gradient,octaves=6";
    auto config = ColorConfig::load("");
    REQUIRE(config);
    MaterialOptions material_options;
    material_options.histograms = true;
    auto materials = prepare_materials(s.scene, *config, material_options);
    REQUIRE_FALSE(materials);
    CHECK(materials.error().kind == ErrorKind::BadInput);
    CHECK(materials.error().message ==
          "test-scene: /surfaces/0/material/driver: exact needs a texture driver with at most 256 distinct values; "
          "noise drivers have no exact filtering distribution");
}

TEST_CASE("the gaussian method takes C0 of each probe's mean where the small-sigma shortcut applies, and counts it")
{
    // Every probe's sigma is the placeholder table's 0.1; a threshold above it
    // at every mean sends every probe to C0(mean): the naive method's colours.
    PlaneScene s = plane_scene(32, 18);
    RenderOptions options;
    options.method = RenderMethod::Gaussian;
    auto lookups = render(s.scene, s.materials, options);
    REQUIRE(lookups);
    CHECK(lookups->footprints > 0);
    CHECK(lookups->plain_footprints == 0);

    const ColorMap& map = s.materials[0].color.map;
    s.materials[0].color.plain = PlainLookupSigma(map.vmin - 100, map.texel_width(), std::vector<float>(100000, 0.11f));
    auto shortcut = render(s.scene, s.materials, options);
    options.method = RenderMethod::Naive;
    auto naive = render(s.scene, s.materials, options);
    REQUIRE(shortcut);
    REQUIRE(naive);
    CHECK(shortcut->plain_footprints == shortcut->footprints);
    CHECK(shortcut->footprints == lookups->footprints);
    CHECK(shortcut->rgb == naive->rgb);
    CHECK(shortcut->rgb != lookups->rgb);
    // A threshold below every probe's sigma changes nothing.
    s.materials[0].color.plain = PlainLookupSigma(map.vmin - 100, map.texel_width(), std::vector<float>(100000, 0.09f));
    options.method = RenderMethod::Gaussian;
    auto below = render(s.scene, s.materials, options);
    REQUIRE(below);
    CHECK(below->plain_footprints == 0);
    CHECK(below->rgb == lookups->rgb);
}
