// SPDX-License-Identifier: Apache-2.0
// The shaders of shaders/ run for real: each kernel of shaders/kernels/ is
// compiled by the OpenGL implementation at hand (Mesa's llvmpipe in CI,
// through EGL without a display), fed the library's own artefacts (a colour
// table, a moment pyramid and a noise sigma table baked and written to files,
// then read back and uploaded as a renderer would), and its results are
// compared with the library's lookups at random points and at the edges:
// sigma 0, sigma_max and beyond, values at and beyond the domain, levels of
// detail below 0 and beyond the pyramid, NaN. The tolerances are the
// measured float32 rounding of each path (docs/shaders.md).
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include "artefact_textures.h"
#include "headless_gl.h"
#include "patch_map_support.h"

#include "cmfilter/colormap/color_map_loading.h"
#include "cmfilter/colormap/slope_color_map_loading.h"
#include "cmfilter/io/image_reading.h"
#include "cmfilter/microsurface/height_filtered_albedo.h"
#include "cmfilter/microsurface/height_filtering.h"
#include "cmfilter/microsurface/height_moment_table.h"
#include "cmfilter/microsurface/slope_color.h"
#include "cmfilter/microsurface/smith_lambda.h"
#include "cmfilter/math/gauss_hermite.h"
#include "cmfilter/math/normal_distribution.h"
#include "cmfilter/noise/noise_sigma_bake.h"
#include "cmfilter/noise/noise_sigma_table_file.h"
#include "cmfilter/noise/noise_spec.h"
#include "cmfilter/stack/linear_fit.h"
#include "cmfilter/synthesis/coordinate_lookup.h"
#include "cmfilter/synthesis/sample_box_sums.h"
#include "cmfilter/synthesis/sample_image_pyramid.h"
#include "cmfilter/tables/gaussian_color_table_file.h"
#include "cmfilter/texture/color_pyramid_file.h"
#include "cmfilter/texture/color_pyramid_texture.h"
#include "cmfilter/colormap/map_breakpoints.h"
#include "cmfilter/texture/segment_pyramid_file.h"
#include "cmfilter/texture/segment_pyramid_texture.h"
#include "cmfilter/texture/moment_pyramid.h"
#include "cmfilter/texture/moment_texture.h"
#include "cmfilter/util/temporary_file.h"

#include <doctest/doctest.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <random>

using namespace cmfilter;
using namespace cmfilter_gl;

namespace {

const std::string kSource = CMFILTER_SOURCE_DIR;
const std::string kShaders = kSource + "/shaders";
constexpr float kNan = std::numeric_limits<float>::quiet_NaN();

GlContext& gl()
{
    static GlContext context;
    static bool said = false;
    if (!said) {
        MESSAGE("OpenGL renderer: " << context.renderer());
        said = true;
    }
    return context;
}

GLuint kernel(const std::string& name)
{
    gl();
    return build_program({{GL_COMPUTE_SHADER, expand_includes(kShaders + "/kernels/" + name + ".comp", kShaders)}});
}

// The largest |gpu - reference| over a check, and where.
struct Tally {
    double max_error = 0;
    std::string where;
    void add(double gpu, double reference, const std::string& what)
    {
        const double e = std::isnan(reference) ? (std::isnan(gpu) ? 0.0 : INFINITY) : std::fabs(gpu - reference);
        if (!(e <= max_error)) {
            max_error = e;
            where = what + ": gpu " + std::to_string(gpu) + ", library " + std::to_string(reference);
        }
    }
};

std::string point_name(const float* p, int n)
{
    std::string s = "(";
    for (int i = 0; i < n; ++i) s += (i ? ", " : "") + std::to_string(p[i]);
    return s + ")";
}

double as_float(double x) { return static_cast<double>(static_cast<float>(x)); }

double channel(const Rgb& c, int ch) { return ch == 0 ? c.r : ch == 1 ? c.g : c.b; }

// ---------------------------------------------------------------------------
// Colour tables (eq. 10) and the colour map C0.

struct BakedTable {
    LoadedColorMap map;
    LoadedGaussianColorTable table;
    ImageData pixels;  // the table file's pixels as a renderer reads them
};

BakedTable bake_table(const std::string& lut, WrapMode wrap, SigmaSpacing spacing, double vmin, double vmax)
{
    ColorMapLoadOptions load;
    load.path = kSource + "/luts/" + lut;
    load.vmin = vmin;
    load.vmax = vmax;
    load.wrap = wrap;
    auto config = ColorConfig::load("");
    REQUIRE(config);
    auto map = load_color_map(load, *config);
    REQUIRE(map);
    GaussianColorTableOptions options;
    options.values = 96;
    options.sigmas = 40;
    options.spacing = spacing;
    options.threads = 1;
    auto table = GaussianColorTable::bake(map->map, options);
    REQUIRE(table);
    auto file = TemporaryFile::create("shader-table", ".exr");
    REQUIRE(file);
    GaussianColorTableInfo info;
    info.source = map->provenance;
    REQUIRE(write_gaussian_color_table(file->path(), *table, info));
    auto loaded = read_gaussian_color_table(file->path());
    REQUIRE(loaded);
    auto pixels = read_image(file->path());
    REQUIRE(pixels);
    REQUIRE(pixels->channels == 3);
    return {std::move(*map), std::move(*loaded), std::move(*pixels)};
}

void check_color_table(const std::string& lut, WrapMode wrap, SigmaSpacing spacing)
{
    const double vmin = -1.0, vmax = 2.0;
    const BakedTable baked = bake_table(lut, wrap, spacing, vmin, vmax);
    const GaussianColorTable& table = baked.table.table;
    const TableAxes& ax = table.axes();
    const ColorMap& map = baked.map.map;

    const GLuint program = kernel("cmfilter_color_table");
    const GLuint table_texture =
        float_texture(0, {{baked.pixels.width, baked.pixels.height, baked.pixels.pixels.data()}}, 3,
                      color_map_wrap(wrap == WrapMode::Repeat ? WrapMode::Repeat : WrapMode::Clamp), GL_CLAMP_TO_EDGE,
                      GL_LINEAR, GL_LINEAR);
    std::vector<float> map_texels;
    for (const Rgb& c : map.texels)
        for (double v : {c.r, c.g, c.b}) map_texels.push_back(static_cast<float>(v));
    const GLuint map_texture = float_texture(1, {{static_cast<int>(map.texels.size()), 1, map_texels.data()}}, 3,
                                             color_map_wrap(wrap), GL_CLAMP_TO_EDGE, GL_LINEAR, GL_LINEAR);

    // Points: (mean, sigma, colour map value, unused).
    std::vector<float> points;
    const double range = vmax - vmin, smax = ax.sigma_max;
    const double reach = wrap == WrapMode::Clamp ? 3 * range : 3 * range;  // beyond the domain by up to 3 periods
    std::mt19937_64 rng(20260214);
    std::uniform_real_distribution<double> mean(vmin - reach, vmax + reach), sigma(0, 1.25 * smax), unit(0, 1);
    for (int k = 0; k < 4000; ++k)
        points.insert(points.end(), {static_cast<float>(k % 2 ? vmin + range * unit(rng) : mean(rng)),
                                     static_cast<float>(k % 3 ? sigma(rng) : smax * unit(rng) * unit(rng) * 0.05),
                                     static_cast<float>(mean(rng)), 0.0f});
    const double edge_means[] = {
        vmin,         vmax,         ax.value_first(),   ax.value_last(), vmin - 0.5 * range,        vmax + 0.5 * range,
        vmin - range, vmax + range, vmin + 0.5 * range, ax.value_at(1),  ax.value_at(ax.values - 1)};
    const double edge_sigmas[] = {0.0, -1.0, smax, 1.5 * smax, 1e6, ax.sigma_at(1), ax.sigma_at(ax.sigmas - 2)};
    for (double m : edge_means)
        for (double s : edge_sigmas)
            points.insert(points.end(), {static_cast<float>(m), static_cast<float>(s), static_cast<float>(m), 0.0f});
    points.insert(points.end(), {kNan, 0.1f, kNan, 0.0f});
    points.insert(points.end(), {0.5f, kNan, 0.5f, 0.0f});
    if (wrap == WrapMode::Clamp) {
        points.insert(points.end(), {1e30f, 0.1f, 1e30f, 0.0f});
        points.insert(points.end(), {-INFINITY, 0.1f, -INFINITY, 0.0f});
    } else {
        points.insert(points.end(), {INFINITY, 0.1f, 0.5f, 0.0f});
    }

    const std::size_t count = points.size() / 4;
    struct {
        ColorTableBlock table;
        std::int32_t count;
    } parameters{color_table_block(ax), static_cast<std::int32_t>(count)};
    const std::vector<float> result = run_kernel(program, points, count, count * 16, &parameters, sizeof parameters);

    Tally exact, sampler, map_exact, map_sampler;
    for (std::size_t k = 0; k < count; ++k) {
        const float* p = &points[4 * k];
        const Rgb t = table.lookup(p[0], p[1]);  // the float inputs the shader saw
        const Rgb c = map.evaluate(p[2]);
        const float* r = &result[16 * k];
        const std::string where = point_name(p, 3);
        for (int ch = 0; ch < 3; ++ch) {
            const double tv = channel(t, ch);
            const double cv = channel(c, ch);
            exact.add(r[ch], tv, where);
            if (!std::isnan(p[0]) && !std::isnan(p[1]) && std::isfinite(p[0])) sampler.add(r[4 + ch], tv, where);
            if (std::isfinite(p[2])) {
                map_exact.add(r[8 + ch], cv, where);
                map_sampler.add(r[12 + ch], cv, where);
            }
        }
    }
    glDeleteTextures(1, &table_texture);
    glDeleteTextures(1, &map_texture);
    glDeleteProgram(program);
    MESSAGE(lut << " " << std::string(to_string(wrap)) << " " << std::string(to_string(spacing)) << ", " << count
                << " points: T exact " << exact.max_error << ", T sampler " << sampler.max_error << ", C0 exact "
                << map_exact.max_error << ", C0 sampler " << map_sampler.max_error);
    // texelFetch and the shader's own interpolation: float32 rounding of
    // the node coordinate (1.2e-7 of it: 1e-4 of a texel at 3 periods
    // beyond a 256-texel map's domain) times the largest step between nodes.
    CHECK_MESSAGE(exact.max_error <= 1e-4, exact.where);
    CHECK_MESSAGE(map_exact.max_error <= 1e-4, map_exact.where);
    // The sampler's bilinear filter: llvmpipe filters float textures with
    // float weights, as close as texelFetch (measured 7.5e-6). GPUs with
    // 8-bit filter weights are not (docs/shaders.md).
    CHECK_MESSAGE(sampler.max_error <= 1e-4, sampler.where);
    CHECK_MESSAGE(map_sampler.max_error <= 1e-4, map_sampler.where);
}

}  // namespace

