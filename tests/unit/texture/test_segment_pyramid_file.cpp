// SPDX-License-Identifier: Apache-2.0
// The segment pyramid (texture/segment_pyramid_file.h) and the breakpoints
// behind it (colormap/map_breakpoints.h) against independent computations:
// the breakpoints reproduce C0 (reference_convolution.h's own interpolation)
// at 4001 points and none can go; every level's lookups, recoloured with a
// map of other colours on the same breakpoints, equal the brute-force
// area-weighted box mean of that map (box_reference.h) for a 13 x 7 float
// driver with values outside the map's domain; a two-colour map takes one
// channel; a map of other breakpoints is refused naming where it breaks; the
// tolerance removes breakpoints within a mean error measured here directly.
#include "cmfilter/colormap/map_breakpoints.h"
#include "cmfilter/texture/segment_pyramid_file.h"
#include "cmfilter/texture/segment_pyramid_texture.h"

#include "box_reference.h"
#include "reference_convolution.h"
#include "scoped_env.h"
#include "test_images.h"

#include "cmfilter/color/ciede2000.h"

#include <OpenImageIO/imageio.h>
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

using namespace cmfilter;
using namespace cmfilter_test;

namespace {

const std::string kDir = temp_dir("cmfilter-test-segment-pyramid");
constexpr int kW = 13, kH = 7;

// 12 texels over [0, 1]: a flat start, a collinear run (texels 2..6 on one
// line: knots 3, 4 and 5 are not breakpoints), a hard step, a flat end.
ReferenceMap reference_colors(double scale)
{
    ReferenceMap m;
    const double g[12] = {0.1, 0.1, 0.1, 0.2, 0.3, 0.4, 0.5, 0.9, 0.2, 0.6, 0.6, 0.6};
    for (int i = 0; i < 12; ++i) m.texels.push_back({scale * g[i], 1 - 0.5 * scale * g[i], 0.5 * g[i] + 0.1 * scale});
    return m;
}

ColorMap color_map(const ReferenceMap& r)
{
    ColorMap m;
    for (const Rgb3& c : r.texels) m.texels.push_back({c[0], c[1], c[2]});
    m.vmin = r.vmin;
    m.vmax = r.vmax;
    return m;
}

std::vector<float> driver_values()
{
    std::vector<float> f(kW * kH);
    for (int i = 0; i < kW * kH; ++i) f[i] = static_cast<float>(0.5 + 0.6 * std::sin(1.3 * i + 0.2 * (i % 5)));
    return f;
}

std::string write_driver(const std::vector<float>& f, const std::string& name)
{
    const std::string path = kDir + "/" + name;
    write_image(path, kW, kH, 1, OIIO::TypeDesc::FLOAT, f.data());
    return path;
}

double max_rgb_difference(const Rgb& a, const Rgb3& b)
{
    return std::max({std::abs(a.r - b[0]), std::abs(a.g - b[1]), std::abs(a.b - b[2])});
}

SegmentPyramidBakeResult bake(const std::string& driver, const std::string& output, std::vector<const ColorMap*> maps,
                              double tolerance = 0, ExrPixelType type = ExrPixelType::Float)
{
    SegmentPyramidBakeOptions o;
    o.driver_path = driver;
    o.output_path = output;
    o.maps = std::move(maps);
    o.tolerance_de = tolerance;
    o.storage.pixel_type = type;
    auto r = bake_segment_pyramid(o);
    if (!r) FAIL(r.error().message);
    return *r;
}

}  // namespace

