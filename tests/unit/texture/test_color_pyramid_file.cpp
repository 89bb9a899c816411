// SPDX-License-Identifier: Apache-2.0
// The baked colour pyramid (texture/color_pyramid_file.h) against independent
// computations: every level's texels, read back with OpenImageIO itself,
// against the brute-force area-weighted box mean of C0(f)
// (tests/support/box_reference.h, reference_convolution.h's C0) for a driver
// whose size is not a power of two, in float32 and in half; the lookup class
// at texel centres against the same; the metadata read back; the refusal of
// another map (the digest of C0 as evaluated, not the file); bad options.
#include "cmfilter/colormap/color_map_digest.h"
#include "cmfilter/texture/color_pyramid_file.h"
#include "cmfilter/texture/color_pyramid_texture.h"

#include "apply_inputs.h"
#include "box_reference.h"
#include "reference_convolution.h"
#include "test_images.h"

#include <OpenImageIO/imageio.h>
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

using namespace cmfilter;
using namespace cmfilter_test;

namespace {

const std::string kDir = temp_dir("cmfilter-test-color-pyramid");
constexpr int kW = 13, kH = 7;

ColorMap color_map()
{
    ColorMap m;
    for (std::size_t i = 0; i < kMap.size(); i += 3) m.texels.push_back({kMap[i], kMap[i + 1], kMap[i + 2]});
    return m;
}

std::vector<float> driver_values()
{
    std::vector<float> f(kW * kH);
    for (int i = 0; i < kW * kH; ++i) f[i] = static_cast<float>(0.5 + 0.6 * std::sin(1.3 * i + 0.2 * (i % 5)));
    return f;
}

std::string write_driver(const std::vector<float>& f)
{
    const std::string path = kDir + "/driver.exr";
    write_image(path, kW, kH, 1, OIIO::TypeDesc::FLOAT, f.data());
    return path;
}

ColorPyramidBakeResult bake(const std::string& driver, const std::string& output, const ColorMap& map,
                            ExrPixelType type = ExrPixelType::Float)
{
    ColorPyramidBakeOptions o;
    o.driver_path = driver;
    o.output_path = output;
    o.map = &map;
    o.map_source = "map.exr";
    o.linear_space = "lin_rec709";
    o.storage.pixel_type = type;
    auto r = bake_color_pyramid(o);
    if (!r) FAIL(r.error().message);
    return *r;
}

// Largest |file texel - brute-force box mean of C0(f)| over every level,
// relative to max(1, |want|).
double worst_level_error(const std::string& path, const std::vector<float>& f)
{
    auto in = OIIO::ImageInput::open(path);
    REQUIRE(in);
    const ReferenceMap m = reference_map();
    double worst = 0;
    for (int k = 0; in->seek_subimage(0, k); ++k) {
        const OIIO::ImageSpec& spec = in->spec();
        REQUIRE(spec.width == std::max(1, kW >> k));
        REQUIRE(spec.height == std::max(1, kH >> k));
        REQUIRE(spec.nchannels == 3);
        std::vector<float> texels(std::size_t(spec.width) * spec.height * 3);
        REQUIRE(in->read_image(0, k, 0, 3, OIIO::TypeDesc::FLOAT, texels.data()));
        for (int y = 0; y < spec.height; ++y)
            for (int x = 0; x < spec.width; ++x) {
                const Rgb3 want = box_mean_color(m, f, kW, kH, spec.width, spec.height, x, y);
                for (int ch = 0; ch < 3; ++ch) {
                    const double got = texels[(std::size_t(y) * spec.width + x) * 3 + ch];
                    worst = std::max(worst, std::abs(got - want[ch]) / std::max(1.0, std::abs(want[ch])));
                }
            }
    }
    return worst;
}

}  // namespace

TEST_CASE("colour pyramid: every level is the box mean of C0(f), float32 and half, 13 x 7 driver")
{
    const std::vector<float> f = driver_values();
    const std::string driver = write_driver(f);
    const ColorMap map = color_map();
    const ColorPyramidBakeResult r = bake(driver, kDir + "/float.exr", map);
    CHECK(r.info.levels == 4);  // 13x7, 6x3, 3x1, 1x1
    // float32 storage of double sums: 2^-24 relative.
    CHECK(worst_level_error(kDir + "/float.exr", f) <= 2e-7);
    bake(driver, kDir + "/half.exr", map, ExrPixelType::Half);
    // half: 2^-11 relative rounding, and no worse.
    const double half = worst_level_error(kDir + "/half.exr", f);
    CHECK(half <= 1.0 / 2048);
    CHECK(half > 1e-6);  // it is stored as half
}