TEST_CASE("color_table: T(v, sigma) of eq. 10 and the colour map C0, clamp, mirror, repeat, linear and sqrt sigma")
{
    check_color_table("terrain.png", WrapMode::Clamp, SigmaSpacing::Sqrt);
    check_color_table("stripes.png", WrapMode::Mirror, SigmaSpacing::Linear);
    check_color_table("hue-ramp.png", WrapMode::Repeat, SigmaSpacing::Sqrt);
    check_color_table("step.png", WrapMode::Clamp, SigmaSpacing::Linear);
}

// ---------------------------------------------------------------------------
// Moment pyramids (sec. 4.2).

namespace {

// A 40 x 40 float driver far from 0 (the moments are stored about the
// driver's mean): a smooth wave plus a hashed texel noise, written as EXR.
std::string write_driver(const TemporaryFile& file)
{
    const int w = 40, h = 40;
    std::vector<float> texels(static_cast<std::size_t>(w) * h);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> noise(-0.25, 0.25);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            texels[static_cast<std::size_t>(y) * w + x] =
                static_cast<float>(100.0 + std::sin(0.4 * x) * std::cos(0.23 * y) + noise(rng));
    auto out = OIIO::ImageOutput::create(file.path());
    REQUIRE(out);
    OIIO::ImageSpec spec(w, h, 1, OIIO::TypeDesc::FLOAT);
    REQUIRE(out->open(file.path(), spec));
    REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, texels.data()));
    REQUIRE(out->close());
    return file.path();
}

// Points over a pyramid of `levels` levels with a level 0 `size` texels
// wide: (s, t, lod, footprint side for textureGrad). Random ones, at integer
// levels (bilinear within one level) and fractional ones, then the edges:
// texel centres and edges of level 0, the corners, LOD beyond the pyramid
// and below 0, NaN LOD.
std::vector<float> pyramid_points(std::uint64_t seed, int levels, double size)
{
    std::vector<float> points;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> st(-0.3, 1.3), lod(-1.0, levels + 1.0), unit(0, 1);
    for (int k = 0; k < 3000; ++k) {
        const double l = k % 2 ? std::round(lod(rng)) : lod(rng);
        const double side = std::exp2(std::clamp(std::round(lod(rng)), 0.0, levels - 1.0)) / size;
        points.insert(points.end(),
                      {static_cast<float>(k % 3 ? unit(rng) : st(rng)), static_cast<float>(k % 3 ? unit(rng) : st(rng)),
                       static_cast<float>(l), static_cast<float>(side)});
    }
    for (double s : {0.0, 0.5 / size, 0.5, 1.0 - 0.5 / size, 1.0})
        for (double l : {-3.0, 0.0, 1.0, levels - 1.0, levels + 4.0})
            points.insert(points.end(), {static_cast<float>(s), static_cast<float>(1.0 - s), static_cast<float>(l),
                                         static_cast<float>(1.0 / size)});
    points.insert(points.end(), {0.3f, 0.6f, kNan, static_cast<float>(1.0 / size)});
    return points;
}

