// SPDX-License-Identifier: Apache-2.0
// Texture drivers in the renderer (filtered_texture.h, scene_materials.h,
// render.h), on small synthetic drivers written to a scratch folder: level-0
// lookups read the texels where they are (t grows downwards) and repeat;
// where the footprint is tiny the moments' mean is the bilinear level-0 value
// and sigma vanishes; a constant driver gives C0 of the constant exactly; two
// references with different seeds agree; renders do not depend on the thread
// count; a moments file brings its driver back from cmfilter:source, and
// refuses it changed; with the driver gone, naive and gaussian render from
// the moments alone and the other methods name the missing file; clamp maps
// whose domain misses the texture are refused; the exact method on a driver
// with four values is the box mean of C0 over the texels and near the
// reference, and refuses a render without histograms and a driver with too
// many values; on a footprint made of aligned squares, the probes give the
// box mean of f, the squares' sigmas, and (exact, color-pyramid, segments)
// the box mean of C0; a segment pyramid baked for one map colours a map of
// other colours on its breakpoints exactly, and refuses other breakpoints
// and another driver.
#include "cmfilter/scene/camera.h"
#include "cmfilter/color/color_config.h"
#include "cmfilter/texture/moment_pyramid.h"
#include "cmfilter/texture/segment_pyramid_file.h"
#include "cmfilter/render/render.h"
#include "cmfilter/scene/scene_materials.h"
#include "cmfilter/scene/surface_hit.h"

#include "render_test_support.h"
#include "test_images.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

using namespace cmfilter;
namespace fs = std::filesystem;