TEST_CASE("segment breakpoints: the interpolant through them is C0 at 4001 points, and none can go")
{
    const ReferenceMap ref = reference_colors(1.0);
    const ColorMap map = color_map(ref);
    const double lo = -0.2, hi = 1.1;  // past both ends of the domain
    auto t = map_breakpoints(map, lo, hi);
    REQUIRE(t);
    // Knots at (i + 0.5) / 12: slope changes at 2, 6, 7, 8, 9; not at 3, 4, 5
    // (collinear), 0, 1, 10, 11 (flat), and the ends are flat.
    const std::vector<double> want = {2.5 / 12, 6.5 / 12, 7.5 / 12, 8.5 / 12, 9.5 / 12};
    REQUIRE(t->size() == want.size());
    for (std::size_t k = 0; k < want.size(); ++k) CHECK((*t)[k] == doctest::Approx(want[k]).epsilon(1e-12));
    const auto worst = [&](const std::vector<double>& b) {
        double w = 0;
        for (int i = 0; i <= 4000; ++i) {
            const double f = lo + (hi - lo) * i / 4000.0;
            w = std::max(w, max_rgb_difference(breakpoint_interpolant(map, b, f), reference_map_value(ref, f)));
        }
        return w;
    };
    CHECK(worst(*t) <= 1e-12);
    for (std::size_t k = 0; k < t->size(); ++k) {
        std::vector<double> fewer = *t;
        fewer.erase(fewer.begin() + static_cast<std::ptrdiff_t>(k));
        CAPTURE(k);
        CHECK(worst(fewer) > 1e-3);
    }
    // A range inside a sloped segment starts and ends with breakpoints.
    auto inside = map_breakpoints(map, 0.3, 0.5);
    REQUIRE(inside);
    REQUIRE(inside->size() == 2);
    CHECK(inside->front() == 0.3);
    CHECK(inside->back() == 0.5);
}

TEST_CASE("segment pyramid: every level recoloured is the box mean of the new map, float32 and half")
{
    const std::vector<float> f = driver_values();  // -0.1 .. 1.1: beyond the domain on both sides
    const std::string driver = write_driver(f, "driver.exr");
    const ReferenceMap baked_ref = reference_colors(1.0);
    const ColorMap baked = color_map(baked_ref);
    // Other colours on the same breakpoints: scaled, and the step reversed.
    const ReferenceMap other_ref = reference_colors(-0.7);
    const ColorMap other = color_map(other_ref);
    for (ExrPixelType type : {ExrPixelType::Float, ExrPixelType::Half}) {
        const std::string path = kDir + (type == ExrPixelType::Half ? "/half.exr" : "/float.exr");
        const SegmentPyramidBakeResult r = bake(driver, path, {&baked}, 0, type);
        CHECK(r.info.channels() == 4);  // 5 breakpoints
        CHECK(r.info.bytes_per_texel() == (type == ExrPixelType::Half ? 8u : 16u));
        auto tex = SegmentPyramidTexture::open(path);
        REQUIRE(tex);
        CHECK(tex->info().breakpoints == r.info.breakpoints);
        auto fit = check_segment_pyramid_map(tex->info(), path, other, "the other map");
        REQUIRE(fit);
        CHECK(fit->max_de <= 1e-9);
        const std::vector<Rgb> colors = ramp_colors(other, tex->info().breakpoints, tex->info().weights());
        std::vector<float> ramps(tex->channels());
        for (int k = 0; k < tex->reachable_levels(); ++k) {
            const int w = std::max(1, kW >> k), h = std::max(1, kH >> k);
            double worst = 0;
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    REQUIRE(tex->lookup((x + 0.5f) / w, (y + 0.5f) / h, static_cast<float>(k), ramps.data()));
                    const Rgb got = ramp_color(colors, ramps.data());
                    Rgb3 want{0, 0, 0};
                    for (const BoxWeight& b : box_weights(kW, kH, w, h, x, y)) {
                        const Rgb3 c = reference_map_value(other_ref, f[std::size_t(b.j) * kW + b.i]);
                        for (int ch = 0; ch < 3; ++ch) want[ch] += b.weight * c[ch];
                    }
                    worst = std::max(worst, max_rgb_difference(got, want));
                }
            CAPTURE(k);
            // float32: rounding of the stored means; half: 2^-11 of each
            // ramp times steps of at most 0.7.
            CHECK(worst <= (type == ExrPixelType::Half ? 4 * 0.7 / 2048 : 1e-6));
        }
    }
}