TEST_CASE("colour pyramid: lookups at texel centres read the box means, and the metadata reads back")
{
    const std::vector<float> f = driver_values();
    const std::string driver = write_driver(f);
    const ColorMap map = color_map();
    bake(driver, kDir + "/lookup.exr", map);
    auto tex = ColorPyramidTexture::open(kDir + "/lookup.exr");
    REQUIRE(tex);
    const ColorPyramidInfo& info = tex->info();
    CHECK(info.width == kW);
    CHECK(info.height == kH);
    CHECK(info.levels == 4);
    CHECK(info.map_sha256 == color_map_sha256(map));
    CHECK(info.map_vmin == 0);
    CHECK(info.map_vmax == 1);
    CHECK(info.linear_space == "lin_rec709");
    CHECK(info.bytes_per_texel() == 12);
    CHECK(same_file_path(info.source, driver));
    CHECK(tex->reachable_levels() == 3);  // the smaller side reaches 1 at level 2
    const ReferenceMap m = reference_map();
    for (int k = 0; k < tex->reachable_levels(); ++k) {
        const int w = std::max(1, kW >> k), h = std::max(1, kH >> k);
        double worst = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const ColorPyramidSample c = tex->lookup((x + 0.5f) / w, (y + 0.5f) / h, static_cast<float>(k));
                REQUIRE(c.ok);
                const Rgb3 want = box_mean_color(m, f, kW, kH, w, h, x, y);
                for (int ch = 0; ch < 3; ++ch) worst = std::max(worst, std::abs(c.color[ch] - want[ch]));
            }
        CAPTURE(k);
        CHECK(worst <= 1e-6);
    }
}

TEST_CASE("colour pyramid: another map is refused by what C0 evaluates to, whatever the file")
{
    const std::string driver = write_driver(driver_values());
    const ColorMap map = color_map();
    const ColorPyramidBakeResult r = bake(driver, kDir + "/refuse.exr", map);
    // The same colours read again: accepted.
    CHECK(check_color_pyramid_map(r.info, "refuse.exr", color_map(), "the table's map"));
    // One colour changed: refused, naming the pyramid and the map.
    ColorMap edited = color_map();
    edited.texels[3].g += 0.01;
    const Status colours = check_color_pyramid_map(r.info, "refuse.exr", edited, "the table's map");
    REQUIRE_FALSE(colours);
    CHECK(colours.error().message.find("refuse.exr") != std::string::npos);
    CHECK(colours.error().message.find("colours or wrap differ") != std::string::npos);
    // Another domain: refused, naming both domains.
    ColorMap shifted = color_map();
    shifted.vmin = 1000;
    shifted.vmax = 1001;
    const Status domain = check_color_pyramid_map(r.info, "refuse.exr", shifted, "the table's map");
    REQUIRE_FALSE(domain);
    CHECK(domain.error().message.find("[1000, 1001]") != std::string::npos);
    CHECK(domain.error().message.find("[0, 1]") != std::string::npos);
    // Another wrap.
    ColorMap repeat = color_map();
    repeat.wrap = WrapMode::Repeat;
    CHECK_FALSE(check_color_pyramid_map(r.info, "refuse.exr", repeat, "the table's map"));
}

TEST_CASE("colour pyramid: bad options are refused, leaving no file")
{
    const std::string driver = write_driver(driver_values());
    ColorPyramidBakeOptions o;
    o.driver_path = driver;
    o.output_path = kDir + "/none.exr";
    auto missing = bake_color_pyramid(o);
    REQUIRE_FALSE(missing);
    CHECK(missing.error().field == "ColorPyramidBakeOptions::map");
    ColorMap empty;
    o.map = &empty;
    CHECK_FALSE(bake_color_pyramid(o));
    // A colour past a half's range, in half.
    ColorMap bright = color_map();
    bright.texels[0] = {1e6, 0, 0};
    o.map = &bright;
    o.storage.pixel_type = ExrPixelType::Half;
    std::vector<float> low(kW * kH, 0.0f);
    write_image(kDir + "/low.exr", kW, kH, 1, OIIO::TypeDesc::FLOAT, low.data());
    o.driver_path = kDir + "/low.exr";
    auto too_bright = bake_color_pyramid(o);
    REQUIRE_FALSE(too_bright);
    CHECK(too_bright.error().message.find("half") != std::string::npos);
    CHECK_FALSE(std::ifstream(o.output_path).good());
}
