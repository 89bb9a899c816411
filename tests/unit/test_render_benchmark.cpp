// The bench's reference (render_benchmark.h): where one round of rays leaves
// two references with other seeds further apart than asked, both grow round
// by round, and averaging k independent rounds must shrink their difference
// like 1 / sqrt(k), the Monte-Carlo rate, whatever the code reports.
#include "cmfilter/render_benchmark.h"

#include "render_test_support.h"

#include <doctest/doctest.h>

#include <string>
#include <vector>

using namespace cmfilter;

namespace {

// A sphere filling a 20 x 20 image under a terrain-coloured fBm whose base
// period is a few hundredths of a pixel: every pixel averages thousands of
// noise cells, so 1024 rays per pixel leave visible noise in the reference.
struct FineNoiseSphere {
    Scene scene;
    std::vector<SurfaceMaterial> materials;
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