TEST_CASE("segment pyramid: lookups read into memory equal TextureSystem's, for every wrap and any lod")
{
    // A second algorithm: OpenImageIO's TextureSystem filtering the same
    // file, at 2000 random points (beyond the texture too) and lods
    // (fractional, negative, past the last level), half of them on texel
    // centres of a level.
    const std::vector<float> f = driver_values();
    const std::string driver = write_driver(f, "reads.exr");
    const ColorMap map = color_map(reference_colors(1.0));
    for (TextureWrap wrap : {TextureWrap::Clamp, TextureWrap::Periodic, TextureWrap::Black}) {
        SegmentPyramidBakeOptions o;
        o.driver_path = driver;
        o.output_path = kDir + "/reads-" + to_string(wrap) + ".exr";
        o.maps = {&map};
        o.wrap = wrap;
        if (auto r = bake_segment_pyramid(o); !r) FAIL(r.error().message);
        auto memory = SegmentPyramidTexture::open(o.output_path, PyramidReads::Memory);
        auto tiles = SegmentPyramidTexture::open(o.output_path, PyramidReads::TextureSystem);
        REQUIRE(memory);
        REQUIRE(tiles);
        CHECK(memory->reads() == PyramidReads::Memory);
        CHECK(tiles->reads() == PyramidReads::TextureSystem);
        CHECK(SegmentPyramidTexture::open(o.output_path)->reads() == PyramidReads::Memory);  // Auto: 2 KB
        const int n = memory->channels();
        std::vector<float> a(n), b(n);
        std::uint32_t state = 12345;
        const auto uniform = [&] {
            state = state * 1664525u + 1013904223u;
            return (state >> 8) / 16777216.0f;
        };
        const char* wrap_name = to_string(wrap);
        double worst = 0, low = 1, high = 0;
        for (int i = 0; i < 2000; ++i) {
            float s = -0.7f + 2.4f * uniform(), t = -0.7f + 2.4f * uniform();
            float lod = -0.5f + 4.5f * uniform();
            if (i % 2 == 0) {  // a texel centre of an integer level
                const int k = static_cast<int>(uniform() * 3.0f);
                const int w = std::max(1, kW >> k), h = std::max(1, kH >> k);
                s = (std::floor(uniform() * w) + 0.5f) / w;
                t = (std::floor(uniform() * h) + 0.5f) / h;
                lod = static_cast<float>(k);
            }
            CAPTURE(wrap_name);
            CAPTURE(s);
            CAPTURE(t);
            CAPTURE(lod);
            REQUIRE(memory->lookup(s, t, lod, a.data()));
            REQUIRE(tiles->lookup(s, t, lod, b.data()));
            for (int c = 0; c < n; ++c) worst = std::max(worst, double(std::abs(a[c] - b[c])));
            low = std::min(low, double(a[n - 1]));
            high = std::max(high, double(a[n - 1]));
        }
        MESSAGE(std::string(wrap_name) << ": largest difference from TextureSystem " << worst << " over ramp means "
                                       << low << " .. " << high);
        CHECK(worst <= 2e-6);
        CHECK(high - low > 0.1);  // the lookups vary: the comparison can fail
    }
}

