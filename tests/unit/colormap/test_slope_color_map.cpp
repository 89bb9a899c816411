// SPDX-License-Identifier: Apache-2.0
// Slope colour maps (slope_color_map.h): the steepness map reads its 1-D map
// at the slope angle in degrees, the slope-vector map lays its image over
// [-s_max, s_max]^2 top row up, bilinear between texel centres and clamped
// beyond; both against values worked out by hand. Loading a slope-vector
// map from an image file (slope_color_map_loading.h).
#include "cmfilter/colormap/slope_color_map.h"
#include "cmfilter/colormap/slope_color_map_loading.h"

#include "test_images.h"
#include "unit_test_support.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace cmfilter;

namespace {

constexpr double kPi = 3.14159265358979323846;

void check_rgb(const Rgb& a, const Rgb& b, double tolerance)
{
    CHECK(std::abs(a.r - b.r) <= tolerance);
    CHECK(std::abs(a.g - b.g) <= tolerance);
    CHECK(std::abs(a.b - b.b) <= tolerance);
}

// 3 x 2 texels over [-1, 1]^2: centres at s_x = -2/3, 0, 2/3 and
// s_y = 1/2 (row 0), -1/2 (row 1).
SlopeVectorColorMap three_by_two()
{
    SlopeVectorColorMap map;
    map.width = 3, map.height = 2, map.s_max = 1;
    map.texels = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0},   // row 0, s_y = +1/2
                  {0, 1, 0}, {1, 1, 0}, {2, 1, 1}};  // row 1, s_y = -1/2
    return map;
}

}  // namespace

TEST_CASE("a steepness map reads its 1-D map at the slope angle in degrees")
{
    // Texels over [0, 90]: centres at 15, 45 and 75 degrees.
    SteepnessColorMap map;
    map.by_angle.vmin = 0, map.by_angle.vmax = 90;
    map.by_angle.texels = {{0, 0, 0}, {1, 0.5, 0}, {1, 1, 1}};
    REQUIRE(validate(map, "steepness"));
    for (double azimuth : {0.0, 1.0, 4.0}) {
        CAPTURE(azimuth);
        // 30 degrees: halfway between the first two centres.
        const double t = std::tan(30 * kPi / 180);
        check_rgb(map.evaluate(t * std::cos(azimuth), t * std::sin(azimuth)), {0.5, 0.25, 0}, 1e-12);
        // 60 degrees: halfway between the last two.
        const double u = std::tan(60 * kPi / 180);
        check_rgb(map.evaluate(u * std::cos(azimuth), u * std::sin(azimuth)), {1, 0.75, 0.5}, 1e-12);
    }
    check_rgb(map.evaluate(0, 0), {0, 0, 0}, 0);      // flat: clamped below 15
    check_rgb(map.evaluate(1e300, 0), {1, 1, 1}, 0);  // vertical: clamped above 75
}

TEST_CASE("a slope-vector map puts row 0 at +s_max, interpolates bilinearly and clamps beyond")
{
    const SlopeVectorColorMap map = three_by_two();
    REQUIRE(validate(map, "slope map"));
    // Texel centres.
    check_rgb(map.evaluate(-2.0 / 3, 0.5), {0, 0, 0}, 1e-12);
    check_rgb(map.evaluate(2.0 / 3, 0.5), {2, 0, 0}, 1e-12);
    check_rgb(map.evaluate(2.0 / 3, -0.5), {2, 1, 1}, 1e-12);
    // The middle of the right four centres: their mean.
    check_rgb(map.evaluate(1.0 / 3, 0), {1.5, 0.5, 0.25}, 1e-12);
    // A quarter of the way down from row 0 at the middle column: g = 1/4.
    check_rgb(map.evaluate(0, 0.25), {1, 0.25, 0}, 1e-12);
    // Beyond the centres: the edge texels hold.
    check_rgb(map.evaluate(5, 5), {2, 0, 0}, 0);
    check_rgb(map.evaluate(-5, -5), {0, 1, 0}, 0);
    check_rgb(map.evaluate(0.95, -0.5), {2, 1, 1}, 1e-12);
    check_rgb(map.evaluate(1e300, -1e300), {2, 1, 1}, 0);
}

TEST_CASE("slope maps with missing or non-finite texels or a bad s_max are refused")
{
    SlopeVectorColorMap map = three_by_two();
    map.texels.pop_back();
    CHECK_FALSE(validate(map, "slope map"));
    map = three_by_two();
    map.s_max = 0;
    const Status bad = validate(map, "slope map");
    REQUIRE_FALSE(bad);
    CHECK(bad.error().kind == ErrorKind::BadInput);
    CHECK(bad.error().message.find("s_max") != std::string::npos);
    map = three_by_two();
    map.texels[2].g = std::nan("");
    CHECK_FALSE(validate(map, "slope map"));
    SteepnessColorMap empty;
    CHECK_FALSE(validate(empty, "steepness"));
}

TEST_CASE("a slope-vector map loads from an image, top row at +s_max, decoded to scene-linear")
{
    const std::string dir = cmfilter_test::temp_dir("cmfilter-test-slope-color-map");
    const std::string path = dir + "/wheel.png";
    // 2 x 2, 8-bit: sRGB by default.
    const unsigned char px[] = {255, 0, 0,   0,   255, 0,     // row 0
                                0,   0, 255, 128, 128, 128};  // row 1
    cmfilter_test::write_image(path, 2, 2, 3, OIIO::TypeDesc::UINT8, px);
    SlopeVectorColorMapLoadOptions options;
    options.path = path;
    options.s_max = 2;
    auto loaded = load_slope_vector_color_map(options, cmfilter_test::builtin_color_config());
    REQUIRE(loaded);
    CHECK(loaded->map.width == 2);
    CHECK(loaded->map.height == 2);
    CHECK(loaded->map.s_max == 2);
    CHECK(loaded->provenance.colorspace == "sRGB Encoded Rec.709");
    CHECK(loaded->provenance.selection == "whole image");
    // Centres at s = +-1: top left red, top right green, bottom right grey.
    check_rgb(loaded->map.evaluate(-1, 1), {1, 0, 0}, 1e-5);
    check_rgb(loaded->map.evaluate(1, 1), {0, 1, 0}, 1e-5);
    const double grey = cmfilter_test::srgb_to_linear(128 / 255.0);
    check_rgb(loaded->map.evaluate(1, -1), {grey, grey, grey}, 1e-5);

    options.s_max = -1;
    auto bad = load_slope_vector_color_map(options, cmfilter_test::builtin_color_config());
    REQUIRE_FALSE(bad);
    CHECK(bad.error().kind == ErrorKind::BadInput);
    options.s_max = 1;
    options.path = dir + "/missing.png";
    CHECK_FALSE(load_slope_vector_color_map(options, cmfilter_test::builtin_color_config()));
}