void check_moments(TextureWrap wrap)
{
    auto driver = TemporaryFile::create("shader-driver", ".exr");
    auto pyramid = TemporaryFile::create("shader-moments", ".exr");
    REQUIRE(driver);
    REQUIRE(pyramid);
    MomentBakeOptions bake;
    bake.driver_path = write_driver(*driver);
    bake.output_path = pyramid->path();
    bake.wrap = wrap;
    bake.threads = 1;
    auto baked = bake_moment_pyramid(bake);
    REQUIRE(baked);
    auto texture = MomentTexture::open(pyramid->path());
    REQUIRE(texture);
    const MomentPyramidInfo& info = texture->info();
    REQUIRE(texture->reachable_levels() == info.levels);

    // The levels as a renderer reads them: MIP level k of subimage 0.
    const MomentLevels levels = read_moment_levels(pyramid->path());
    REQUIRE(static_cast<int>(levels.levels.size()) == info.levels);
    const GLenum gl_wrap = wrap == TextureWrap::Periodic ? GL_REPEAT
                           : wrap == TextureWrap::Black  ? GL_CLAMP_TO_BORDER
                                                         : GL_CLAMP_TO_EDGE;
    const GLuint program = kernel("cmfilter_moments");
    const GLuint tex = float_texture(0, levels.levels, 2, gl_wrap, gl_wrap, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);

    const double size = info.width;
    const std::vector<float> points = pyramid_points(11, info.levels, size);

    const std::size_t count = points.size() / 4;
    struct {
        float reference;
        std::int32_t levels, count;
    } parameters{static_cast<float>(info.reference), info.levels, static_cast<std::int32_t>(count)};
    const std::vector<float> result = run_kernel(program, points, count, count * 8, &parameters, sizeof parameters);

    Tally mean, sigma, grad_mean, grad_sigma;
    for (std::size_t k = 0; k < count; ++k) {
        const float* p = &points[4 * k];
        const std::string where = point_name(p, 4);
        const MomentSample s = texture->lookup(p[0], p[1], p[2]);
        mean.add(result[8 * k], s.mean, where);
        sigma.add(result[8 * k + 2], s.sigma, where);
        // textureGrad with the footprint side w: the level log2(w size).
        const MomentSample g = texture->lookup(p[0], p[1], static_cast<float>(std::log2(p[3] * size)));
        grad_mean.add(result[8 * k + 4], g.mean, where);
        grad_sigma.add(result[8 * k + 6], g.sigma, where);
    }
    glDeleteTextures(1, &tex);
    glDeleteProgram(program);
    MESSAGE("moments, wrap " << std::string(to_string(wrap)) << ", " << count << " points: mean " << mean.max_error
                             << ", sigma " << sigma.max_error << "; textureGrad mean " << grad_mean.max_error
                             << ", sigma " << grad_sigma.max_error);
    // Against OpenImageIO's TextureSystem: float32 rounding of the mean
    // c + m1 about 100 (its spacing there is 7.6e-6) and of the moments
    // (measured 3.2e-5 at worst, the sigma through textureGrad).
    CHECK_MESSAGE(mean.max_error <= 1e-4, mean.where);
    CHECK_MESSAGE(sigma.max_error <= 1e-4, sigma.where);
    CHECK_MESSAGE(grad_mean.max_error <= 1e-4, grad_mean.where);
    CHECK_MESSAGE(grad_sigma.max_error <= 1e-4, grad_sigma.where);
}

}  // namespace

TEST_CASE("moments: the moment pyramid's mean and sigma at a level of detail, clamp, periodic, black")
{
    check_moments(TextureWrap::Clamp);
    check_moments(TextureWrap::Periodic);
    check_moments(TextureWrap::Black);
}

// ---------------------------------------------------------------------------
// Colour pyramids (bake-moments --method color-pyramid).

namespace {

void check_color_pyramid(TextureWrap wrap)
{
    auto driver = TemporaryFile::create("shader-driver", ".exr");
    auto pyramid = TemporaryFile::create("shader-color-pyramid", ".exr");
    REQUIRE(driver);
    REQUIRE(pyramid);
    // A hard-edged map over the driver's values (about 99 to 101).
    ColorMap map;
    map.vmin = 99;
    map.vmax = 101;
    map.texels = {{0.02, 0.05, 0.4}, {0.9, 0.1, 0.05}, {0.1, 0.8, 0.2}, {2.5, 2.2, 0.3}, {0.0, 0.0, 0.0}};
    ColorPyramidBakeOptions bake;
    bake.driver_path = write_driver(*driver);
    bake.output_path = pyramid->path();
    bake.wrap = wrap;
    bake.map = &map;
    bake.threads = 1;
    REQUIRE(bake_color_pyramid(bake));
    auto texture = ColorPyramidTexture::open(pyramid->path());
    REQUIRE(texture);
    const ColorPyramidInfo& info = texture->info();
    const MomentLevels levels = read_pyramid_levels(pyramid->path(), 3);
    REQUIRE(static_cast<int>(levels.levels.size()) == info.levels);
    const GLenum gl_wrap = wrap == TextureWrap::Periodic ? GL_REPEAT
                           : wrap == TextureWrap::Black  ? GL_CLAMP_TO_BORDER
                                                         : GL_CLAMP_TO_EDGE;
    const GLuint program = kernel("cmfilter_color_pyramid");
    const GLuint tex = float_texture(0, levels.levels, 3, gl_wrap, gl_wrap, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);

    const double size = info.width;
    const std::vector<float> points = pyramid_points(13, info.levels, size);

    const std::size_t count = points.size() / 4;
    struct {
        std::int32_t levels, count;
    } parameters{info.levels, static_cast<std::int32_t>(count)};
    const std::vector<float> result = run_kernel(program, points, count, count * 8, &parameters, sizeof parameters);

    Tally colour, grad;
    for (std::size_t k = 0; k < count; ++k) {
        const float* p = &points[4 * k];
        const std::string where = point_name(p, 4);
        const ColorPyramidSample c = texture->lookup(p[0], p[1], p[2]);
        const ColorPyramidSample g = texture->lookup(p[0], p[1], static_cast<float>(std::log2(p[3] * size)));
        for (int ch = 0; ch < 3; ++ch) {
            colour.add(result[8 * k + ch], c.color[ch], where);
            grad.add(result[8 * k + 4 + ch], g.color[ch], where);
        }
    }
    glDeleteTextures(1, &tex);
    glDeleteProgram(program);
    MESSAGE("color_pyramid, wrap " << std::string(to_string(wrap)) << ", " << count << " points: colour "
                                   << colour.max_error << "; textureGrad " << grad.max_error);
    // Against OpenImageIO's TextureSystem: float32 rounding of colours up to
    // 2.5 in both filters (measured 3.3e-6 at worst, periodic), while a
    // level off by one or means of means differ by 1e-2 and more.
    CHECK_MESSAGE(colour.max_error <= 1e-4, colour.where);
    CHECK_MESSAGE(grad.max_error <= 1e-4, grad.where);
}

}  // namespace

TEST_CASE("color_pyramid: the colour pyramid's filtered colour at a level of detail, clamp, periodic, black")
{
    check_color_pyramid(TextureWrap::Clamp);
    check_color_pyramid(TextureWrap::Periodic);
    check_color_pyramid(TextureWrap::Black);
}

// ---------------------------------------------------------------------------
// Segment pyramids (bake-moments --segments), recoloured in the shader.