namespace {

const double kTwoPi = 6.283185307179586;

std::string scratch(const std::string& name)
{
    return (fs::path(cmfilter_test::temp_dir("cmfilter-test-render-texture")) / name).string();
}

// A float32 single-channel driver image at `name` in the scratch folder.
std::string write_driver(const std::string& name, int w, int h, const std::vector<float>& values)
{
    const std::string path = scratch(name);
    cmfilter_test::write_image(path, w, h, 1, OIIO::TypeDesc::FLOAT, values.data());
    return path;
}

// A smooth driver, one period of a sine along x and of a cosine along y:
// neighbouring texels differ by at most about 0.0035.
std::vector<float> smooth_driver(int w, int h)
{
    std::vector<float> f(static_cast<std::size_t>(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            f[static_cast<std::size_t>(y) * w + x] = static_cast<float>(0.5 + 0.1 * std::sin(kTwoPi * (x + 0.5) / w) +
                                                                        0.1 * std::cos(kTwoPi * (y + 0.5) / h));
    return f;
}

// A ground plane under a terrain map over [domain_min, domain_max] driven by
// the driver image at `driver` (the renderer bakes its moments), seen from
// `position` towards `look_at`, with the light straight above (no ambient):
// lit pixels show the map's colour itself.
Scene texture_scene(const std::string& driver, const Vec3& position, const Vec3& look_at, const Vec3& up, double repeat,
                    int w, int h)
{
    Scene scene;
    scene.path = "texture-scene";
    scene.camera.position = position;
    scene.camera.look_at = look_at;
    scene.camera.up = up;
    scene.camera.fov_degrees = 30;
    scene.camera.width = w;
    scene.camera.height = h;
    scene.light.direction = {0, 1, 0};
    scene.light.radiance = {1, 1, 1};
    scene.background = {0.55, 0.65, 0.8};
    Surface plane;
    plane.mapping.u_axis = {1 / repeat, 0, 0};
    plane.mapping.v_axis = {0, 0, 1 / repeat};
    plane.material.colormap.image_path = std::string(CMFILTER_SOURCE_DIR) + "/luts/terrain.png";
    plane.material.colormap.domain_min = 0.2;
    plane.material.colormap.domain_max = 0.8;
    plane.material.driver.kind = DriverKind::Image;
    plane.material.driver.image_path = driver;
    scene.surfaces.push_back(plane);
    return scene;
}

// A material's texture driver, or null.
const TextureDriver* texture_driver(const Material& m) { return std::get_if<TextureDriver>(&m.driver); }

// Its filtered texture and histogram pyramid, or null.
const FilteredTexture* texture_of(const Material& m)
{
    const TextureDriver* d = texture_driver(m);
    return d ? &d->texture : nullptr;
}

const HistogramTexture* histograms_of(const Material& m)
{
    const TextureDriver* d = texture_driver(m);
    return d && d->histograms ? &*d->histograms : nullptr;
}

std::vector<Material> materials_of(const Scene& scene)
{
    auto config = ColorConfig::load("");
    REQUIRE(config);
    auto materials = prepare_materials(scene, *config, MaterialOptions{});
    if (!materials) FAIL(materials.error().message);
    return std::move(*materials);
}

// A moment pyramid of `driver` at `name` in the scratch folder.
std::string bake_moments(const std::string& driver, const std::string& name)
{
    MomentBakeOptions options;
    options.driver_path = driver;
    options.output_path = scratch(name);
    options.wrap = TextureWrap::Periodic;
    auto baked = bake_moment_pyramid(options);
    if (!baked) FAIL(baked.error().message);
    return options.output_path;
}

// The error prepare_materials gives for `scene`.
Error material_error(const Scene& scene)
{
    auto config = ColorConfig::load("");
    REQUIRE(config);
    auto materials = prepare_materials(scene, *config, MaterialOptions{});
    REQUIRE_FALSE(materials);
    return materials.error();
}

}  // namespace

TEST_CASE("texture values at texel centres are the texels, t grows downwards, and the texture repeats")
{
    const int w = 16, h = 8;
    std::vector<float> f(static_cast<std::size_t>(w) * h);
    for (std::size_t i = 0; i < f.size(); ++i) f[i] = static_cast<float>(i) / static_cast<float>(f.size());
    const Scene scene = texture_scene(write_driver("ramp.exr", w, h, f), {0, 1, 0}, {0, 0, 0}, {0, 0, 1}, 1, 4, 4);
    const std::vector<Material> materials = materials_of(scene);
    REQUIRE(texture_of(materials[0]));
    const FilteredTexture& texture = *texture_of(materials[0]);
    CHECK(materials[0].provenance.moments_baked);
    CHECK(texture.moments().info().wrap == TextureWrap::Periodic);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double u = (x + 0.5) / w, v = (y + 0.5) / h;
            CAPTURE(x);
            CAPTURE(y);
            CHECK(texture.value(u, v) == static_cast<double>(f[static_cast<std::size_t>(y) * w + x]));
            CHECK(texture.value(u + 3, v - 2) == doctest::Approx(texture.value(u, v)).epsilon(1e-12));
        }
    // Halfway between two texels of a row, and across the periodic seam.
    CHECK(texture.value(1.0 / w, 0.5 / h) == doctest::Approx(0.5 * (f[0] + f[1])));
    CHECK(texture.value(0.0, 0.5 / h) == doctest::Approx(0.5 * (f[0] + f[w - 1])));
    CHECK(texture.lod(4.0 / w) == doctest::Approx(2.0));
}

TEST_CASE("where the footprint is tiny the naive and gaussian mean is the bilinear level-0 value and sigma is about 0")
{
    // 256 x 256 texels over 20 scene units, seen from 1 unit above, straight
    // down and obliquely: about 0.2 texel per pixel.
    const int size = 256;
    const std::string driver = write_driver("smooth.exr", size, size, smooth_driver(size, size));
    for (const Vec3& look_at : {Vec3{0.3, 0, 0.2}, Vec3{0.6, 0, 0.8}}) {
        const Scene scene = texture_scene(driver, {0.3, 1, 0.2}, look_at, {0, 0, 1}, 20, 32, 24);
        const std::vector<Material> materials = materials_of(scene);
        const FilteredTexture& texture = *texture_of(materials[0]);
        auto camera = Camera::create(scene.camera);
        REQUIRE(camera);
        for (RenderMethod method : {RenderMethod::Naive, RenderMethod::Gaussian}) {
            RenderOptions options;
            options.method = method;
            auto image = render(scene, materials, options);
            REQUIRE(image);
            double worst_mean = 0, worst_sigma = 0, largest_lod = -1e9;
            for (int y = 0; y < image->height; ++y)
                for (int x = 0; x < image->width; ++x) {
                    const std::size_t p = static_cast<std::size_t>(y) * image->width + x;
                    const auto hit = intersect_scene(scene, camera->ray(x + 0.5, y + 0.5));
                    REQUIRE(hit);
                    REQUIRE(image->hit[p]);
                    const double expected = texture.value(hit->hit.u, hit->hit.v);
                    worst_mean = std::max(worst_mean, std::abs(image->mean[p] - expected));
                    worst_sigma = std::max(worst_sigma, static_cast<double>(image->sigma[p]));
                    largest_lod = std::max(largest_lod, static_cast<double>(image->lod[p]));
                }
            CAPTURE(to_string(method));
            CAPTURE(look_at);
            CHECK(worst_mean <= 1e-3);
            CHECK(worst_sigma <= 2e-3);
            CHECK(largest_lod < 0);  // less than a texel per pixel
        }
    }
}

TEST_CASE("the supersampled colour of a constant driver is C0 of the constant exactly")
{
    const float constant = 0.3f;
    const std::string driver = write_driver("constant.exr", 16, 16, std::vector<float>(256, constant));
    const Scene scene = texture_scene(driver, {0, 1, 0}, {0, 0, 0}, {0, 0, 1}, 2, 12, 8);
    const std::vector<Material> materials = materials_of(scene);
    // Straight above a plane facing it, with no ambient, the shade is the
    // albedo itself: 1 * C0 + 0.
    const Rgb c0 = materials[0].color.map.evaluate(constant);
    for (RenderMethod method : {RenderMethod::Supersample, RenderMethod::Reference, RenderMethod::Naive}) {
        for (int samples : {1, 16}) {
            RenderOptions options;
            options.method = method;
            options.samples = samples;
            options.seed = 4;
            auto image = render(scene, materials, options);
            REQUIRE(image);
            CAPTURE(to_string(method));
            CAPTURE(samples);
            for (std::size_t p = 0; p < image->hit.size(); ++p) {
                REQUIRE(image->hit[p]);
                CHECK(image->rgb[3 * p] == static_cast<float>(c0.r));
                CHECK(image->rgb[3 * p + 1] == static_cast<float>(c0.g));
                CHECK(image->rgb[3 * p + 2] == static_cast<float>(c0.b));
                CHECK(image->mean[p] == constant);
                CHECK(image->sigma[p] == 0.0f);
            }
        }
    }
}

TEST_CASE("two texture references with different seeds differ by at most 0.2 mean CIEDE2000")
{
    // The bundled driver on a ground plane to the horizon under the map of
    // examples/scenes/plane-image-terrain.json (its mean +- 2.78 sigma), 64
    // units a repeat: features of about a unit, as the fBm of test_render.cpp
    // has at this size (the scene's 8 units a repeat put hundreds of features
    // in each of these large pixels; the two references then differ by 0.4).
    Scene scene = texture_scene(std::string(CMFILTER_SOURCE_DIR) + "/examples/noise-driver.png", {0, 1.5, 0},
                                {0, 0.9, 10}, {0, 1, 0}, 64, 48, 27);
    scene.surfaces[0].material.colormap.domain_min = 0.002;
    scene.surfaces[0].material.colormap.domain_max = 0.998;
    const std::vector<Material> materials = materials_of(scene);
    RenderOptions options;
    options.method = RenderMethod::Reference;
    options.seed = 1;
    auto a = render(scene, materials, options);
    options.seed = 2;
    auto b = render(scene, materials, options);
    REQUIRE(a);
    REQUIRE(b);
    const ErrorSummary d = cmfilter_test::render_difference(*a, *b);
    CAPTURE(d.mean);
    CAPTURE(d.max);
    CHECK(d.mean <= 0.2);
    CHECK(d.mean > 0.0);
}

TEST_CASE("texture renders do not depend on the thread count")
{
    const Scene scene = texture_scene(std::string(CMFILTER_SOURCE_DIR) + "/examples/noise-driver.png", {0, 1.5, 0},
                                      {0, 0.9, 10}, {0, 1, 0}, 8, 40, 24);
    const std::vector<Material> materials = materials_of(scene);
    for (RenderMethod method : {RenderMethod::Naive, RenderMethod::Gaussian, RenderMethod::Supersample}) {
        RenderOptions options;
        options.method = method;
        options.samples = 5;
        options.threads = 1;
        auto one = render(scene, materials, options);
        options.threads = 2;
        auto two = render(scene, materials, options);
        REQUIRE(one);
        REQUIRE(two);
        CAPTURE(to_string(method));
        CHECK(one->rgb == two->rgb);
        CHECK(one->sigma == two->sigma);
        CHECK(one->lod == two->lod);
    }
}

TEST_CASE("a moments driver reads its texels from cmfilter:source, refuses a driver changed, and does without one gone")
{
    const int size = 32;
    const std::string driver = write_driver("source.exr", size, size, smooth_driver(size, size));
    const std::string moments = bake_moments(driver, "source-moments.exr");
    Scene scene = texture_scene(driver, {0, 1, 0}, {0, 0, 0}, {0, 0, 1}, 1, 8, 8);
    scene.surfaces[0].material.driver.kind = DriverKind::Moments;
    scene.surfaces[0].material.driver.moments_path = moments;

    SUBCASE("present: the same texels as the image itself")
    {
        const std::vector<Material> from_moments = materials_of(scene);
        REQUIRE(texture_of(from_moments[0]));
        CHECK_FALSE(from_moments[0].provenance.moments_baked);
        CHECK(from_moments[0].provenance.driver_path == driver);
        scene.surfaces[0].material.driver.kind = DriverKind::Image;
        const std::vector<Material> from_image = materials_of(scene);
        for (double u : {0.1, 0.37, 0.93})
            CHECK(texture_of(from_moments[0])->value(u, 0.4) == texture_of(from_image[0])->value(u, 0.4));
    }
    SUBCASE("gone: naive and gaussian render from the moments alone, the rest name the missing driver")
    {
        const std::string gone = write_driver("gone.exr", size, size, smooth_driver(size, size));
        scene.surfaces[0].material.driver.moments_path = bake_moments(gone, "gone-moments.exr");
        const std::vector<Material> with_source = materials_of(scene);
        fs::remove(gone);
        const std::vector<Material> without = materials_of(scene);
        REQUIRE(texture_of(without[0]));
        CHECK_FALSE(texture_of(without[0])->has_level0());
        CHECK(texture_of(with_source[0])->has_level0());
        const std::string named = "texture-scene: /surfaces/0/material/driver/moments: cannot read driver '" + gone +
                                  "' recorded in '" + scene.surfaces[0].material.driver.moments_path + "'";
        for (RenderMethod method : {RenderMethod::Naive, RenderMethod::Gaussian}) {
            RenderOptions options;
            options.method = method;
            auto a = render(scene, with_source, options);
            auto b = render(scene, without, options);
            REQUIRE(a);
            REQUIRE(b);
            CAPTURE(to_string(method));
            CHECK(a->rgb == b->rgb);  // level 0 plays no part in them
        }
        for (RenderMethod method : {RenderMethod::Supersample, RenderMethod::Reference}) {
            RenderOptions options;
            options.method = method;
            auto image = render(scene, without, options);
            REQUIRE_FALSE(image);
            CHECK(image.error().kind == ErrorKind::Io);
            CAPTURE(image.error().message);
            CHECK(image.error().message.rfind(named, 0) == 0);
            CHECK(image.error().message.find(std::string("; ") + to_string(method) + " reads the driver's texels") !=
                  std::string::npos);
        }
        auto config = ColorConfig::load("");
        REQUIRE(config);
        MaterialOptions exact;
        exact.histograms = true;
        auto histograms = prepare_materials(scene, *config, exact);
        REQUIRE_FALSE(histograms);
        CHECK(histograms.error().kind == ErrorKind::Io);
        CAPTURE(histograms.error().message);
        CHECK(histograms.error().message.rfind(named, 0) == 0);
        CHECK(histograms.error().message.find("exact bakes its histograms from the driver's texels") !=
              std::string::npos);
    }
    SUBCASE("changed")
    {
        const std::string changed = write_driver("changed.exr", size, size, smooth_driver(size, size));
        scene.surfaces[0].material.driver.moments_path = bake_moments(changed, "changed-moments.exr");
        write_driver("changed.exr", size, size, std::vector<float>(size * size, 0.5f));
        const Error e = material_error(scene);
        CHECK(e.kind == ErrorKind::BadInput);
        CAPTURE(e.message);
        CHECK(e.message.find("/surfaces/0/material/driver/moments: driver '" + changed + "' (sha256 ") !=
              std::string::npos);
        CHECK(e.message.find("re-bake the moments") != std::string::npos);
    }
}

TEST_CASE("a clamp colour map whose domain misses the texture's values is refused")
{
    const int size = 16;
    const std::string driver = write_driver("domain.exr", size, size, smooth_driver(size, size));
    Scene scene = texture_scene(driver, {0, 1, 0}, {0, 0, 0}, {0, 0, 1}, 1, 4, 4);
    scene.surfaces[0].material.colormap.domain_min = 5;
    scene.surfaces[0].material.colormap.domain_max = 6;
    const Error image = material_error(scene);
    CHECK(image.kind == ErrorKind::BadInput);
    CAPTURE(image.message);
    CHECK(image.message.find("/surfaces/0/material/colormap: the colour map's domain [5, 6] does not meet the "
                             "driver's values (min and max: [0.") != std::string::npos);
    scene.surfaces[0].material.driver.kind = DriverKind::Moments;
    scene.surfaces[0].material.driver.moments_path = bake_moments(driver, "domain-moments.exr");
    CHECK(material_error(scene).message == image.message);
    // A repeating map meets every value.
    scene.surfaces[0].material.colormap.wrap = WrapMode::Repeat;
    CHECK(materials_of(scene).size() == 1);
}

namespace {

// A driver with four distinct values in blocks of 4 x 4 texels, the blocks'
// values from a fixed hash: texel-scale detail that the pixels of a plane
// seen obliquely average over many blocks.
std::vector<float> quantised_driver(int w, int h)
{
    const float levels[4] = {0.3f, 0.45f, 0.6f, 0.75f};
    std::vector<float> f(static_cast<std::size_t>(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const unsigned bx = static_cast<unsigned>(x / 16), by = static_cast<unsigned>(y / 16);
            const unsigned k = (bx * 73856093u) ^ (by * 19349663u);
            f[static_cast<std::size_t>(y) * w + x] = levels[(k >> 3) % 4];
        }
    return f;
}

std::vector<Material> exact_materials_of(const Scene& scene)
{
    auto config = ColorConfig::load("");
    REQUIRE(config);
    MaterialOptions options;
    options.histograms = true;
    auto materials = prepare_materials(scene, *config, options);
    if (!materials) FAIL(materials.error().message);
    return std::move(*materials);
}

// The box mean of C0 over the 32 x 32 level-0 texels (of an n x n driver f,
// repeating) around the hit of pixel (x, y)'s centre ray: the pixels of the
// aligned straight-down scenes below, computed here.
Rgb aligned_box_mean(const Scene& scene, const Camera& camera, const ColorMap& map, const std::vector<float>& f, int n,
                     int x, int y)
{
    const auto hit = intersect_scene(scene, camera.ray(x + 0.5, y + 0.5));
    REQUIRE(hit);
    const long x0 = std::lround(hit->hit.u * n) - 16, y0 = std::lround(hit->hit.v * n) - 16;
    Rgb want;
    for (long j = 0; j < 32; ++j)
        for (long i = 0; i < 32; ++i) {
            const long tx = ((x0 + i) % n + n) % n, ty = ((y0 + j) % n + n) % n;
            want += (1.0 / 1024) * map.evaluate(f[static_cast<std::size_t>(ty * n + tx)]);
        }
    return want;
}

}  // namespace

TEST_CASE("exact on a driver with four values matches the reference within 0.5 mean CIEDE2000")
{
    // 512 x 512 texels a repeat seen straight down, 2 repeats over 32 x 32
    // pixels: each pixel is a box of 32 x 32 texels aligned with level 5 of
    // the pyramid, over 4 blocks of 16 x 16 texels. The reference's f is
    // bilinear in level 0, so half a texel each side of a block edge takes
    // values between the four (1/16 of the area); the histograms see
    // piecewise-constant texels: that is the 0.42 left.
    const int n = 512;
    const std::vector<float> f = quantised_driver(n, n);
    const double d = 1 / std::tan(kTwoPi / 24);  // fov 30 degrees: 2 units across
    const Scene scene =
        texture_scene(write_driver("quantised.exr", n, n, f), {0, d, 0}, {0, 0, 0}, {0, 0, 1}, 1, 32, 32);
    const std::vector<Material> materials = exact_materials_of(scene);
    REQUIRE(histograms_of(materials[0]));
    CHECK(histograms_of(materials[0])->bins() == 4);
    RenderOptions options;
    options.method = RenderMethod::Exact;
    auto exact = render(scene, materials, options);
    options.method = RenderMethod::Gaussian;
    auto gaussian = render(scene, materials, options);
    options.method = RenderMethod::Reference;
    options.seed = 1;
    auto reference = render(scene, materials, options);
    REQUIRE(exact);
    REQUIRE(gaussian);
    REQUIRE(reference);
    CHECK(exact->method == RenderMethod::Exact);
    CHECK(exact->samples == 1);
    const ErrorSummary e = cmfilter_test::render_difference(*exact, *reference);
    const ErrorSummary g = cmfilter_test::render_difference(*gaussian, *reference);
    MESSAGE("exact vs reference: mean " << e.mean << ", max " << e.max << "; gaussian: mean " << g.mean << ", max "
                                        << g.max);
    CHECK(e.mean <= 0.5);
    CHECK(g.mean > 5 * e.mean);

    // Against the box mean of C0 over each pixel's 32 x 32 piecewise-constant
    // texels, computed here: exact up to float32 weights.
    auto camera = Camera::create(scene.camera);
    REQUIRE(camera);
    double worst = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            const Rgb want = aligned_box_mean(scene, *camera, materials[0].color.map, f, n, x, y);
            const std::size_t p = static_cast<std::size_t>(y) * 32 + static_cast<std::size_t>(x);
            worst = std::max({worst, std::abs(exact->rgb[3 * p] - want.r), std::abs(exact->rgb[3 * p + 1] - want.g),
                              std::abs(exact->rgb[3 * p + 2] - want.b)});
        }
    MESSAGE("exact vs the box mean of C0 over the texels: largest difference " << worst);
    CHECK(worst < 1e-4);
}

TEST_CASE("mixture on a two-valued driver is the box mean of C0 over the footprint, and gaussian is not")
{
    // The 32 x 32-texel pixel boxes of the exact case above, over blocks of
    // two values: each pixel's four moments are those of two atoms, which
    // the mixture recovers (s = 0, math/moment_mixture.h), so only the
    // table's row sigma = 0 against C0 at the two values is left.
    const int n = 512;
    std::vector<float> f = quantised_driver(n, n);
    for (float& v : f) v = v < 0.5f ? 0.3f : 0.75f;
    const double d = 1 / std::tan(kTwoPi / 24);
    const Scene scene =
        texture_scene(write_driver("two-valued.exr", n, n, f), {0, d, 0}, {0, 0, 0}, {0, 0, 1}, 1, 32, 32);
    auto config = ColorConfig::load("");
    REQUIRE(config);
    MaterialOptions material_options;
    material_options.moment_order = 4;
    auto materials = prepare_materials(scene, *config, material_options);
    REQUIRE(materials);
    REQUIRE(texture_of((*materials)[0])->moments().info().order == 4);
    const ColorLayer& layer = (*materials)[0].color;
    double table_error = 0;
    for (double v : {0.3, 0.75}) {
        const Rgb t = layer.table.lookup(v, 0), c = layer.map.evaluate(v);
        table_error = std::max({table_error, std::abs(t.r - c.r), std::abs(t.g - c.g), std::abs(t.b - c.b)});
    }
    RenderOptions options;
    options.method = RenderMethod::Mixture;
    auto mixture = render(scene, *materials, options);
    options.method = RenderMethod::Gaussian;
    auto gaussian = render(scene, *materials, options);
    REQUIRE(mixture);
    REQUIRE(gaussian);
    auto camera = Camera::create(scene.camera);
    REQUIRE(camera);
    double worst_mixture = 0, worst_gaussian = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            const Rgb want = aligned_box_mean(scene, *camera, layer.map, f, n, x, y);
            const std::size_t p = static_cast<std::size_t>(y) * 32 + static_cast<std::size_t>(x);
            for (int c = 0; c < 3; ++c) {
                const double w = c == 0 ? want.r : c == 1 ? want.g : want.b;
                worst_mixture = std::max(worst_mixture, std::abs(mixture->rgb[3 * p + c] - w));
                worst_gaussian = std::max(worst_gaussian, std::abs(gaussian->rgb[3 * p + c] - w));
            }
        }
    MESSAGE("largest difference from the box mean of C0: mixture "
            << worst_mixture << " (table row 0 against C0: " << table_error << "), gaussian " << worst_gaussian);
    // float32 moments: 1e-5 beyond the table's own error.
    CHECK(worst_mixture <= table_error + 1e-5);
    CHECK(worst_gaussian > 0.02);

