// SPDX-License-Identifier: Apache-2.0
// render's mixture on a noise driver (noise_sub_footprints.h through
// noise_surface.h): a ground plane whose fBm is in the transition, seen from
// straight down to the horizon, stays finite and never further from the
// ray-traced reference than gaussian; with one square it is gaussian. The
// LODs a view reaches on it (surface_lods.h), which --method auto measures.
#include "cmfilter/render/render.h"
#include "cmfilter/render/surface_lods.h"
#include "cmfilter/tables/gaussian_color_table.h"

#include "noise_transition_fixture.h"
#include "render_test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using namespace cmfilter;

namespace {

constexpr double kTwoPi = 6.283185307179586;

// The fixture's fBm (its baked sigma table) through its hue cycle, with the
// default table, on a plane 16 noise units to a scene unit.
struct NoisePlane {
    Scene scene;
    std::vector<Material> materials;
};

NoisePlane noise_plane(double elevation_degrees, int w, int h)
{
    const auto& f = cmfilter_test::noise_transition_fixture();
    NoisePlane s;
    s.scene.path = "noise-mixture-plane";
    const double a = elevation_degrees * kTwoPi / 360;
    if (elevation_degrees == 90.0) {
        s.scene.camera.position = {0, 2, 0};
        s.scene.camera.look_at = {0, 0, 0};
        s.scene.camera.up = {0, 0, 1};
    } else {
        s.scene.camera.position = {0, 0.5 + 2 * std::sin(a), -2 * std::cos(a)};
        s.scene.camera.look_at = {0, 0.5, 0};
        s.scene.camera.up = {0, 1, 0};
    }
    s.scene.camera.fov_degrees = 30;
    s.scene.camera.width = w;
    s.scene.camera.height = h;
    s.scene.light.direction = {0, 1, 0};
    s.scene.background = {0.55, 0.65, 0.8};
    Surface plane;
    plane.mapping.u_axis = {16, 0, 0};
    plane.mapping.v_axis = {0, 0, 16};
    s.scene.surfaces.push_back(plane);
    ColorLayer color;
    color.map = f.map;
    auto table = GaussianColorTable::bake(color.map, {});
    REQUIRE(table);
    color.table = std::move(*table);
    s.materials.push_back({{}, std::move(color), NoiseDriver{f.noise}});
    return s;
}

}  // namespace

TEST_CASE("mixture on a noise plane stays finite and within gaussian's error from straight down to the horizon")
{
    // 16 x 16 pixels; elevations 90 to 1 degrees and along the plane (0:
    // the horizon through the middle). Against the reference the mixture's
    // mean CIEDE2000 is no more than the Gaussian's plus 0.05 (a shared
    // reference, as the texture test's).
    for (double elevation : {90.0, 30.0, 10.0, 3.0, 1.0, 0.0}) {
        CAPTURE(elevation);
        const NoisePlane p = noise_plane(elevation, 16, 16);
        cmfilter_test::check_mixture_within_gaussian(p.scene, p.materials, 5, elevation);
    }
}

TEST_CASE("mixture with one square per footprint renders as gaussian, bit for bit")
{
    const NoisePlane p = noise_plane(10, 12, 8);
    RenderOptions options;
    options.method = RenderMethod::Gaussian;
    auto gaussian = render(p.scene, p.materials, options);
    options.method = RenderMethod::Mixture;
    options.sub_footprints.max_cells = 1;
    auto one = render(p.scene, p.materials, options);
    REQUIRE(gaussian);
    REQUIRE(one);
    CHECK(one->rgb == gaussian->rgb);
    // And per surface, as --method auto sets it.
    options.sub_footprints.max_cells = 8;
    options.noise_sub_footprints = {1};
    options.method = RenderMethod::Gaussian;
    auto chosen = render(p.scene, p.materials, options);
    REQUIRE(chosen);
    CHECK(chosen->rgb == gaussian->rgb);
    options.noise_sub_footprints = {4};
    auto four = render(p.scene, p.materials, options);
    options.noise_sub_footprints.clear();
    options.method = RenderMethod::Mixture;
    options.sub_footprints.max_cells = 4;
    auto mixture_four = render(p.scene, p.materials, options);
    REQUIRE(four);
    REQUIRE(mixture_four);
    CHECK(four->rgb == mixture_four->rgb);
    CHECK(four->rgb != gaussian->rgb);
    options.noise_sub_footprints = {17};
    auto bad = render(p.scene, p.materials, options);
    REQUIRE(!bad);
    CHECK(bad.error().field == "RenderOptions::noise_sub_footprints");
}

TEST_CASE("the LODs a view reaches: a plane seen straight down has one, a surface behind the camera none")
{
    // Straight down from height 2 with a 30-degree field of view over 16
    // pixels, the plane is parallel to the image: every pixel's footprint
    // is the same square, 2 * 2 tan(15 deg) / 16 scene units, 16 noise units
    // to a scene unit: LOD log2(4 tan(15 deg) / p_0).
    NoisePlane p = noise_plane(90.0, 16, 16);
    Surface behind;
    behind.kind = SurfaceKind::Sphere;
    behind.center = {0, 6, 0};
    behind.radius = 0.5;
    p.scene.surfaces.push_back(behind);
    p.materials.push_back(p.materials.front());
    const double p0 = cmfilter_test::noise_transition_fixture().noise.noise().base_period();
    const double expected = std::log2(4 * std::tan(kTwoPi / 24) / p0);
    RenderOptions options;
    options.method = RenderMethod::Mixture;
    // One footprint a pixel: a square's edges differ by rounding, and two
    // probes (ceil of a ratio a hair above 1) would halve one edge.
    options.max_probes = 1;
    options.region = PixelRegion{2, 3, 5, 7};  // the survey takes the whole frame
    auto ranges = survey_surface_lods(p.scene, p.materials, options);
    REQUIRE(ranges);
    REQUIRE(ranges->size() == 2);
    CHECK((*ranges)[0].pixels == 256);
    CHECK((*ranges)[0].first == doctest::Approx(expected).epsilon(1e-5));
    CHECK((*ranges)[0].last == doctest::Approx(expected).epsilon(1e-5));
    CHECK((*ranges)[1].pixels == 0);

    // From an image without surface indices: refused, naming the field.
    options.region.reset();
    auto image = render(p.scene, p.materials, options);
    REQUIRE(image);
    auto refused = surface_lod_ranges(*image, 2);
    REQUIRE(!refused);
    CHECK(refused.error().message.find("RenderedImage::surface") != std::string::npos);
}