namespace {

void check_segments(TextureWrap wrap)
{
    auto driver = TemporaryFile::create("shader-driver", ".exr");
    auto pyramid = TemporaryFile::create("shader-segments", ".exr");
    REQUIRE(driver);
    REQUIRE(pyramid);
    // Baked for a hard-edged periodic map over the driver's values (about
    // 98.7 to 101.3): a breakpoint at every knot and at both ends, more than
    // four channels (two layers at least); applied with other colours on the
    // same breakpoints.
    ColorMap baked_map;
    baked_map.vmin = 99;
    baked_map.vmax = 101;
    baked_map.texels = {{0.02, 0.05, 0.4}, {0.9, 0.1, 0.05}, {0.1, 0.8, 0.2}, {2.5, 2.2, 0.3}, {0.0, 0.0, 0.0}};
    baked_map.wrap = WrapMode::Repeat;
    ColorMap recoloured = baked_map;
    for (Rgb& c : recoloured.texels) c = {c.b + 0.1, 0.5 * c.r, c.g * c.g};
    SegmentPyramidBakeOptions bake;
    bake.driver_path = write_driver(*driver);
    bake.output_path = pyramid->path();
    bake.wrap = wrap;
    bake.maps = {&baked_map};
    bake.threads = 1;
    REQUIRE(bake_segment_pyramid(bake));
    auto texture = SegmentPyramidTexture::open(pyramid->path());
    REQUIRE(texture);
    const SegmentPyramidInfo& info = texture->info();
    const int K = info.channels();
    REQUIRE(K > 4);
    REQUIRE(K <= 16);
    REQUIRE(check_segment_pyramid_map(info, pyramid->path(), recoloured, "the recoloured map"));
    // The levels as a renderer uploads them: four channels a layer.
    const MomentLevels levels = read_pyramid_levels(pyramid->path(), K);
    const int layer_count = (K + 3) / 4;
    std::vector<std::vector<std::vector<float>>> layer_texels(layer_count);
    std::vector<std::vector<TextureLevel>> layers(layer_count);
    for (int j = 0; j < layer_count; ++j)
        for (std::size_t k = 0; k < levels.levels.size(); ++k) {
            const TextureLevel& l = levels.levels[k];
            const std::size_t n = static_cast<std::size_t>(l.width) * l.height;
            std::vector<float> t(n * 4, 0.0f);
            for (std::size_t p = 0; p < n; ++p)
                for (int c = 0; c < 4 && 4 * j + c < K; ++c) t[4 * p + c] = levels.texels[k][p * K + 4 * j + c];
            layer_texels[j].push_back(std::move(t));
        }
    for (int j = 0; j < layer_count; ++j)
        for (std::size_t k = 0; k < levels.levels.size(); ++k)
            layers[j].push_back({levels.levels[k].width, levels.levels[k].height, layer_texels[j][k].data()});
    const GLenum gl_wrap = wrap == TextureWrap::Periodic ? GL_REPEAT
                           : wrap == TextureWrap::Black  ? GL_CLAMP_TO_BORDER
                                                         : GL_CLAMP_TO_EDGE;
    const GLuint program = kernel("cmfilter_segments");
    const GLuint tex = float_texture_array(0, layers, gl_wrap, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);

    const double size = info.width;
    const std::vector<float> points = pyramid_points(17, info.levels, size);
    const std::size_t count = points.size() / 4;
    struct {
        std::int32_t levels, channels, count, unused;
        float colors[17][4];
    } parameters{info.levels, K, static_cast<std::int32_t>(count), 0, {}};
    for (int k = 0; k <= K; ++k) {
        const Rgb c = recoloured.evaluate(info.breakpoints[k]);
        parameters.colors[k][0] = static_cast<float>(c.r);
        parameters.colors[k][1] = static_cast<float>(c.g);
        parameters.colors[k][2] = static_cast<float>(c.b);
    }
    const std::vector<float> result = run_kernel(program, points, count, count * 8, &parameters, sizeof parameters);

    const std::vector<Rgb> steps = ramp_colors(recoloured, info.breakpoints, info.weights());
    std::vector<float> ramps(K);
    Tally colour, grad;
    for (std::size_t k = 0; k < count; ++k) {
        const float* p = &points[4 * k];
        const std::string where = point_name(p, 4);
        texture->lookup(p[0], p[1], p[2], ramps.data());
        const Rgb c = ramp_color(steps, ramps.data());
        texture->lookup(p[0], p[1], static_cast<float>(std::log2(p[3] * size)), ramps.data());
        const Rgb g = ramp_color(steps, ramps.data());
        for (int ch = 0; ch < 3; ++ch) {
            colour.add(result[8 * k + ch], c[ch], where);
            grad.add(result[8 * k + 4 + ch], g[ch], where);
        }
    }
    glDeleteTextures(1, &tex);
    glDeleteProgram(program);
    MESSAGE("segments, wrap " << std::string(to_string(wrap)) << ", " << K << " channels, " << count
                              << " points: colour " << colour.max_error << "; textureGrad " << grad.max_error);
    // Against OpenImageIO's TextureSystem and ramp_color: float32 rounding
    // of the ramp means times steps up to 2.5, while a level off by one or a
    // channel in the wrong layer differs by 1e-2 and more.
    CHECK_MESSAGE(colour.max_error <= 1e-4, colour.where);
    CHECK_MESSAGE(grad.max_error <= 1e-4, grad.where);
}

}  // namespace

TEST_CASE("segments: the segment pyramid recoloured in the shader at a level of detail, clamp, periodic, black")
{
    check_segments(TextureWrap::Clamp);
    check_segments(TextureWrap::Periodic);
    check_segments(TextureWrap::Black);
}

// ---------------------------------------------------------------------------
// Noise sigma tables (sec. 4.2).

TEST_CASE("noise_sigma: sigma(L) of a baked noise sigma table, box and Gaussian footprints")
{
    auto spec = parse_noise_spec("fbm:base=gradient,octaves=3,seed=5");
    REQUIRE(spec);
    auto noise = make_noise(*spec);
    REQUIRE(noise);
    NoiseSigmaBakeOptions options;
    options.lod_step = 0.5;
    options.samples_per_footprint = 16;
    options.initial_footprints = 64;
    options.max_footprints = 64;
    options.global_samples = 4096;
    options.threads = 1;
    auto bake = bake_noise_sigma(*noise, options);
    REQUIRE(bake);
    auto file = TemporaryFile::create("shader-noise-sigma", ".exr");
    REQUIRE(file);
    REQUIRE(write_noise_sigma_table(file->path(), *bake, to_string(*spec), noise->base_period()));
    auto box = read_noise_sigma_table(file->path(), FootprintShape::Box);
    auto gaussian = read_noise_sigma_table(file->path(), FootprintShape::Gaussian);
    REQUIRE(box);
    REQUIRE(gaussian);
    auto pixels = read_image(file->path());
    REQUIRE(pixels);
    REQUIRE(pixels->channels == 4);
    // OpenEXR keeps channels sorted by name: pick them by name, as a
    // renderer must, into (box_sigma, gaussian_sigma).
    const auto channel = [&](const std::string& name) {
        const auto at = std::find(pixels->channel_names.begin(), pixels->channel_names.end(), name);
        REQUIRE(at != pixels->channel_names.end());
        return static_cast<int>(at - pixels->channel_names.begin());
    };
    const int box_channel = channel("box_sigma"), gaussian_channel = channel("gaussian_sigma");
    std::vector<float> texels;
    for (int i = 0; i < pixels->width; ++i)
        texels.insert(texels.end(), {pixels->pixels[static_cast<std::size_t>(4 * i + box_channel)],
                                     pixels->pixels[static_cast<std::size_t>(4 * i + gaussian_channel)]});
    const NoiseSigmaTable& table = box->table;
    const int lods = static_cast<int>(table.sigmas().size());

    const GLuint program = kernel("cmfilter_noise_sigma");
    const GLuint tex = float_texture(0, {{pixels->width, 1, texels.data()}}, 2, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE,
                                     GL_LINEAR, GL_LINEAR);
    std::vector<float> points;
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> lod(table.lod_first() - 2, table.lod_last() + 2);
    for (int k = 0; k < 2000; ++k) {
        const double l = lod(rng);
        points.insert(points.end(), {static_cast<float>(l), static_cast<float>(std::exp2(l) * box->base_period), 0, 0});
    }
    for (int k = 0; k < lods; ++k) {
        const double l = table.lod_first() + k * table.lod_step();
        points.insert(points.end(), {static_cast<float>(l), 1.0f, 0, 0});
    }
    for (double l : {table.lod_first() - 100, table.lod_last() + 100, table.lod_last(), table.lod_first()})
        points.insert(points.end(), {static_cast<float>(l), 1.0f, 0, 0});
    points.insert(points.end(), {kNan, 1.0f, 0, 0});
    const std::size_t count = points.size() / 4;
    struct {
        float lod_first, lod_step, base_period;
        std::int32_t lods, count;
    } parameters{static_cast<float>(table.lod_first()), static_cast<float>(table.lod_step()),
                 static_cast<float>(box->base_period), lods, static_cast<std::int32_t>(count)};
    const std::vector<float> result = run_kernel(program, points, count, count * 8, &parameters, sizeof parameters);
    Tally sampler, exact, lod_of_width;
    for (std::size_t k = 0; k < count; ++k) {
        const float* p = &points[4 * k];
        const std::string where = point_name(p, 1);
        const double b = table.sigma_at(p[0]), g = gaussian->table.sigma_at(p[0]);
        sampler.add(result[8 * k], b, where);
        sampler.add(result[8 * k + 1], g, where);
        exact.add(result[8 * k + 2], b, where);
        exact.add(result[8 * k + 3], g, where);
        lod_of_width.add(result[8 * k + 4], std::log2(p[1] / box->base_period), where);
    }
    glDeleteTextures(1, &tex);
    glDeleteProgram(program);
    const double global = bake->global.sigma;
    MESSAGE("noise sigma, " << lods << " LODs, global sigma " << global << ", " << count << " points: exact "
                            << exact.max_error << ", sampler " << sampler.max_error << ", LOD of a width "
                            << lod_of_width.max_error);
    CHECK_MESSAGE(exact.max_error <= 1e-6 * std::max(1.0, global), exact.where);
    CHECK_MESSAGE(sampler.max_error <= 1e-6 * std::max(1.0, global), sampler.where);
    CHECK_MESSAGE(lod_of_width.max_error <= 1e-5, lod_of_width.where);
}