    // A pyramid of two moments cannot: refused, naming the surface.
    auto two = prepare_materials(scene, *config, MaterialOptions{});
    REQUIRE(two);
    options.method = RenderMethod::Mixture;
    auto refused = render(scene, *two, options);
    REQUIRE_FALSE(refused);
    CHECK(refused.error().kind == ErrorKind::BadInput);
    CHECK(refused.error().message.find("surface 0: mixture needs a moment pyramid of order 4") != std::string::npos);
}

TEST_CASE("mixture stays finite and within gaussian's error from straight down to the horizon")
{
    // Blocks of two values, the plane seen at elevations from 90 degrees to
    // 1 and along it (0: the horizon through the image's middle), 16 x 16
    // pixels: footprints from isotropic to as anisotropic as the probes go,
    // LODs up to the whole texture. Every pixel finite; against the
    // reference, the mixture's mean CIEDE2000 no more than the Gaussian's
    // plus 0.05 (two references of different seeds differ by up to 0.2 above,
    // on a smooth driver: a shared reference leaves a smaller share of noise
    // between two methods).
    const int n = 128;
    std::vector<float> f = quantised_driver(n, n);
    for (float& v : f) v = v < 0.5f ? 0.3f : 0.75f;
    const std::string driver = write_driver("two-valued-sweep.exr", n, n, f);
    auto config = ColorConfig::load("");
    REQUIRE(config);
    for (double elevation : {90.0, 30.0, 10.0, 3.0, 1.0, 0.0}) {
        CAPTURE(elevation);
        const double a = elevation * kTwoPi / 360;
        const Vec3 eye{0, 0.5 + 2 * std::sin(a), -2 * std::cos(a)};
        const Vec3 at = elevation == 90.0 ? Vec3{0, 0, 0} : Vec3{0, 0.5, 0};
        const Scene scene = texture_scene(driver, elevation == 90.0 ? Vec3{0, 2, 0} : eye, at,
                                          elevation == 90.0 ? Vec3{0, 0, 1} : Vec3{0, 1, 0}, 1, 16, 16);
        MaterialOptions material_options;
        material_options.moment_order = 4;
        auto materials = prepare_materials(scene, *config, material_options);
        REQUIRE(materials);
        cmfilter_test::check_mixture_within_gaussian(scene, *materials, 3, elevation);
    }
}

