// SPDX-License-Identifier: Apache-2.0
// The largest sigma a driver gives a colour table (driver_sigma_range.h):
// a moment pyramid's against brute-force box statistics of its driver
// (tests/support/box_reference.h), a driver image's aligned blocks, a noise
// sigma table's largest box sigma, a scene's surfaces (those using the map,
// else all), and the errors for missing files and files of another kind.
#include "cmfilter/scene/driver_sigma_range.h"

#include "cmfilter/texture/moment_pyramid.h"
#include "cmfilter/noise/noise_sigma_table_file.h"

#include "box_reference.h"
#include "test_images.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

using namespace cmfilter;
namespace fs = std::filesystem;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

const std::string kSource = CMFILTER_SOURCE_DIR;
const std::string kSigmaTable = kSource + "/examples/scenes/fbm-gradient-6.exr";

// Values in [0, 1) from a 64-bit LCG, with a bright square in one corner so
// that a middle level holds the largest variance.
std::vector<float> driver_values(int w, int h, std::uint64_t seed)
{
    std::vector<float> v(static_cast<std::size_t>(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
            const double u = static_cast<double>(seed >> 11) * 0x1.0p-53;
            v[static_cast<std::size_t>(y) * w + x] = static_cast<float>(x < w / 4 && y < h / 4 ? 4 + u : u);
        }
    return v;
}

// Brute force: the largest standard deviation of f over the texels of every
// level the pyramid's geometry gives (box_reference.h), levels up to `levels`.
double reference_largest_sigma(const std::vector<float>& f, int W, int H, int levels)
{
    double largest = 0;
    for (int k = 0; k < levels; ++k) {
        const int w = std::max(1, W >> k), h = std::max(1, H >> k);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                double m1 = 0, m2 = 0;
                for (const auto& b : cmfilter_test::box_weights(W, H, w, h, x, y)) {
                    const double d = f[static_cast<std::size_t>(b.j) * W + b.i];
                    m1 += b.weight * d;
                    m2 += b.weight * d * d;
                }
                largest = std::max(largest, m2 - m1 * m1);
            }
    }
    return std::sqrt(largest);
}

std::string bake_pyramid(const std::string& dir, const std::string& name, const std::vector<float>& f, int w, int h)
{
    const std::string driver = dir + "/" + name + ".exr", output = dir + "/" + name + "-moments.exr";
    cmfilter_test::write_image(driver, w, h, 1, OIIO::TypeDesc::FLOAT, f.data());
    MomentBakeOptions options;
    options.driver_path = driver;
    options.output_path = output;
    auto r = bake_moment_pyramid(options);
    if (!r) FAIL(r.error().message);
    return output;
}

double largest_box_sigma(const std::string& path)
{
    auto loaded = read_noise_sigma_table(path, FootprintShape::Box);
    REQUIRE(loaded);
    const std::vector<double>& s = loaded->table.sigmas();
    return *std::max_element(s.begin(), s.end());
}

Surface noise_surface(const std::string& map, const std::string& spec, const std::string& sigma_table)
{
    Surface s;
    s.material.colormap.image_path = map;
    s.material.driver.kind = DriverKind::Noise;
    s.material.driver.noise_spec = spec;
    s.material.driver.sigma_table_path = sigma_table;
    return s;
}

}  // namespace

TEST_CASE("a moment pyramid's largest sigma is the largest box-footprint sigma over its levels")
{
    const std::string dir = cmfilter_test::temp_dir("cmfilter-test-driver-sigma");
    struct Size {
        int w, h;
    };
    for (Size size : {Size{32, 32}, Size{24, 10}}) {
        CAPTURE(size.w);
        CAPTURE(size.h);
        const std::vector<float> f = driver_values(size.w, size.h, 7);
        const std::string name = "driver-" + std::to_string(size.w) + "x" + std::to_string(size.h);
        const std::string pyramid = bake_pyramid(dir, name, f, size.w, size.h);
        auto range = largest_moment_pyramid_sigma(pyramid);
        REQUIRE(range);
        // Every level TextureSystem reaches: all of them for the square
        // driver; up to the first with a side of 1 for 24 x 10 (24 x 10 ..
        // 3 x 1: 4 of 5 levels).
        const int reachable = size.w == size.h ? moment_level_count(size.w, size.h) : 4;
        const double expected = reference_largest_sigma(f, size.w, size.h, reachable);
        CHECK(range->sigma_max == doctest::Approx(expected).epsilon(1e-5));
        CHECK(range->kind == "moment-pyramid");
        CHECK(contains(range->how, pyramid));
        // The whole driver's sigma is smaller: the bright corner gives a
        // middle level the largest spread.
        CHECK(reference_largest_sigma(f, size.w, size.h, 1) < expected);

        auto by_kind = largest_driver_sigma(pyramid, {});
        REQUIRE(by_kind);
        CHECK(by_kind->sigma_max == range->sigma_max);

        if (size.w == size.h) {  // power of two: the image's aligned blocks are the pyramid's texels
            auto image = largest_driver_image_sigma(dir + "/" + name + ".exr", 1);
            REQUIRE(image);
            CHECK(image->sigma_max == doctest::Approx(expected).epsilon(1e-6));
        }
    }
}