TEST_CASE("segment pyramid: read into memory only where its levels fit a quarter of the memory budget")
{
    // A 256 x 256 driver: 9 levels, (4^9 - 1) / 3 = 87381 texels of 4
    // channels, 1398096 bytes as float; a tile of 64 x 64 fits every budget
    // below.
    constexpr int n = 256;
    std::vector<float> f(n * n);
    for (int i = 0; i < n * n; ++i) f[i] = static_cast<float>(0.5 + 0.6 * std::sin(1.3 * i + 0.2 * (i % 5)));
    const std::string driver = kDir + "/budget.exr";
    write_image(driver, n, n, 1, OIIO::TypeDesc::FLOAT, f.data());
    const ColorMap map = color_map(reference_colors(1.0));
    SegmentPyramidBakeOptions o;
    o.driver_path = driver;
    o.output_path = kDir + "/budget-segments.exr";
    o.maps = {&map};
    if (auto r = bake_segment_pyramid(o); !r) FAIL(r.error().message);
    const auto open = [&](const char* limit, PyramidReads reads) {
        ScopedEnv env("CMFILTER_MEMORY_LIMIT", limit);
        return SegmentPyramidTexture::open(o.output_path, reads);
    };
    auto five = open("5M", PyramidReads::Auto);  // a quarter: 1310720 bytes, too few
    REQUIRE(five);
    REQUIRE(five->channels() == 4);
    CHECK(five->reads() == PyramidReads::TextureSystem);
    auto six = open("6M", PyramidReads::Auto);  // a quarter: 1572864 bytes
    REQUIRE(six);
    CHECK(six->reads() == PyramidReads::Memory);
    std::vector<float> a(4), b(4);
    REQUIRE(five->lookup(0.3f, 0.6f, 2.5f, a.data()));
    REQUIRE(six->lookup(0.3f, 0.6f, 2.5f, b.data()));
    for (int c = 0; c < 4; ++c) CHECK(a[c] == doctest::Approx(b[c]).epsilon(1e-5));
    auto forced = open("5M", PyramidReads::Memory);  // asked for: the whole budget
    REQUIRE(forced);
    CHECK(forced->reads() == PyramidReads::Memory);
    auto refused = open("1M", PyramidReads::Memory);
    REQUIRE_FALSE(refused);
    CHECK(refused.error().message.find("segment pyramid '" + o.output_path + "' read into memory (9 levels of 4 " +
                                       "channels as float) needs 1.4 MB") != std::string::npos);
}

TEST_CASE("segment pyramid: a two-colour map takes one channel whatever its colours")
{
    const std::vector<float> f = driver_values();
    const std::string driver = write_driver(f, "two.exr");
    ColorMap two;
    two.texels = {{1, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, 0, 1}};
    const SegmentPyramidBakeResult r = bake(driver, kDir + "/two-colour.exr", {&two});
    CHECK(r.info.channels() == 1);
    ColorMap yellow_green = two;
    for (int i = 0; i < 2; ++i) yellow_green.texels[i] = {1, 1, 0};
    for (int i = 2; i < 4; ++i) yellow_green.texels[i] = {0, 0.5, 0};
    CHECK(check_segment_pyramid_map(r.info, "two-colour.exr", yellow_green, "the yellow-green map"));
    // A third colour breaks elsewhere: refused, naming where.
    ColorMap three = two;
    three.texels[3] = {0, 1, 0};
    auto refused = check_segment_pyramid_map(r.info, "two-colour.exr", three, "the three-colour map");
    REQUIRE_FALSE(refused);
    const std::string& msg = refused.error().message;
    CHECK(msg.find("two-colour.exr") != std::string::npos);
    CHECK(msg.find("the three-colour map") != std::string::npos);
    CHECK(msg.find("0.875") != std::string::npos);  // knot 3 of 4: (3 + 0.5) / 4
}