TEST_CASE("exact refuses a render without histograms, and a driver with too many values")
{
    const Scene scene = texture_scene(write_driver("quantised-small.exr", 16, 16, quantised_driver(16, 16)), {0, 1, 0},
                                      {0, 0, 0}, {0, 0, 1}, 1, 4, 4);
    RenderOptions options;
    options.method = RenderMethod::Exact;
    auto no_histograms = render(scene, materials_of(scene), options);
    REQUIRE_FALSE(no_histograms);
    CHECK(no_histograms.error().kind == ErrorKind::BadInput);
    CHECK(no_histograms.error().message.find("histogram pyramid") != std::string::npos);

    std::vector<float> many(32 * 32);
    for (std::size_t i = 0; i < many.size(); ++i) many[i] = 0.2f + 0.6f * static_cast<float>(i) / 1024.0f;
    const Scene too_many =
        texture_scene(write_driver("many-values.exr", 32, 32, many), {0, 1, 0}, {0, 0, 0}, {0, 0, 1}, 1, 4, 4);
    auto config = ColorConfig::load("");
    REQUIRE(config);
    MaterialOptions material_options;
    material_options.histograms = true;
    auto materials = prepare_materials(too_many, *config, material_options);
    REQUIRE_FALSE(materials);
    CHECK(materials.error().kind == ErrorKind::BadInput);
    CHECK(materials.error().message.find("/surfaces/0/material/driver/image: ") != std::string::npos);
    CHECK(materials.error().message.find("1024 distinct values") != std::string::npos);
}

