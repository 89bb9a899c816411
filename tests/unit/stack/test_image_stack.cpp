// SPDX-License-Identifier: Apache-2.0
// Loading image stacks (image_stack.h): 8-bit images decoded to scene-linear
// by the sRGB curve (computed here from its definition), kept as codes / 255
// when display-encoded, EXR kept linear; and the checks across images.
#include "cmfilter/stack/image_stack.h"

#include "test_images.h"
#include "unit_test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

using namespace cmfilter;

namespace {

const std::string kDir = cmfilter_test::temp_dir("cmfilter-image-stack");

double srgb_to_linear(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }

// n 4x3 RGB images, image k texel t channel c holding code (7 k + 13 t + 50 c) % 256.
std::string write_png_stack(const std::string& name, int n)
{
    std::string lp = std::to_string(n) + "\n";
    for (int k = 0; k < n; ++k) {
        std::vector<unsigned char> px(4 * 3 * 3);
        for (int t = 0; t < 12; ++t)
            for (int c = 0; c < 3; ++c) px[3 * t + c] = static_cast<unsigned char>((7 * k + 13 * t + 50 * c) % 256);
        const std::string file = name + "-" + std::to_string(k) + ".png";
        cmfilter_test::write_image(kDir + "/" + file, 4, 3, 3, OIIO::TypeDesc::UINT8, px.data());
        const double a = 6.283185307179586 * k / n;
        lp += file + " " + std::to_string(0.5 * std::cos(a)) + " " + std::to_string(0.5 * std::sin(a)) + " 0.8\n";
    }
    const std::string path = kDir + "/" + name + ".lp";
    std::ofstream(path) << lp;
    return path;
}

}  // namespace

TEST_CASE("image stack: 8-bit images decode to scene-linear by the sRGB curve, or stay display codes")
{
    const auto config = cmfilter_test::builtin_color_config();
    const std::string lp = write_png_stack("png", 6);
    StackLoadOptions options;
    options.light_file = lp;
    auto linear = load_image_stack(options, config);
    REQUIRE(linear);
    CHECK(linear->width == 4);
    CHECK(linear->height == 3);
    CHECK(linear->channels == 3);
    CHECK(linear->count() == 6);
    CHECK(linear->encoding == StackEncoding::SceneLinear);
    CHECK(length(linear->lights[2]) == doctest::Approx(1.0));
    options.encoding = StackEncoding::DisplayEncoded;
    auto encoded = load_image_stack(options, config);
    REQUIRE(encoded);
    for (int k = 0; k < 6; ++k)
        for (int t = 0; t < 12; ++t)
            for (int c = 0; c < 3; ++c) {
                const double code = (7 * k + 13 * t + 50 * c) % 256 / 255.0;
                CHECK(linear->image(k)[3 * t + c] == doctest::Approx(srgb_to_linear(code)).epsilon(1e-4));
                CHECK(encoded->image(k)[3 * t + c] == doctest::Approx(code).epsilon(1e-4));
            }
}

TEST_CASE("image stack: EXR images are linear as stored")
{
    const auto config = cmfilter_test::builtin_color_config();
    std::string lp = "6\n";
    for (int k = 0; k < 6; ++k) {
        std::vector<float> px = {0.25f * k, 2.0f, 0.125f};
        const std::string file = "exr-" + std::to_string(k) + ".exr";
        cmfilter_test::write_image(kDir + "/" + file, 1, 1, 3, OIIO::TypeDesc::FLOAT, px.data());
        lp += file + " 0 " + std::to_string(0.1 * k) + " 1\n";
    }
    std::ofstream(kDir + "/exr.lp") << lp;
    StackLoadOptions options;
    options.light_file = kDir + "/exr.lp";
    auto stack = load_image_stack(options, config);
    REQUIRE(stack);
    CHECK(stack->image(4)[0] == doctest::Approx(1.0));
    CHECK(stack->image(4)[1] == doctest::Approx(2.0));
}

TEST_CASE("image stack: too few lights, a missing image, sizes and channels that differ")
{
    const auto config = cmfilter_test::builtin_color_config();
    StackLoadOptions options;
    options.light_file = write_png_stack("five", 5);
    auto few = load_image_stack(options, config);
    REQUIRE_FALSE(few);
    CHECK(few.error().message.find("has 5 lights; a stack needs at least 6") != std::string::npos);

    options.light_file = write_png_stack("size", 6);
    std::vector<unsigned char> px(5 * 3 * 3, 9);
    cmfilter_test::write_image(kDir + "/size-3.png", 5, 3, 3, OIIO::TypeDesc::UINT8, px.data());
    auto size = load_image_stack(options, config);
    REQUIRE_FALSE(size);
    CHECK(size.error().kind == ErrorKind::BadInput);
    CHECK(size.error().message.find("size-3.png' is 5x3 but") != std::string::npos);

    options.light_file = write_png_stack("channels", 6);
    std::vector<unsigned char> grey(4 * 3, 9);
    cmfilter_test::write_image(kDir + "/channels-5.png", 4, 3, 1, OIIO::TypeDesc::UINT8, grey.data());
    auto channels = load_image_stack(options, config);
    REQUIRE_FALSE(channels);
    CHECK(channels.error().message.find("channels-5.png' has 1 channel but") != std::string::npos);

    options.light_file = write_png_stack("missing", 6);
    std::remove((kDir + "/missing-2.png").c_str());
    auto missing = load_image_stack(options, config);
    REQUIRE_FALSE(missing);
    CHECK(missing.error().kind == ErrorKind::Io);
    CHECK(missing.error().message.find("missing-2.png") != std::string::npos);
}

TEST_CASE("image stack: display-encoded values are named by the config's sRGB space, data cannot be encoded")
{
    const auto config = cmfilter_test::builtin_color_config();
    StackLoadOptions options;
    options.light_file = write_png_stack("named", 6);
    options.encoding = StackEncoding::DisplayEncoded;
    auto encoded = load_image_stack(options, config);
    REQUIRE(encoded);
    CHECK(encoded->colorspace == *config.resolve("sRGB"));
    options.encoding = StackEncoding::SceneLinear;
    auto linear = load_image_stack(options, config);
    REQUIRE(linear);
    CHECK(linear->colorspace == config.scene_linear_name());
    options.colorspace = "Raw";
    auto raw = load_image_stack(options, config);
    REQUIRE(raw);
    CHECK(raw->image(1)[0] == doctest::Approx(7 / 255.0));  // data: codes / 255, not decoded
    options.encoding = StackEncoding::DisplayEncoded;
    auto refused = load_image_stack(options, config);
    REQUIRE_FALSE(refused);
    CHECK(refused.error().field == "StackLoadOptions::encoding");
    CHECK(refused.error().message.find("data colour space 'Raw'") != std::string::npos);
}