// ---------------------------------------------------------------------------
// Height filtering (sec. 5.1).

TEST_CASE("height: Lambda, visibility, D_h's moments by the fit and the table, the height colour")
{
    auto moments = HeightMomentTable::create();
    REQUIRE(moments);
    std::vector<float> nodes;
    for (std::size_t i = 0; i < moments->node_means().size(); ++i)
        nodes.insert(nodes.end(),
                     {static_cast<float>(moments->node_means()[i]), static_cast<float>(moments->node_sigmas()[i])});
    const BakedTable baked = bake_table("sand-snow.png", WrapMode::Clamp, SigmaSpacing::Sqrt, -0.024, 0.024);
    const GaussianColorTable& table = baked.table.table;

    const GLuint program = kernel("cmfilter_height");
    const GLuint moment_tex = float_texture(0, {{static_cast<int>(nodes.size() / 2), 1, nodes.data()}}, 2,
                                            GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE, GL_NEAREST, GL_NEAREST);
    const GLuint table_tex = float_texture(1, {{baked.pixels.width, baked.pixels.height, baked.pixels.pixels.data()}},
                                           3, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE, GL_LINEAR, GL_LINEAR);
    const double half_pi = 1.57079632679489661923;
    std::vector<float> points;
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> theta(0, half_pi), sigma_s(0.02, 1.0), phi(-7, 7), h(-0.03, 0.03),
        unit(0, 1);
    auto add = [&](double to, double ti, double ss, double dphi, double height, double sh, double lambda, double L) {
        points.insert(points.end(), {static_cast<float>(to), static_cast<float>(ti), static_cast<float>(ss),
                                     static_cast<float>(dphi), static_cast<float>(height), static_cast<float>(sh),
                                     static_cast<float>(lambda), static_cast<float>(L)});
    };
    for (int k = 0; k < 3000; ++k)
        add(theta(rng), k % 4 ? theta(rng) : half_pi * (1 - 1e-3 * unit(rng)), sigma_s(rng), phi(rng), h(rng),
            0.002 + 0.01 * unit(rng), std::exp(8 * unit(rng) - 4), std::expm1(16 * unit(rng)));
    // Edges: head-on, grazing, 90 degrees; a flat surface; L = 0, at and
    // beyond the table's end (1e6), infinite; heights far in both tails.
    for (double to : {0.0, 1e-4, half_pi - 1e-4, half_pi})
        for (double ti : {0.0, half_pi - 1e-3, half_pi})
            for (double L : {0.0, 1e-6, 1e6, 1e9, static_cast<double>(INFINITY)}) {
                add(to, ti, 0.3, 0.0, 0.0, 0.008, 1.0, L);
                add(to, ti, 0.0, 3.14159, -0.04, 0.008, static_cast<double>(INFINITY), L);
            }
    add(0.5, 0.7, 0.3, 1.0, 0.06, 0.008, 50.0, 2.0);
    add(0.5, 0.7, 0.3, 1.0, -0.06, 0.008, 50.0, 2.0);

    const std::size_t count = points.size() / 8;
    struct {
        ColorTableBlock table;
        float s_max;
        std::int32_t count;
    } parameters{color_table_block(table.axes()), static_cast<float>(moments->s_max()),
                 static_cast<std::int32_t>(count)};
    const std::vector<float> r = run_kernel(program, points, count, count * 16, &parameters, sizeof parameters);

    Tally lambda, sum, visibility, height_visibility, log_cdf, fit, table_moments, colour;
    // Lambda spans decades: compared relative to max(1, Lambda).
    auto relative = [](Tally& t, double gpu, double ref, const std::string& where) {
        if (std::isinf(ref) || std::isinf(gpu)) {
            t.add(std::isinf(gpu) == std::isinf(ref) ? 0.0 : 1.0, 0.0, where);
            return;
        }
        t.add(gpu / std::max(1.0, std::fabs(ref)), ref / std::max(1.0, std::fabs(ref)), where);
    };
    for (std::size_t k = 0; k < count; ++k) {
        const float* p = &points[8 * k];
        const float* o = &r[16 * k];
        const std::string where = point_name(p, 8);
        const double lo = smith_lambda_gaussian(p[0], p[2]), li = smith_lambda_gaussian(p[1], p[2]);
        relative(lambda, o[0], lo, where);
        relative(lambda, o[1], li, where);
        relative(sum, o[2], lambda_sum(lo, li, p[3], MaskingShadowing::Uncorrelated), where);
        relative(sum, o[3], lambda_sum(lo, li, p[3], MaskingShadowing::DirectionCorrelated), where);
        visibility.add(o[4], mean_visibility(lo, li, p[3], MaskingShadowing::Uncorrelated), where);
        visibility.add(o[5], mean_visibility(lo, li, p[3], MaskingShadowing::DirectionCorrelated), where);
        const double v = resolved_visibility(p[4], p[5], p[6]);
        height_visibility.add(o[6], v, where);
        relative(log_cdf, o[7], log_normal_cdf(static_cast<double>(p[4] / p[5])), where);
        const HeightMoments f = paper_height_fit(p[7], p[5]), m = moments->lookup(p[7], p[5]);
        fit.add(o[8] / p[5], f.mean / p[5], where);  // in units of sigma_h
        fit.add(o[9] / p[5], f.sigma / p[5], where);
        table_moments.add(o[10] / p[5], m.mean / p[5], where);
        table_moments.add(o[11] / p[5], m.sigma / p[5], where);
        // The colour from the shader's own moments (their float rounding is
        // table_moments' error, not the colour's).
        const Rgb c = table.lookup(p[4] + o[10], o[11]);
        colour.add(o[12], v * c.r, where);
        colour.add(o[13], v * c.g, where);
        colour.add(o[14], v * c.b, where);
    }
    glDeleteTextures(1, &moment_tex);
    glDeleteTextures(1, &table_tex);
    glDeleteProgram(program);
    MESSAGE("height, " << count << " points: Lambda " << lambda.max_error << ", Lambda sums " << sum.max_error
                       << ", V (eq. 13) " << visibility.max_error << ", eq. 2 " << height_visibility.max_error
                       << ", ln Phi " << log_cdf.max_error << ", fit (sigma_h) " << fit.max_error
                       << ", table (sigma_h) " << table_moments.max_error << ", colour " << colour.max_error);
    CHECK_MESSAGE(lambda.max_error <= 1e-5, lambda.where);
    CHECK_MESSAGE(sum.max_error <= 1e-5, sum.where);
    CHECK_MESSAGE(visibility.max_error <= 1e-5, visibility.where);
    CHECK_MESSAGE(height_visibility.max_error <= 1e-5, height_visibility.where);
    CHECK_MESSAGE(log_cdf.max_error <= 1e-5, log_cdf.where);
    CHECK_MESSAGE(fit.max_error <= 1e-5, fit.where);
    CHECK_MESSAGE(table_moments.max_error <= 1e-5, table_moments.where);
    CHECK_MESSAGE(colour.max_error <= 1e-5, colour.where);
}