namespace {

// A plane seen straight down, 32 x 32 pixels over 2 x 2 units, mapped with
// 512 x 512 texels a repeat but 1 repeat a unit along u and 1/4 along v:
// each pixel is a rectangle of 32 x 8 level-0 texels, its centre at
// u n = 16 (mod 32) and v n = 4 (mod 8). Cut into four probes along u, each
// a square of 8 x 8 texels (the rms width of a piece 8 texels long and 8
// wide), the pieces are level-3 texels, so each probe reads one texel there.
const int kStripN = 512, kStripPixels = 32;

Scene strip_scene(const std::string& driver)
{
    const double d = 1 / std::tan(kTwoPi / 24);  // fov 30 degrees: 2 units across
    Scene scene = texture_scene(driver, {0, d, 0}, {0, 0, 0}, {0, 0, 1}, 1, kStripPixels, kStripPixels);
    scene.surfaces[0].mapping.v_axis = {0, 0, 0.25};
    return scene;
}

// Brute force over a pixel's 32 x 8 texels (periodic): calls add(x, y) for
// each texel, its coordinates wrapped into the image.
template <typename F>
void for_footprint_texels(double u, double v, F add)
{
    const long x0 = std::lround(u * kStripN) - 16, y0 = std::lround(v * kStripN) - 4;
    for (long j = 0; j < 8; ++j)
        for (long i = 0; i < 32; ++i)
            add(((x0 + i) % kStripN + kStripN) % kStripN, ((y0 + j) % kStripN + kStripN) % kStripN);
}

}  // namespace