TEST_CASE("a noise sigma table's largest sigma is its largest box sigma")
{
    auto range = largest_driver_sigma(kSigmaTable, {});
    REQUIRE(range);
    CHECK(range->sigma_max == largest_box_sigma(kSigmaTable));
    CHECK(range->kind == "noise-sigma-table");
    CHECK(range->sigma_max > 0.2);  // fbm, 6 octaves: global sigma 0.245
    CHECK(range->sigma_max < 0.25);
}

TEST_CASE("a scene's largest sigma comes from the surfaces using the map, else from all")
{
    const std::string terrain = kSource + "/luts/terrain.png", step = kSource + "/luts/step.png";
    Scene scene;
    scene.path = "test-scene.json";
    // Surface 0: terrain over the baked sigma table; surface 1: step over a
    // single octave without a sigma table (its global sigma, larger).
    scene.surfaces.push_back(noise_surface(terrain, "fbm:base=gradient,octaves=6", kSigmaTable));
    scene.surfaces.push_back(noise_surface(step, "gradient", ""));

    DriverSigmaOptions options;
    options.map_path = terrain;
    auto for_terrain = largest_scene_sigma(scene, options);
    REQUIRE(for_terrain);
    CHECK(for_terrain->sigma_max == largest_box_sigma(kSigmaTable));
    CHECK(contains(for_terrain->how, "surface 0"));
    CHECK(contains(for_terrain->how, "1 of 2 surfaces, those using this map"));

    options.map_path = step;
    auto for_step = largest_scene_sigma(scene, options);
    REQUIRE(for_step);
    CHECK(contains(for_step->how, "global sigma of the noise 'gradient'"));
    CHECK(for_step->sigma_max > 0);

    options.map_path = kSource + "/luts/stripes.png";  // no surface uses it: all surfaces
    auto for_other = largest_scene_sigma(scene, options);
    REQUIRE(for_other);
    CHECK(for_other->sigma_max == std::max(for_terrain->sigma_max, for_step->sigma_max));
    CHECK(contains(for_other->how, "all 2 surfaces; none uses this map"));

    // A scene file: the bundled example, whose map is terrain.png.
    options.map_path = terrain;
    auto file = largest_driver_sigma(kSource + "/examples/scenes/plane-fbm-terrain.json", options);
    REQUIRE(file);
    CHECK(file->sigma_max == largest_box_sigma(kSigmaTable));
    CHECK(file->kind == "scene");
}

TEST_CASE("--for files that are missing or of another kind are refused")
{
    auto missing = largest_driver_sigma("no-such-dir/no-such.exr", {});
    REQUIRE_FALSE(missing);
    CHECK(missing.error().kind == ErrorKind::Io);
    CHECK(contains(missing.error().message, "no-such.exr"));

    auto missing_scene = largest_driver_sigma("no-such-dir/no-such.json", {});
    REQUIRE_FALSE(missing_scene);
    CHECK(missing_scene.error().kind == ErrorKind::Io);

    auto plain_image = largest_driver_sigma(kSource + "/luts/terrain.png", {});
    REQUIRE_FALSE(plain_image);
    CHECK(plain_image.error().kind == ErrorKind::BadInput);
    CHECK(contains(plain_image.error().message, "is not a driver to take sigma from (it has no cmfilter:kind;"));
    CHECK(contains(plain_image.error().message, "expected a noise sigma table"));

    const std::string dir = cmfilter_test::temp_dir("cmfilter-test-driver-sigma");
    const std::vector<float> constant(16, 0.5f);
    const std::string pyramid = bake_pyramid(dir, "constant", constant, 4, 4);
    auto flat = largest_driver_sigma(pyramid, {});
    REQUIRE_FALSE(flat);
    CHECK(flat.error().kind == ErrorKind::BadInput);
    CHECK(contains(flat.error().message, "holds no positive footprint sigma"));
}