// ---------------------------------------------------------------------------
// Relighting linear fits (PTM, HSH).

TEST_CASE("relight: PTM-RGB, PTM-LRGB, HSH2 and HSH3 fits at lights over the hemisphere")
{
    const GLuint program = kernel("cmfilter_relight");
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> coefficient(-1, 1), unit(0, 1);
    for (LinearModel model : {LinearModel::PtmRgb, LinearModel::PtmLrgb, LinearModel::Hsh2, LinearModel::Hsh3}) {
        LinearFit fit;
        fit.model = model;
        fit.width = 7;
        fit.height = 5;
        fit.channels = 3;
        fit.coefficients.resize(fit.texels() * static_cast<std::size_t>(fit.stride()));
        for (float& c : fit.coefficients) c = static_cast<float>(coefficient(rng));
        // One layer a coefficient.
        const int stride = fit.stride();
        std::vector<float> layers(fit.coefficients.size());
        for (std::size_t t = 0; t < fit.texels(); ++t)
            for (int j = 0; j < stride; ++j) layers[j * fit.texels() + t] = fit.texel(t)[j];
        GLuint tex = 0;
        glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &tex);
        glTextureStorage3D(tex, 1, GL_R32F, fit.width, fit.height, stride);
        glTextureSubImage3D(tex, 0, 0, 0, 0, fit.width, fit.height, stride, GL_RED, GL_FLOAT, layers.data());
        glBindTextureUnit(0, tex);

        std::vector<Vec3> lights = {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}, {0.6, 0.8, 0}, {-0.6, 0, 0.8}};
        for (int k = 0; k < 200; ++k) {
            const double z = unit(rng), a = 6.283185307179586 * unit(rng), s = std::sqrt(1 - z * z);
            lights.push_back({s * std::cos(a), s * std::sin(a), z});
        }
        std::vector<float> points;
        std::vector<Vec3> used;  // the float lights the shader sees
        for (const Vec3& l : lights)
            for (std::size_t t = 0; t < fit.texels(); t += 3) {
                points.insert(points.end(), {static_cast<float>(l.x), static_cast<float>(l.y), static_cast<float>(l.z),
                                             static_cast<float>(t)});
                used.push_back({as_float(l.x), as_float(l.y), as_float(l.z)});
            }
        const std::size_t count = points.size() / 4;
        const std::int32_t parameters[4] = {static_cast<std::int32_t>(model), fit.channels, fit.width,
                                            static_cast<std::int32_t>(count)};
        const std::vector<float> r = run_kernel(program, points, count, count * 4, &parameters, sizeof parameters);
        Tally error;
        for (std::size_t k = 0; k < count; ++k) {
            const auto t = static_cast<std::size_t>(points[4 * k + 3]);
            const std::vector<float> reference = relight(fit, used[k], 1);
            for (int c = 0; c < 3; ++c) error.add(r[4 * k + c], reference[t * 3 + c], point_name(&points[4 * k], 4));
        }
        glDeleteTextures(1, &tex);
        MESSAGE("relight " << std::string(to_string(model)) << ", " << count << " points: " << error.max_error);
        // Sums of up to 9 unit terms in float32.
        CHECK_MESSAGE(error.max_error <= 1e-5, error.where);
    }
    glDeleteProgram(program);
}

// ---------------------------------------------------------------------------
// Coordinate maps (synthesis).

