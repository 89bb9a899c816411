// SPDX-License-Identifier: Apache-2.0
// The bench's reference (render_benchmark.h): where one round of rays leaves
// two references with other seeds further apart than asked, both grow round
// by round, and averaging k independent rounds must shrink their difference
// like 1 / sqrt(k), the Monte-Carlo rate, whatever the code reports.
#include "bench/render_benchmark.h"

#include "render_test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace cmfilter;
using namespace cmfilter::bench;

namespace {

// A sphere filling a 20 x 20 image under a terrain-coloured fBm whose base
// period is a few hundredths of a pixel: every pixel averages thousands of
// noise cells, so 1024 rays per pixel leave visible noise in the reference.
struct FineNoiseSphere {
    Scene scene;
    std::vector<Material> materials;
};

FineNoiseSphere fine_noise_sphere()
{
    FineNoiseSphere s;
    s.scene.path = "fine-noise-sphere";
    s.scene.camera = cmfilter_test::make_scene_camera({0, 0, -3}, {0, 0, 0}, {0, 1, 0}, 30, 20, 20);
    s.scene.light.direction = normalize(Vec3{0.3, 0.8, -0.5});
    s.scene.background = {0.1, 0.1, 0.1};
    Surface sphere;
    sphere.kind = SurfaceKind::Sphere;
    sphere.radius = 1;
    sphere.mapping.kind = MappingKind::Spherical;
    sphere.mapping.u_scale = 1024;
    sphere.mapping.v_scale = 512;
    s.scene.surfaces.push_back(sphere);
    s.materials.push_back(cmfilter_test::terrain_fbm_material());
    return s;
}

SceneBench run_bench(FineNoiseSphere& s, double repeat, int max_samples)
{
    BenchOptions options;
    options.configurations = {BenchConfiguration{RenderMethod::Naive}};
    options.repeats = 1;
    options.reference_repeat = repeat;
    options.max_reference_samples = max_samples;
    auto bench = bench_scene(s.scene, s.materials, options);
    REQUIRE(bench);
    return *bench;
}

}  // namespace

TEST_CASE("bench grows its references until they repeat, shrinking their difference like 1 over sqrt of the rounds")
{
    FineNoiseSphere s = fine_noise_sphere();
    const SceneBench one = run_bench(s, 1e9, 16 * kReferenceSamples);
    CHECK(one.reference_samples == kReferenceSamples);  // already within the (huge) tolerance
    const double d1 = one.reference_repeatability.all.mean;
    CAPTURE(d1);
    REQUIRE(d1 > 0.05);  // the scene is as noisy as meant: rounds have something to average away

    // Tolerance 0: grow to the cap, 4 rounds; the difference shrinks like
    // 1 / sqrt(4) (0.5; allow 0.65 for the spread of a 400-pixel mean).
    const SceneBench four = run_bench(s, 0, 4 * kReferenceSamples);
    CHECK(four.reference_samples == 4 * kReferenceSamples);
    const double d4 = four.reference_repeatability.all.mean;
    CAPTURE(d4);
    CHECK(d4 < 0.65 * d1);
    CHECK(d4 > 0.35 * d1);

    // A tolerance between the two: it stops at the first round that meets it.
    const double tolerance = 0.5 * (d1 + d4);
    const SceneBench between = run_bench(s, tolerance, 16 * kReferenceSamples);
    CHECK(between.reference_samples > kReferenceSamples);
    CHECK(between.reference_samples < 16 * kReferenceSamples);
    CHECK(between.reference_repeatability.all.mean <= tolerance);
}

TEST_CASE("bench refuses a negative reference tolerance and a cap below one round")
{
    FineNoiseSphere s = fine_noise_sphere();
    BenchOptions options;
    options.reference_repeat = -1;
    CHECK_FALSE(bench_scene(s.scene, s.materials, options));
    options.reference_repeat = 0.2;
    options.max_reference_samples = kReferenceSamples - 1;
    CHECK_FALSE(bench_scene(s.scene, s.materials, options));
}

TEST_CASE("bench compares the pixels a surface covers in part: the horizon row, whose centre rays miss")
{
    // A ground plane seen from 1.5 units up, looking 0.6 down over 10: the
    // horizon is the image row y_h = H/2 - (H/2) tan(pitch) / tan(fov/2)
    // (y down, pixel rows [k, k + 1)), worked out here from the camera alone.
    const int w = 40, h = 27;
    Scene scene;
    scene.path = "horizon-plane";
    scene.camera = cmfilter_test::make_scene_camera({0, 1.5, 0}, {0, 0.9, 10}, {0, 1, 0}, 50, w, h);
    scene.light.direction = normalize(Vec3{0.4, 1, -0.3});
    scene.background = {0.55, 0.65, 0.8};
    Surface plane;
    plane.mapping.u_axis = {0.5, 0, 0};
    plane.mapping.v_axis = {0, 0, 0.5};
    scene.surfaces.push_back(plane);
    std::vector<Material> materials;
    materials.push_back(cmfilter_test::terrain_fbm_material());

    const double kPi = 3.14159265358979323846;
    const double y_h = h / 2.0 - (h / 2.0) * (0.6 / 10) / std::tan(25 * kPi / 180);
    const int row = static_cast<int>(std::floor(y_h));
    const double below = row + 1 - y_h;  // the horizon row's share below the line
    REQUIRE(below > 0.1);
    REQUIRE(below < 0.5);  // its centre ray misses: the row would not count by centre rays alone

    RenderOptions ro;
    ro.method = RenderMethod::Reference;
    auto reference = render(scene, materials, ro);
    REQUIRE(reference);
    for (int x = 0; x < w; ++x) {
        const auto p = static_cast<std::size_t>(row * w + x);
        CHECK(reference->hit[p] == 0);
        CHECK(std::abs(reference->covered[p] - below) <= 1.0 / 32);  // 32 x 32 jittered rows
        CHECK(reference->covered[static_cast<std::size_t>((row - 1) * w + x)] == 0);
        CHECK(reference->covered[static_cast<std::size_t>((row + 1) * w + x)] == 1);
    }

    BenchOptions options;
    options.configurations = {BenchConfiguration{RenderMethod::Naive}};
    options.repeats = 1;
    auto bench = bench_scene(scene, materials, options);
    REQUIRE(bench);
    // Every row from the horizon's down, the horizon row included.
    CHECK(bench->pixels_hit == static_cast<std::size_t>((h - row) * w));
}