TEST_CASE("texture probes on a footprint of aligned squares give its box mean and the squares' mean sigma")
{
    const std::vector<float> f = smooth_driver(kStripN, kStripN);
    const Scene scene = strip_scene(write_driver("strip-smooth.exr", kStripN, kStripN, f));
    const std::vector<Material> materials = materials_of(scene);
    auto camera = Camera::create(scene.camera);
    REQUIRE(camera);
    RenderOptions options;
    options.method = RenderMethod::Naive;
    // A ratio of 4 (up to rounding, which may make it 4 + 1e-15 and ask for
    // five): four probes.
    options.max_probes = 4;
    auto image = render(scene, materials, options);
    REQUIRE(image);
    double worst_mean = 0, worst_sigma = 0, worst_lod = 0;
    for (int y = 0; y < kStripPixels; ++y)
        for (int x = 0; x < kStripPixels; ++x) {
            const auto hit = intersect_scene(scene, camera->ray(x + 0.5, y + 0.5));
            REQUIRE(hit);
            // The box mean of f over the 32 x 8 texels, and the mean of the
            // standard deviations of f over each 8 x 8 square.
            double sum = 0;
            double square_sum[4] = {0, 0, 0, 0}, square_sq[4] = {0, 0, 0, 0};
            int k = 0;
            for_footprint_texels(hit->hit.u, hit->hit.v, [&](long tx, long ty) {
                const double value = f[static_cast<std::size_t>(ty * kStripN + tx)];
                const int square = (k % 32) / 8;
                sum += value;
                square_sum[square] += value;
                square_sq[square] += value * value;
                ++k;
            });
            double sigma = 0;
            for (int s = 0; s < 4; ++s) {
                const double mean = square_sum[s] / 64;
                sigma += 0.25 * std::sqrt(std::max(0.0, square_sq[s] / 64 - mean * mean));
            }
            const std::size_t p = static_cast<std::size_t>(y) * kStripPixels + static_cast<std::size_t>(x);
            worst_mean = std::max(worst_mean, std::abs(image->mean[p] - sum / 256));
            worst_sigma = std::max(worst_sigma, std::abs(image->sigma[p] - sigma));
            worst_lod = std::max(worst_lod, std::abs(image->lod[p] - 3.0));
        }
    MESSAGE("largest differences: mean " << worst_mean << ", sigma " << worst_sigma << ", lod " << worst_lod);
    // float32 moments of values near 0.5 (relative 6e-8), and sigma from
    // m2 - m1^2 of float32 moments of f - c: a few 1e-6 at most.
    CHECK(worst_mean < 1e-5);
    CHECK(worst_sigma < 1e-4);
    CHECK(worst_lod < 1e-6);
}