namespace {

// Levels stacked downwards from row 0, as wide as the first
// (shaders/cmfilter_coordinate_map.glsl): `values` per texel of each level,
// level k given as (width, height, texels).
struct StackedLevels {
    int width = 0, height = 0;
    std::vector<float> texels;
};

template <typename Level>
StackedLevels stack_levels(const std::vector<Level>& levels, int values,
                           const std::function<float(const Level&, std::size_t)>& value)
{
    StackedLevels out;
    out.width = levels.front().width;
    for (const Level& level : levels) out.height += level.height;
    out.texels.assign(static_cast<std::size_t>(out.width) * out.height * values, 0.0f);
    int row = 0;
    for (const Level& level : levels) {
        for (int y = 0; y < level.height; ++y)
            for (std::size_t k = 0; k < static_cast<std::size_t>(level.width) * values; ++k)
                out.texels[(static_cast<std::size_t>(row + y) * out.width) * values + k] =
                    value(level, static_cast<std::size_t>(y) * level.width * values + k);
        row += level.height;
    }
    return out;
}

void check_coordinate_map(GLuint program, CoordinateMap map, const SampleImage& sample, int patches,
                          std::mt19937_64& rng)
{
    // Hierarchical levels 1 and 2 into the sample's pyramid levels, random
    // (what render_at_lod reads of them is the texel each names).
    const std::vector<SampleImage> pyramid = sample_image_pyramid(sample);
    for (int l = 1; l <= 2; ++l) {
        CoordinateLevel level;
        level.width = (map.width() + (1 << l) - 1) >> l;
        level.height = (map.height() + (1 << l) - 1) >> l;
        level.sample_width = pyramid[l].width;
        level.sample_height = pyramid[l].height;
        std::uniform_int_distribution<int> x(0, level.sample_width - 1), y(0, level.sample_height - 1);
        for (std::size_t t = 0; t < level.texels(); ++t) level.coords.insert(level.coords.end(), {x(rng), y(rng)});
        map.levels.push_back(level);
    }
    const int top = static_cast<int>(std::ceil(std::log2(std::max(map.width(), map.height()))));
    REQUIRE(top >= 3);
    std::vector<PatchLevel> patch_levels;
    for (int l = 1; l <= top; ++l) {
        auto level = build_patch_level(map, l, patches, sample.periodic, 1);
        REQUIRE(level);
        patch_levels.push_back(std::move(*level));
    }

    // The uploads.
    const StackedLevels coords = stack_levels<CoordinateLevel>(
        map.levels, 2, [](const CoordinateLevel& l, std::size_t k) { return static_cast<float>(l.coords[k]); });
    std::vector<std::int32_t> coord_texels(coords.texels.begin(), coords.texels.end());
    GLuint map_tex = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &map_tex);
    glTextureStorage2D(map_tex, 1, GL_RG32I, coords.width, coords.height);
    glTextureSubImage2D(map_tex, 0, 0, 0, coords.width, coords.height, GL_RG_INTEGER, GL_INT, coord_texels.data());
    glTextureParameteri(map_tex, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(map_tex, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTextureUnit(0, map_tex);
    const StackedLevels samples = stack_levels<SampleImage>(
        pyramid, sample.channels, [](const SampleImage& l, std::size_t k) { return l.pixels[k]; });
    const GLuint sample_tex = float_texture(1, {{samples.width, samples.height, samples.texels.data()}},
                                            sample.channels, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE, GL_NEAREST,
                                            GL_NEAREST);
    // One layer an entry k of every footprint.
    std::vector<std::vector<float>> layers;
    for (int k = 0; k < patches; ++k) {
        layers.push_back(stack_levels<PatchLevel>(patch_levels, 3, [k](const PatchLevel& l, std::size_t i) {
                             return l.entry(i / 3, k)[i % 3];
                         }).texels);
    }
    GLuint patch_tex = 0;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &patch_tex);
    const int patch_width = patch_levels.front().width;
    const int patch_height = static_cast<int>(layers.front().size() / (3 * patch_width));
    glTextureStorage3D(patch_tex, 1, GL_RGB32F, patch_width, patch_height, patches);
    for (int k = 0; k < patches; ++k)
        glTextureSubImage3D(patch_tex, 0, 0, 0, k, patch_width, patch_height, 1, GL_RGB, GL_FLOAT, layers[k].data());
    glTextureParameteri(patch_tex, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(patch_tex, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTextureUnit(2, patch_tex);
    const SampleBoxSums sums(sample);
    const std::vector<float> sum_texels(sums.table().begin(), sums.table().end());
    const GLuint sums_tex = float_texture(3, {{sample.width + 1, sample.height + 1, sum_texels.data()}},
                                          sample.channels, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE, GL_NEAREST, GL_NEAREST);

    // Every output texel at L = -1 .. top + 2.
    const int first_lod = -1, last_lod = top + 2;
    std::vector<float> points;
    for (int lod = first_lod; lod <= last_lod; ++lod) {
        const int l = std::max(lod, 0);
        for (int j = 0; j < (map.height() + (1 << l) - 1) >> l; ++j)
            for (int i = 0; i < (map.width() + (1 << l) - 1) >> l; ++i)
                points.insert(points.end(), {static_cast<float>(i), static_cast<float>(j), static_cast<float>(lod), 0});
    }
    const std::size_t count = points.size() / 4;
    auto full = render_through_map(map, sample, 1);
    REQUIRE(full);
    struct {
        float sample_mean[4], output_mean[4];
        std::int32_t patches, levels, padding[2];  // CmfPatchLevels is 16-aligned (std430)
        std::int32_t width, height, map_levels, sample_width, sample_height, sample_periodic;
        std::int32_t count;
    } parameters{{},
                 {},
                 patches,
                 top,
                 {},
                 map.width(),
                 map.height(),
                 static_cast<std::int32_t>(map.levels.size()),
                 sample.width,
                 sample.height,
                 sample.periodic ? 1 : 0,
                 static_cast<std::int32_t>(count)};
    for (int c = 0; c < sample.channels; ++c) {
        double sum = 0;
        for (std::size_t t = 0; t < full->pixels.size() / sample.channels; ++t)
            sum += full->pixels[t * sample.channels + c];
        parameters.sample_mean[c] = static_cast<float>(sums.means()[c]);
        parameters.output_mean[c] =
            static_cast<float>(sum / static_cast<double>(full->pixels.size() / sample.channels));
    }
    const std::vector<float> r = run_kernel(program, points, count, count * 16, &parameters, sizeof parameters);

    // The library at each L (L < 0 as 0; `levels` only where the map has the level).
    std::map<std::pair<int, LodMethod>, OutputImage> reference;
    const auto library = [&](int lod, LodMethod method) -> const OutputImage& {
        auto found = reference.find({lod, method});
        if (found != reference.end()) return found->second;
        LodOptions options;
        options.lod = lod;
        options.method = method;
        options.patches = patches;
        options.threads = 1;
        auto out = render_at_lod(map, sample, options);
        REQUIRE(out);
        return reference.emplace(std::make_pair(lod, method), std::move(*out)).first->second;
    };
    Tally at_full, levels, point, patched;
    const int c = sample.channels;
    for (std::size_t k = 0; k < count; ++k) {
        const float* p = &points[4 * k];
        const int i = static_cast<int>(p[0]), j = static_cast<int>(p[1]), lod = std::max(static_cast<int>(p[2]), 0);
        const std::string where = point_name(p, 3);
        const float* o = &r[16 * k];
        for (int ch = 0; ch < c; ++ch) {
            if (lod == 0)
                at_full.add(o[ch], full->pixels[(static_cast<std::size_t>(j) * full->width + i) * c + ch], where);
            const auto at = [&](const OutputImage& out) {
                return out.pixels[(static_cast<std::size_t>(j) * out.width + i) * c + ch];
            };
            if (lod < static_cast<int>(map.levels.size()))
                levels.add(o[4 + ch], at(library(lod, LodMethod::Levels)), where);
            point.add(o[8 + ch], at(library(lod, LodMethod::Point)), where);
            patched.add(o[12 + ch], at(library(lod, LodMethod::Patches)), where);
        }
    }
    glDeleteTextures(1, &map_tex);
    glDeleteTextures(1, &sample_tex);
    glDeleteTextures(1, &patch_tex);
    glDeleteTextures(1, &sums_tex);
    MESSAGE("coordinate map " << map.width() << " x " << map.height() << " into " << sample.width << " x "
                              << sample.height << std::string(sample.periodic ? " periodic" : " clamped") << ", "
                              << patches << " patches, L " << first_lod << " .. " << last_lod << ", " << count
                              << " texels: full size " << at_full.max_error << ", levels " << levels.max_error
                              << ", point " << point.max_error << ", patches " << patched.max_error);
    // Texel copies: bit for bit.
    CHECK_MESSAGE(at_full.max_error == 0.0, at_full.where);
    CHECK_MESSAGE(levels.max_error == 0.0, levels.where);
    // A bilinear read (float coordinates and lerps) and float sums.
    CHECK_MESSAGE(point.max_error <= 1e-6, point.where);
    CHECK_MESSAGE(patched.max_error <= 1e-5, patched.where);
}

}  // namespace

TEST_CASE("coordinate_map: rendering through a coordinate map at full size and at every level of detail")
{
    const GLuint program = kernel("cmfilter_coordinate_map");
    std::mt19937_64 rng(13);
    // Every texel its own piece (footprints of more pieces than kept),
    // into a sample that clamps.
    const SampleImage sample = cmfilter_test::procedural_sample(11, 9, 4, false);
    CoordinateMap scattered = cmfilter_test::empty_map(23, 17, sample.width, sample.height, false);
    std::uniform_int_distribution<int> x(0, sample.width - 1), y(0, sample.height - 1);
    std::vector<std::int32_t>& coords = scattered.levels[0].coords;
    for (std::size_t k = 0; k < coords.size(); k += 2) {
        coords[k] = x(rng);
        coords[k + 1] = y(rng);
    }
    check_coordinate_map(program, scattered, sample, 2, rng);
    // Rectangular pieces, as k-coherence synthesis copies them, into a
    // periodic sample and one that clamps.
    for (bool periodic : {true, false}) {
        const SampleImage image = cmfilter_test::procedural_sample(11, 9, 4, periodic);
        check_coordinate_map(program, cmfilter_test::random_patch_map(23, 17, 11, 9, 2, 6, periodic, 5), image, 3, rng);
    }
    glDeleteProgram(program);
}

// ---------------------------------------------------------------------------
// Slope filtering (sec. 5.2).

TEST_CASE("slope: D_s's exact moments (eq. 20) and the Gaussian slope colour of a steepness and a slope-vector map")
{
    auto config = ColorConfig::load("");
    REQUIRE(config);
    ColorMapLoadOptions load;
    load.path = kSource + "/luts/grass-rock.png";
    load.vmin = 0;
    load.vmax = 90;
    auto loaded = load_color_map(load, *config);
    REQUIRE(loaded);
    const SteepnessColorMap map{loaded->map};
    SlopeVectorColorMapLoadOptions vector_load;
    vector_load.path = kSource + "/luts/slope-wheel.png";
    vector_load.s_max = 1.0;
    auto vector_loaded = load_slope_vector_color_map(vector_load, *config);
    REQUIRE(vector_loaded);
    const SlopeVectorColorMap& vector_map = vector_loaded->map;
    const GLuint program = kernel("cmfilter_slope");
    const auto texels_of = [](const std::vector<Rgb>& colours) {
        std::vector<float> texels;
        for (const Rgb& c : colours)
            for (double v : {c.r, c.g, c.b}) texels.push_back(static_cast<float>(v));
        return texels;
    };
    const std::vector<float> texels = texels_of(map.by_angle.texels);
    const GLuint tex = float_texture(0, {{static_cast<int>(map.by_angle.texels.size()), 1, texels.data()}}, 3,
                                     GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE, GL_LINEAR, GL_LINEAR);
    const std::vector<float> vector_texels = texels_of(vector_map.texels);
    const GLuint vector_tex = float_texture(1, {{vector_map.width, vector_map.height, vector_texels.data()}}, 3,
                                            GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE, GL_LINEAR, GL_LINEAR);
    const GaussianSlopeColorOptions options;  // render's 12 points per axis
    const GaussHermiteRule rule = gauss_hermite_rule(options.points_per_axis);

    const double half_pi = 1.57079632679489661923, s_max = vector_map.s_max;
    std::vector<float> points;
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> theta(0, half_pi), phi(-4, 4), mean(-0.6, 0.6), spread(0, 0.8), unit(-1, 1);
    // A point: the slopes N(m, Sigma), the view, and a slope at which the
    // slope-vector map is read alone.
    auto add = [&](double mx, double my, double t, double p, double sx, double sy, double rho, double lx, double ly) {
        points.insert(points.end(),
                      {static_cast<float>(mx), static_cast<float>(my), static_cast<float>(t), static_cast<float>(p),
                       static_cast<float>(sx * sx), static_cast<float>(rho * sx * sy), static_cast<float>(sy * sy),
                       0.0f, static_cast<float>(lx), static_cast<float>(ly), 0.0f, 0.0f});
    };
    for (int k = 0; k < 1500; ++k) {
        const double reach = k % 2 ? s_max : 3 * s_max;  // half within the map's domain, half up to 3 s_max
        add(k % 3 ? mean(rng) : 0.0, k % 3 ? mean(rng) : 0.0, theta(rng), phi(rng), spread(rng), spread(rng),
            0.95 * unit(rng), reach * unit(rng), reach * unit(rng));
    }
    // Edges: head-on, grazing, 90 degrees; no spread (every facet facing
    // away, or all facing); a steep mean slope beyond the horizon (k < -3);
    // sigma 0 and a spread of 5 s_max, means beyond the vector map's domain.
    const double texel = 2 * s_max / vector_map.width;
    for (double t : {0.0, 1.2, half_pi - 1e-3, half_pi}) {
        add(0, 0, t, 0.3, 0.3, 0.3, 0, 0, 0);
        add(0.2, -0.1, t, 0.3, 0, 0, 0, s_max, -s_max);
        add(4.0, 0, t, 0.0, 0.3, 0.2, 0.5, -s_max + 0.5 * texel, s_max - 0.5 * texel);
        add(-0.3, 0.5, t, 2.0, 0.4, 0.0, 0, -s_max + 1.5 * texel, 0.25 * texel);
        add(-s_max + 0.5 * texel, s_max - 2.5 * texel, t, 0.0, 0, 0, 0, 1e30, -1e30);
        add(2.5 * s_max, -1.5 * s_max, t, 0.7, 0, 0, 0, -1e30, 1e30);
        add(0.0, 0.0, t, -1.0, 5 * s_max, 5 * s_max, 0.5, 3 * s_max, 0.1);
        add(1.5 * s_max, -s_max, t, 1.0, 5 * s_max, 2 * s_max, -0.3, 0.1, -3 * s_max);
        add(3 * s_max, -2.5 * s_max, t, 2.5, 0.3, 0.3, 0, INFINITY, 0.5);
        add(-3 * s_max, 2.5 * s_max, t, -2.5, 0.1, 0.4, 0.9, -INFINITY, kNan);
    }
    const std::size_t count = points.size() / 12;
    struct {
        float domain_min, domain_max;
        std::int32_t wrap;
        float s_max;
        std::int32_t points;
        float nodes[16], weights[16];
        std::int32_t count;
    } parameters{0.0f, 90.0f, 0, static_cast<float>(s_max), static_cast<std::int32_t>(rule.nodes.size()), {}, {}, 0};
    for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
        parameters.nodes[i] = static_cast<float>(rule.nodes[i]);
        parameters.weights[i] = static_cast<float>(rule.weights[i]);
    }
    parameters.count = static_cast<std::int32_t>(count);
    const std::vector<float> r = run_kernel(program, points, count, count * 20, &parameters, sizeof parameters);
    Tally moments, colour, vector_colour, vector_exact, vector_sampler;
    for (std::size_t k = 0; k < count; ++k) {
        const float* p = &points[12 * k];
        const float* o = &r[20 * k];
        const std::string where = point_name(p, 7);
        const SlopeGaussian slopes{p[0], p[1], p[4], p[5], p[6]};
        const ViewAngles view{p[2], p[3]};
        const SlopeMoments m = exact_slope_moments(slopes, view);
        // Relative to the slopes' scale (a slope at the horizon of a grazing
        // view is cot theta, large).
        const double scale = std::max({1.0, std::fabs(m.mean_x), std::fabs(m.mean_y)});
        moments.add(o[0] / scale, m.mean_x / scale, where);
        moments.add(o[1] / scale, m.mean_y / scale, where);
        moments.add(o[2] / scale, m.xx / scale, where);
        moments.add(o[3] / scale, m.xy / scale, where);
        moments.add(o[4] / scale, m.yy / scale, where);
        const Rgb c = gaussian_slope_color(map, slopes, view, options);
        const Rgb v = gaussian_slope_color(vector_map, slopes, view, options);
        const Rgb at = vector_map.evaluate(p[8], p[9]);
        const std::string lookup = point_name(p + 8, 2);
        for (int ch = 0; ch < 3; ++ch) {
            colour.add(o[5 + ch], channel(c, ch), where);
            vector_colour.add(o[8 + ch], channel(v, ch), where);
            vector_exact.add(o[12 + ch], channel(at, ch), lookup);
            vector_sampler.add(o[16 + ch], channel(at, ch), lookup);
        }
    }
    glDeleteTextures(1, &tex);
    glDeleteTextures(1, &vector_tex);
    glDeleteProgram(program);
    MESSAGE("slope, " << count << " points: D_s moments " << moments.max_error << ", Gaussian slope colour "
                      << colour.max_error << ", slope-vector map: Gaussian slope colour " << vector_colour.max_error
                      << ", C_s exact " << vector_exact.max_error << ", C_s sampler " << vector_sampler.max_error);
    CHECK_MESSAGE(moments.max_error <= 1e-5, moments.where);
    CHECK_MESSAGE(colour.max_error <= 1e-5, colour.where);
    CHECK_MESSAGE(vector_colour.max_error <= 1e-5, vector_colour.where);
    CHECK_MESSAGE(vector_exact.max_error <= 1e-5, vector_exact.where);
    // llvmpipe filters float textures with float weights (docs/shaders.md).
    CHECK_MESSAGE(vector_sampler.max_error <= 1e-5, vector_sampler.where);
}