TEST_CASE("segment breakpoints: a tolerance keeps fewer, with the mean error over the driver within it")
{
    // A smooth 64-texel map over a driver of 2000 values.
    ColorMap smooth;
    for (int i = 0; i < 64; ++i) {
        const double u = i / 63.0;
        smooth.texels.push_back({u * u, std::sin(3 * u) * 0.5 + 0.5, 1 - u});
    }
    std::vector<float> values;
    for (int i = 0; i < 2000; ++i) values.push_back(static_cast<float>(0.5 + 0.45 * std::sin(0.37 * i)));
    BreakpointSelectionOptions o;
    o.maps = {&smooth};
    o.lo = *std::min_element(values.begin(), values.end());
    o.hi = *std::max_element(values.begin(), values.end());
    o.driver = &values;
    auto exact = select_breakpoints(o);
    REQUIRE(exact);
    o.tolerance_de = 0.5;
    auto fewer = select_breakpoints(o);
    REQUIRE(fewer);
    CHECK(fewer->breakpoints.size() < exact->breakpoints.size() / 3);
    // The mean CIEDE2000 over the driver's values, computed here.
    double sum = 0;
    for (float v : values)
        sum += ciede2000_linear_rgb(smooth.evaluate(v), breakpoint_interpolant(smooth, fewer->breakpoints, v));
    const double mean = sum / values.size();
    CHECK(mean <= 0.5 * 1.01);  // the selection's 8192 bins against every value
    CHECK(fewer->max_mean_de == doctest::Approx(mean).epsilon(0.01));
    // A limit of 4 breakpoints goes past the tolerance and says so.
    o.max_breakpoints = 4;
    auto capped = select_breakpoints(o);
    REQUIRE(capped);
    CHECK(capped->breakpoints.size() == 4);
    CHECK(capped->max_mean_de > 0.5);
}

TEST_CASE("segment pyramid: bad options and another kind of file are refused")
{
    const std::string driver = write_driver(driver_values(), "bad.exr");
    SegmentPyramidBakeOptions o;
    o.driver_path = driver;
    o.output_path = kDir + "/none.exr";
    auto none = bake_segment_pyramid(o);
    REQUIRE_FALSE(none);
    CHECK(none.error().field == "SegmentPyramidBakeOptions::maps");
    const ColorMap map = color_map(reference_colors(1.0));
    o.maps = {&map};
    o.tolerance_de = -1;
    auto negative = bake_segment_pyramid(o);
    REQUIRE_FALSE(negative);
    CHECK(negative.error().field == "SegmentPyramidBakeOptions::tolerance_de");
    o.tolerance_de = 0;
    o.max_channels = 2;  // the map needs 4 exactly
    auto capped = bake_segment_pyramid(o);
    REQUIRE_FALSE(capped);
    CHECK(capped.error().field == "SegmentPyramidBakeOptions::max_channels");
    CHECK(capped.error().message.find("closest within 2 channels") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(o.output_path));
    auto not_one = SegmentPyramidTexture::open(driver);
    REQUIRE_FALSE(not_one);
    CHECK(not_one.error().message.find("not a cmfilter segment pyramid") != std::string::npos);
}

TEST_CASE("segment pyramid: least-squares colours without valid driver weights are refused, naming the file")
{
    SegmentPyramidInfo info;
    info.width = 4;
    info.height = 2;
    info.levels = 3;  // 4 x 2, 2 x 1, 1 x 1
    info.breakpoints = {0.2, 0.5, 0.9};
    info.color_weights.values = {0.25, 0.75};
    info.color_weights.shares = {0.5, 0.5};
    OIIO::ImageSpec spec(4, 2, 2, OIIO::TypeDesc::FLOAT);
    set_segment_pyramid_metadata(spec, info, "w.exr");
    auto good = get_segment_pyramid_metadata(spec, "w.exr");
    REQUIRE(good);
    CHECK(good->color_weights.values == info.color_weights.values);  // %.17g round-trips
    CHECK(good->color_weights.shares == info.color_weights.shares);
    spec.attribute("cmfilter:segment_weight_shares", "0.5");  // one share for two values
    auto bad = get_segment_pyramid_metadata(spec, "w.exr");
    REQUIRE_FALSE(bad);
    CHECK(bad.error().message.find("'w.exr'") != std::string::npos);
    CHECK(bad.error().message.find("least-squares") != std::string::npos);
    spec.attribute("cmfilter:segment_colors", "cubic");
    REQUIRE_FALSE(get_segment_pyramid_metadata(spec, "w.exr"));
}
