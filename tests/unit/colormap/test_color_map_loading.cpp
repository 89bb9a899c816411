// SPDX-License-Identifier: Apache-2.0
// Loading colour maps from image files: gradient selection, colour-space
// decisions, and bad input.
#include "cmfilter/colormap/color_map_loading.h"

#include "test_images.h"
#include "unit_test_support.h"

#include <doctest/doctest.h>

using namespace cmfilter;
using cmfilter_test::write_image;

namespace {

std::string temp_dir() { return cmfilter_test::temp_dir("cmfilter-test-color-map-loading"); }

}  // namespace

TEST_CASE("an 8-bit PNG is decoded as sRGB and laid over the domain")
{
    const std::string path = temp_dir() + "/ramp.png";
    const unsigned char px[] = {0, 64, 128, 255, 32, 16, 200, 100, 50};
    write_image(path, 3, 1, 3, OIIO::TypeDesc::UINT8, px);
    ColorMapLoadOptions opt;
    opt.path = path;
    opt.vmin = -1;
    opt.vmax = 2;
    auto loaded = load_color_map(opt, cmfilter_test::builtin_color_config());
    REQUIRE(loaded);
    REQUIRE(loaded->map.size() == 3);
    for (int i = 0; i < 9; ++i)
        CHECK(loaded->map.texels[i / 3][i % 3] ==
              doctest::Approx(cmfilter_test::srgb_to_linear(px[i] / 255.0)).epsilon(1e-5));
    CHECK(loaded->map.vmin == -1);
    CHECK(loaded->map.vmax == 2);
    CHECK(loaded->provenance.colorspace == "sRGB Encoded Rec.709");
    CHECK(loaded->provenance.sha256.size() == 64);
}

TEST_CASE("a float EXR is linear by default, and ColorMapLoadOptions::colorspace overrides the file")
{
    const std::string path = temp_dir() + "/lin.exr";
    const float px[] = {0.5f, 0.25f, 2.0f, 1.0f, 0.0f, 0.125f};
    write_image(path, 2, 1, 3, OIIO::TypeDesc::FLOAT, px);
    ColorMapLoadOptions opt;
    opt.path = path;
    auto loaded = load_color_map(opt, cmfilter_test::builtin_color_config());
    REQUIRE(loaded);
    CHECK(loaded->map.texels[0].b == doctest::Approx(2.0));  // no conversion, HDR kept
    CHECK(loaded->provenance.colorspace == "Linear Rec.709");

    opt.colorspace = "ACEScg";
    auto acescg = load_color_map(opt, cmfilter_test::builtin_color_config());
    REQUIRE(acescg);
    // Row 1 of the AP1 -> Rec.709 matrix applied to (0.5, 0.25, 2.0).
    CHECK(acescg->map.texels[0].g ==
          doctest::Approx(-0.1302564 * 0.5 + 1.1408047 * 0.25 - 0.0105483 * 2.0).epsilon(1e-4));
    CHECK(acescg->provenance.colorspace_rule == "ColorMapLoadOptions::colorspace");
}

TEST_CASE("rows and columns of a larger image, grey replicated")
{
    const std::string path = temp_dir() + "/grid.exr";
    std::vector<float> px(4 * 3);
    for (int i = 0; i < 12; ++i) px[i] = static_cast<float>(i);
    write_image(path, 4, 3, 1, OIIO::TypeDesc::FLOAT, px.data());
    ColorMapLoadOptions opt;
    opt.path = path;
    CHECK(load_color_map(opt, cmfilter_test::builtin_color_config())
              .error()
              .message.find("pass ColorMapLoadOptions::row N or ColorMapLoadOptions::column N") != std::string::npos);
    opt.row = 1;
    auto row = load_color_map(opt, cmfilter_test::builtin_color_config());
    REQUIRE(row);
    CHECK(row->map.size() == 4);
    CHECK(row->map.texels[2].r == 6.0);
    CHECK(row->map.texels[2].b == 6.0);
    opt.row.reset();
    opt.column = 3;
    auto col = load_color_map(opt, cmfilter_test::builtin_color_config());
    REQUIRE(col);
    CHECK(col->map.size() == 3);
    CHECK(col->map.texels[2].g == 11.0);
    CHECK(col->provenance.selection == "column 3");
}

TEST_CASE("the file's declared colour space is honoured")
{
    const std::string path = temp_dir() + "/declared.exr";
    const float px[] = {1, 0, 0, 1, 1, 1};
    write_image(path, 2, 1, 3, OIIO::TypeDesc::FLOAT, px, "lin_ap1_scene");
    ColorMapLoadOptions opt;
    opt.path = path;
    auto loaded = load_color_map(opt, cmfilter_test::builtin_color_config());
    REQUIRE(loaded);
    CHECK(loaded->provenance.colorspace == "ACEScg");
    CHECK(loaded->provenance.colorspace_rule == "file metadata");
    CHECK(loaded->map.texels[0].r == doctest::Approx(1.7051).epsilon(1e-4));
}