TEST_CASE("exact follows an anisotropic footprint: the box mean of C0 over a footprint of aligned squares")
{
    const std::vector<float> f = quantised_driver(kStripN, kStripN);
    const Scene scene = strip_scene(write_driver("strip-quantised.exr", kStripN, kStripN, f));
    const std::vector<Material> materials = exact_materials_of(scene);
    auto camera = Camera::create(scene.camera);
    REQUIRE(camera);
    // Against the box mean of C0 over each pixel's 32 x 8 piecewise-constant
    // texels, computed here: exact up to float32 weights. One probe (an
    // isotropic lookup of the whole footprint's width) is far from it.
    RenderOptions options;
    options.method = RenderMethod::Exact;
    double worst[2] = {0, 0};
    for (int probes : {4, 1}) {  // four probes, as above; or one
        options.max_probes = probes;
        auto exact = render(scene, materials, options);
        REQUIRE(exact);
        double& w = worst[probes == 4 ? 0 : 1];
        for (int y = 0; y < kStripPixels; ++y)
            for (int x = 0; x < kStripPixels; ++x) {
                const auto hit = intersect_scene(scene, camera->ray(x + 0.5, y + 0.5));
                REQUIRE(hit);
                Rgb want;
                for_footprint_texels(hit->hit.u, hit->hit.v, [&](long tx, long ty) {
                    want += (1.0 / 256) *
                            materials[0].color.map.evaluate(f[static_cast<std::size_t>(ty * kStripN + tx)]);
                });
                const std::size_t p = static_cast<std::size_t>(y) * kStripPixels + static_cast<std::size_t>(x);
                w = std::max({w, std::abs(exact->rgb[3 * p] - want.r), std::abs(exact->rgb[3 * p + 1] - want.g),
                              std::abs(exact->rgb[3 * p + 2] - want.b)});
            }
    }
    MESSAGE("exact vs the box mean of C0 over the texels: largest difference " << worst[0] << " with probes, "
                                                                               << worst[1] << " with one");
    CHECK(worst[0] < 1e-4);
    CHECK(worst[1] > 1e-2);
}

TEST_CASE("color-pyramid is the box mean of C0 over a footprint of aligned squares, for a driver of any values")
{
    // The aligned straight-down scene of the exact case (each pixel a box of
    // 32 x 32 texels, level 5) and the anisotropic strip, with a driver of
    // many values through the same map.
    auto config = ColorConfig::load("");
    REQUIRE(config);
    const int n = 512;
    // Constant over blocks of 16 x 16 texels (as the exact case's), so that
    // a hit a little off a texel centre reads the same texels, but 1024
    // distinct values (no histogram pyramid can hold them).
    const auto block_driver = [](int size) {
        std::vector<float> v(static_cast<std::size_t>(size) * size);
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const unsigned k = static_cast<unsigned>(x / 16) * 73856093u ^
                                   static_cast<unsigned>(y / 16) * 19349663u;
                v[static_cast<std::size_t>(y) * size + x] = static_cast<float>((k >> 4) % 4096) / 4096.0f;
            }
        return v;
    };
    const std::vector<float> f = block_driver(n);
    const double d = 1 / std::tan(kTwoPi / 24);
    const Scene scene = texture_scene(write_driver("smooth.exr", n, n, f), {0, d, 0}, {0, 0, 0}, {0, 0, 1}, 1, 32, 32);
    auto materials = prepare_materials(scene, *config, MaterialOptions{});
    REQUIRE(materials);
    RenderOptions options;
    options.method = RenderMethod::ColorPyramid;
    auto pyramid = render(scene, *materials, options);
    options.method = RenderMethod::Gaussian;
    auto gaussian = render(scene, *materials, options);
    REQUIRE(pyramid);
    REQUIRE(gaussian);
    CHECK(pyramid->method == RenderMethod::ColorPyramid);
    auto camera = Camera::create(scene.camera);
    REQUIRE(camera);
    double worst = 0, worst_gaussian = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            const Rgb want = aligned_box_mean(scene, *camera, (*materials)[0].color.map, f, n, x, y);
            const std::size_t p = static_cast<std::size_t>(y) * 32 + static_cast<std::size_t>(x);
            for (int ch = 0; ch < 3; ++ch) {
                worst = std::max(worst, std::abs(pyramid->rgb[3 * p + ch] - want[ch]));
                worst_gaussian = std::max(worst_gaussian, std::abs(gaussian->rgb[3 * p + ch] - want[ch]));
            }
        }
    MESSAGE("color-pyramid vs the box mean of C0 over the texels: largest difference " << worst << " (gaussian "
                                                                                       << worst_gaussian << ")");
    CHECK(worst < 1e-4);
    CHECK(worst_gaussian > 1e-2);

    // The strip: four probes of 8 x 8 texels along the footprint.
    const std::vector<float> g = block_driver(kStripN);
    const Scene strip = strip_scene(write_driver("strip-smooth.exr", kStripN, kStripN, g));
    auto strip_materials = prepare_materials(strip, *config, MaterialOptions{});
    REQUIRE(strip_materials);
    auto strip_camera = Camera::create(strip.camera);
    REQUIRE(strip_camera);
    options.method = RenderMethod::ColorPyramid;
    options.max_probes = 4;
    auto along = render(strip, *strip_materials, options);
    REQUIRE(along);
    double strip_worst = 0;
    for (int y = 0; y < kStripPixels; ++y)
        for (int x = 0; x < kStripPixels; ++x) {
            const auto hit = intersect_scene(strip, strip_camera->ray(x + 0.5, y + 0.5));
            REQUIRE(hit);
            Rgb want;
            for_footprint_texels(hit->hit.u, hit->hit.v, [&](long tx, long ty) {
                want += (1.0 / 256) *
                        (*strip_materials)[0].color.map.evaluate(g[static_cast<std::size_t>(ty * kStripN + tx)]);
            });
            const std::size_t p = static_cast<std::size_t>(y) * kStripPixels + static_cast<std::size_t>(x);
            for (int ch = 0; ch < 3; ++ch)
                strip_worst = std::max(strip_worst, std::abs(along->rgb[3 * p + ch] - want[ch]));
        }
    CHECK(strip_worst < 1e-4);
}

TEST_CASE("segments is the box mean of C0 over aligned squares, and one pyramid baked for a map recolours another on "
          "its breakpoints")
{
    // The aligned straight-down scene of the colour-pyramid case, through
    // 8-texel maps: A, baked in process; B, other colours on the same
    // knots, reading a pyramid baked for A (driver/segments); C, 5 texels
    // (other knots), refused by that pyramid.
    auto config = ColorConfig::load("");
    REQUIRE(config);
    const int n = 512;
    std::vector<float> f(static_cast<std::size_t>(n) * n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const unsigned k = static_cast<unsigned>(x / 16) * 73856093u ^ static_cast<unsigned>(y / 16) * 19349663u;
            f[static_cast<std::size_t>(y) * n + x] = static_cast<float>((k >> 4) % 4096) / 4096.0f;
        }
    const auto write_map = [](const std::string& name, const std::vector<unsigned char>& rgb) {
        const std::string path = scratch(name);
        cmfilter_test::write_image(path, static_cast<int>(rgb.size() / 3), 1, 3, OIIO::TypeDesc::UINT8, rgb.data());
        return path;
    };
    const std::string map_a = write_map("segments-a.png", {10,  200, 30,  250, 240, 10,  0,   0,   0,   200, 20,  20,
                                                           255, 255, 255, 30,  60,  220, 120, 120, 120, 250, 130, 0});
    const std::string map_b = write_map("segments-b.png", {250, 10,  10,  0,   90, 40,  220, 220, 30, 5,   5,   5,
                                                           40,  200, 240, 255, 0,  255, 90,  40,  0,  200, 200, 200});
    const std::string map_c =
        write_map("segments-c.png", {10, 200, 30, 250, 240, 10, 0, 0, 0, 200, 20, 20, 255, 255, 255});
    const double d = 1 / std::tan(kTwoPi / 24);
    Scene scene = texture_scene(write_driver("segments.exr", n, n, f), {0, d, 0}, {0, 0, 0}, {0, 0, 1}, 1, 32, 32);
    scene.surfaces[0].material.colormap.domain_min = 0;
    scene.surfaces[0].material.colormap.domain_max = 1;
    scene.surfaces[0].material.colormap.image_path = map_a;
    auto camera = Camera::create(scene.camera);
    REQUIRE(camera);
    // The largest channel difference from the box mean of C0 over each
    // pixel's 32 x 32 texels.
    const auto worst_of = [&](const RenderedImage& image, const ColorMap& map) {
        double worst = 0;
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x) {
                const Rgb want = aligned_box_mean(scene, *camera, map, f, n, x, y);
                const std::size_t p = static_cast<std::size_t>(y) * 32 + static_cast<std::size_t>(x);
                for (int ch = 0; ch < 3; ++ch) worst = std::max(worst, std::abs(image.rgb[3 * p + ch] - want[ch]));
            }
        return worst;
    };
    RenderOptions options;
    options.method = RenderMethod::Segments;
    MaterialOptions baked_here;
    set_method_materials(options.method, baked_here);
    CHECK(baked_here.segments);
    auto a = prepare_materials(scene, *config, baked_here);
    REQUIRE(a);
    const TextureDriver* driver = texture_driver((*a)[0]);
    REQUIRE(driver);
    REQUIRE(driver->segments);
    CHECK(driver->segments->channels() <= 8);
    auto image_a = render(scene, *a, options);
    REQUIRE(image_a);
    CHECK(image_a->method == RenderMethod::Segments);
    const double worst_a = worst_of(*image_a, (*a)[0].color.map);
    MESSAGE("segments (map A, baked in process) vs the box mean of C0: largest difference " << worst_a);
    CHECK(worst_a < 1e-4);

    // One pyramid for A, periodic as scene textures are, read for B.
    SegmentPyramidBakeOptions bake;
    bake.driver_path = scene.surfaces[0].material.driver.image_path;
    bake.wrap = TextureWrap::Periodic;
    bake.maps = {&(*a)[0].color.map};
    bake.map_sources = {map_a};
    bake.output_path = scratch("segments-a-pyramid.exr");
    REQUIRE(bake_segment_pyramid(bake));
    scene.surfaces[0].material.colormap.image_path = map_b;
    scene.surfaces[0].material.driver.segments_path = bake.output_path;
    auto b = prepare_materials(scene, *config, MaterialOptions{});
    REQUIRE(b);
    REQUIRE(texture_driver((*b)[0])->segments);
    CHECK(texture_driver((*b)[0])->segments->path() == bake.output_path);
    auto image_b = render(scene, *b, options);
    REQUIRE(image_b);
    const double worst_b = worst_of(*image_b, (*b)[0].color.map);
    options.method = RenderMethod::Gaussian;
    auto gaussian_b = render(scene, *b, options);
    REQUIRE(gaussian_b);
    const double worst_gaussian = worst_of(*gaussian_b, (*b)[0].color.map);
    MESSAGE("segments (map B through A's pyramid): largest difference " << worst_b << " (gaussian " << worst_gaussian
                                                                        << ")");
    CHECK(worst_b < 1e-4);
    CHECK(worst_gaussian > 1e-2);

    // Other knots, and a pyramid of another driver, are refused by name.
    scene.surfaces[0].material.colormap.image_path = map_c;
    auto c = prepare_materials(scene, *config, MaterialOptions{});
    REQUIRE_FALSE(c);
    CHECK(c.error().message.find("/surfaces/0/material/driver/segments") != std::string::npos);
    CHECK(c.error().message.find(bake.output_path) != std::string::npos);
    scene.surfaces[0].material.colormap.image_path = map_b;
    std::vector<float> g = f;
    g[0] = 0.5f;
    scene.surfaces[0].material.driver.image_path = write_driver("segments-other.exr", n, n, g);
    auto other = prepare_materials(scene, *config, MaterialOptions{});
    REQUIRE_FALSE(other);
    CHECK(other.error().message.find("(expected the texture's own driver)") != std::string::npos);
}
