// SPDX-License-Identifier: Apache-2.0
// Comparing two images: RMSE and CIEDE2000 against values computed here from
// the pixels the test writes (never values read back from the library), grey
// and alpha handling, colour spaces, the heat-map ramp, and bad input.
#include "cmfilter/ops/image_comparison.h"

#include "cmfilter/color/ciede2000.h"
#include "cmfilter/ops/error_heatmap.h"

#include "reference_convolution.h"
#include "test_images.h"
#include "unit_test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <vector>

using namespace cmfilter;
using cmfilter_test::write_image;

namespace {

std::string temp_dir() { return cmfilter_test::temp_dir("cmfilter-test-image-comparison"); }

// CIE L*a*b* of a linear Rec.709 colour, written here independently of
// libcmfilter: XYZ from the IEC 61966-2-1 (sRGB) matrix, white = the XYZ of
// RGB (1,1,1) (so white Y = 1 -> L* = 100), and CIE 15:2004's f in its
// rational form: t^(1/3) above (6/29)^3 = 216/24389, else (24389/27 t + 16) / 116.
Lab test_lab(double r, double g, double b)
{
    const double m[3][3] = {{0.4124, 0.3576, 0.1805}, {0.2126, 0.7152, 0.0722}, {0.0193, 0.1192, 0.9505}};
    double xyz[3], white[3];
    for (int i = 0; i < 3; ++i) {
        xyz[i] = m[i][0] * r + m[i][1] * g + m[i][2] * b;
        white[i] = m[i][0] + m[i][1] + m[i][2];
    }
    const auto f = [](double t) {
        return t > 216.0 / 24389.0 ? std::pow(t, 1.0 / 3.0) : (24389.0 / 27.0 * t + 16.0) / 116.0;
    };
    const double fx = f(xyz[0] / white[0]), fy = f(xyz[1] / white[1]), fz = f(xyz[2] / white[2]);
    return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

// Delta E00 of two neutral greys, from the CIEDE2000 definition directly: with
// a* = b* = 0 every chroma and hue term vanishes (Sharma et al. 2005, eqs.
// 2-11), leaving |Delta L'| / S_L with S_L from eq. 18.
double grey_de2000(double y1, double y2)
{
    const double l1 = test_lab(y1, y1, y1).L, l2 = test_lab(y2, y2, y2).L;
    const double lm = 0.5 * (l1 + l2) - 50.0;
    const double s_l = 1.0 + 0.015 * lm * lm / std::sqrt(20.0 + lm * lm);
    return std::fabs(l2 - l1) / s_l;
}

// A w x h float RGB image of one colour.
std::vector<float> constant_rgb(int w, int h, float r, float g, float b)
{
    std::vector<float> px;
    for (int i = 0; i < w * h; ++i) px.insert(px.end(), {r, g, b});
    return px;
}

ImageComparisonOptions paths(const std::string& a, const std::string& b)
{
    ImageComparisonOptions options;
    options.path_a = a;
    options.path_b = b;
    return options;
}

bool has_temp_file(const std::string& dir)
{
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        if (entry.path().filename().string().find(".tmp-") != std::string::npos) return true;
    return false;
}

}  // namespace

TEST_CASE("compare: RMSE over R, G, B of every pixel, overall and per channel")
{
    const std::string a = temp_dir() + "/rmse-a.exr", b = temp_dir() + "/rmse-b.exr";
    // 3 x 2 pixels; differences chosen so the sums are easy to check by hand,
    // with HDR and negative values, which RMSE must not clip.
    const std::vector<float> pa = {0.0f, 0.5f, 1.0f, 2.0f, -1.0f, 0.25f, 0.5f, 0.5f, 0.5f,
                                   4.0f, 0.0f, 0.0f, 0.0f, 0.0f,  0.0f,  1.0f, 1.0f, 1.0f};
    const std::vector<float> pb = {0.5f, 0.5f, 1.0f, 2.0f, 1.0f, 0.25f, 0.5f, 0.5f, 0.0f,
                                   1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f,  1.0f, 1.0f, 1.0f};
    write_image(a, 3, 2, 3, OIIO::TypeDesc::FLOAT, pa.data());
    write_image(b, 3, 2, 3, OIIO::TypeDesc::FLOAT, pb.data());
    auto c = compare_images(paths(a, b), cmfilter_test::builtin_color_config());
    REQUIRE(c);
    // Squared differences per channel: R 0.25 + 9 = 9.25, G 4, B 0.25, over 6
    // pixels; overall (9.25 + 4 + 0.25) / 18. Float files are linear and pass
    // through unconverted, so these hold to double rounding: 1e-12.
    CHECK(c->rmse == doctest::Approx(std::sqrt(13.5 / 18.0)).epsilon(1e-12));
    CHECK(c->rmse_rgb[0] == doctest::Approx(std::sqrt(9.25 / 6.0)).epsilon(1e-12));
    CHECK(c->rmse_rgb[1] == doctest::Approx(std::sqrt(4.0 / 6.0)).epsilon(1e-12));
    CHECK(c->rmse_rgb[2] == doctest::Approx(std::sqrt(0.25 / 6.0)).epsilon(1e-12));
    CHECK(c->width == 3);
    CHECK(c->height == 2);
    CHECK(c->pixels == 6);
    CHECK(c->a.colorspace == "Linear Rec.709");  // EXR: linear (OpenImageIO tags it so)
    CHECK(c->de2000.count == 6);
}

TEST_CASE("compare: CIEDE2000 of two constant images is that of their colours")
{
    const std::string a = temp_dir() + "/const-a.exr", b = temp_dir() + "/const-b.exr";
    const float ca[3] = {0.8f, 0.2f, 0.1f}, cb[3] = {0.6f, 0.3f, 0.2f};
    write_image(a, 4, 3, 3, OIIO::TypeDesc::FLOAT, constant_rgb(4, 3, ca[0], ca[1], ca[2]).data());
    write_image(b, 4, 3, 3, OIIO::TypeDesc::FLOAT, constant_rgb(4, 3, cb[0], cb[1], cb[2]).data());
    auto c = compare_images(paths(a, b), cmfilter_test::builtin_color_config());
    REQUIRE(c);
    // The formula is the one verified against Sharma et al.'s pairs
    // (test_ciede2000.cpp); the L*a*b* inputs are computed here. Tolerance
    // 1e-9: the float pixels pass through unconverted, and the two L*a*b*
    // computations differ only in rounding (~1e-13 on values of order 100).
    const double expected = ciede2000(test_lab(ca[0], ca[1], ca[2]), test_lab(cb[0], cb[1], cb[2]));
    CHECK(expected > 5.0);  // a real difference, not a degenerate case
    CHECK(std::fabs(c->de2000.mean - expected) <= 1e-9);
    // Exact: every pixel is the same computation, so p95 and max are the
    // mean's very value.
    CHECK(c->de2000.p95 == c->de2000.max);
    CHECK(std::fabs(c->de2000.max - expected) <= 1e-9);
}

TEST_CASE("compare: 8-bit images are decoded as sRGB before measuring")
{
    const std::string a = temp_dir() + "/srgb-a.png", b = temp_dir() + "/srgb-b.png";
    std::vector<unsigned char> pa, pb;
    for (int i = 0; i < 6; ++i) {
        pa.insert(pa.end(), {200, 50, 30});
        pb.insert(pb.end(), {180, 60, 40});
    }
    write_image(a, 3, 2, 3, OIIO::TypeDesc::UINT8, pa.data());
    write_image(b, 3, 2, 3, OIIO::TypeDesc::UINT8, pb.data());
    auto c = compare_images(paths(a, b), cmfilter_test::builtin_color_config());
    REQUIRE(c);
    CHECK(c->a.colorspace == "sRGB Encoded Rec.709");
    using cmfilter_test::srgb_to_linear;
    const Lab la = test_lab(srgb_to_linear(200 / 255.0), srgb_to_linear(50 / 255.0), srgb_to_linear(30 / 255.0));
    const Lab lb = test_lab(srgb_to_linear(180 / 255.0), srgb_to_linear(60 / 255.0), srgb_to_linear(40 / 255.0));
    // Tolerance 1e-4: OpenColorIO decodes in float32 (relative error ~6e-8 on
    // linear values above 0.01; all codes here are above 11, where its sRGB
    // curve and IEC 61966-2-1's coincide), and Delta E00 changes by at most a
    // few hundred per unit of linear value at these colours: < 3e-5.
    CHECK(std::fabs(c->de2000.max - ciede2000(la, lb)) <= 1e-4);
    // RMSE is measured on the decoded linear values, not on the codes.
    // Tolerance 1e-6: the same float32 decoding error, ~6e-8 per value.
    const double dr = srgb_to_linear(200 / 255.0) - srgb_to_linear(180 / 255.0);
    const double dg = srgb_to_linear(50 / 255.0) - srgb_to_linear(60 / 255.0);
    const double db = srgb_to_linear(30 / 255.0) - srgb_to_linear(40 / 255.0);
    CHECK(std::fabs(c->rmse - std::sqrt((dr * dr + dg * dg + db * db) / 3.0)) <= 1e-6);
}

TEST_CASE("compare: an image against itself is zero everywhere, heat map black")
{
    const std::string a = temp_dir() + "/same.exr", heat = temp_dir() + "/same-heat.png";
    std::vector<float> px;
    for (int i = 0; i < 5 * 4; ++i) px.insert(px.end(), {0.1f * i, 2.0f - 0.1f * i, -0.5f + 0.05f * i});
    write_image(a, 5, 4, 3, OIIO::TypeDesc::FLOAT, px.data());
    ImageComparisonOptions options = paths(a, a);
    options.heatmap_path = heat;
    auto c = compare_images(options, cmfilter_test::builtin_color_config());
    REQUIRE(c);
    // Exact: identical inputs give differences of exactly 0 (eqs. 8-11 of
    // Sharma et al. are differences of equal numbers).
    CHECK(c->rmse == 0.0);
    CHECK(c->rmse_rgb[0] == 0.0);
    CHECK(c->de2000.mean == 0.0);
    CHECK(c->de2000.p95 == 0.0);
    CHECK(c->de2000.max == 0.0);
    auto in = OIIO::ImageInput::open(heat);
    REQUIRE(in);
    std::vector<unsigned char> codes(5 * 4 * 3);
    REQUIRE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, codes.data()));
    for (unsigned char code : codes) CHECK(code == 0);
}

TEST_CASE("compare: grey images are replicated to RGB and alpha is ignored")
{
    const std::string grey = temp_dir() + "/grey.exr", grey_alpha = temp_dir() + "/grey-alpha.exr";
    const std::string rgb = temp_dir() + "/grey-rgb.exr", rgba = temp_dir() + "/grey-rgba.exr";
    const std::vector<float> g = {0.1f, 0.4f, 0.9f, 0.0f};
    std::vector<float> ga, c3, c4;
    for (int i = 0; i < 4; ++i) {
        ga.insert(ga.end(), {g[i], 0.25f * i});
        c3.insert(c3.end(), {g[i], g[i], g[i]});
        c4.insert(c4.end(), {g[i], g[i], g[i], 1.0f - 0.3f * i});
    }
    write_image(grey, 2, 2, 1, OIIO::TypeDesc::FLOAT, g.data());
    write_image(grey_alpha, 2, 2, 2, OIIO::TypeDesc::FLOAT, ga.data());
    write_image(rgb, 2, 2, 3, OIIO::TypeDesc::FLOAT, c3.data());
    write_image(rgba, 2, 2, 4, OIIO::TypeDesc::FLOAT, c4.data());
    for (const std::string& other : {grey_alpha, rgb, rgba}) {
        INFO(other);
        auto c = compare_images(paths(grey, other), cmfilter_test::builtin_color_config());
        REQUIRE(c);
        CHECK(c->rmse == 0.0);  // exact: the same float values on both sides
        CHECK(c->de2000.max == 0.0);
        CHECK(c->channels_compared == 3);
    }
}

TEST_CASE("compare: --colorspace-a/-b override the file's colour space")
{
    const std::string a = temp_dir() + "/override.exr";
    const std::vector<float> px = constant_rgb(2, 1, 0.5f, 0.5f, 0.5f);
    write_image(a, 2, 1, 3, OIIO::TypeDesc::FLOAT, px.data());
    ImageComparisonOptions options = paths(a, a);
    options.colorspace_a = "sRGB";
    auto c = compare_images(options, cmfilter_test::builtin_color_config());
    REQUIRE(c);
    CHECK(c->a.colorspace == "sRGB Encoded Rec.709");
    CHECK(c->a.colorspace_rule == "ImageComparisonOptions::colorspace_a");
    CHECK(c->b.colorspace == "Linear Rec.709");
    // A is decoded as sRGB (0.5 -> 0.21404), B is taken as linear 0.5. Tolerance
    // 1e-6: float32 decoding in OpenColorIO (relative ~6e-8).
    CHECK(std::fabs(c->rmse - (0.5 - cmfilter_test::srgb_to_linear(0.5))) <= 1e-6);

    options.colorspace_b = "bogus";
    auto bad = compare_images(options, cmfilter_test::builtin_color_config());
    REQUIRE(!bad);
    CHECK(bad.error().kind == ErrorKind::BadInput);
    CHECK(bad.error().message.find("unknown colour space 'bogus'") != std::string::npos);
}

TEST_CASE("heat map ramp: black, red, yellow, white at 0, max/3, 2 max/3, max")
{
    // Exact: each code is round(255 clamp(3t - k, 0, 1)) at t = 0, 1/3, 2/3, 1,
    // where 3t is within a few ulps of an integer.
    CHECK(heatmap_color(0.0, 9.0) == Rgb8{0, 0, 0});
    CHECK(heatmap_color(3.0, 9.0) == Rgb8{255, 0, 0});
    CHECK(heatmap_color(6.0, 9.0) == Rgb8{255, 255, 0});
    CHECK(heatmap_color(9.0, 9.0) == Rgb8{255, 255, 255});
    CHECK(heatmap_color(50.0, 9.0) == Rgb8{255, 255, 255});  // saturates
    CHECK(heatmap_color(-1.0, 9.0) == Rgb8{0, 0, 0});
    CHECK(heatmap_color(std::nan(""), 9.0) == Rgb8{0, 0, 0});
    // Midway along the first segment: 3t = 0.5 -> 127.5, rounded away from 0.
    CHECK(heatmap_color(1.5, 9.0) == Rgb8{128, 0, 0});
}

TEST_CASE("heat map: a pixel with a known Delta E00 gets the ramp's colour")
{
    const std::string a = temp_dir() + "/heat-a.exr", b = temp_dir() + "/heat-b.exr";
    const std::string heat = temp_dir() + "/heat.png";
    // Pixel 0: greys 0.2 vs 0.3 (Delta E00 known in closed form); pixel 1:
    // equal; pixel 2: black vs white (L* 0 vs 100), far above the scale.
    const std::vector<float> pa = {0.2f, 0.2f, 0.2f, 0.5f, 0.1f, 0.7f, 0.0f, 0.0f, 0.0f};
    const std::vector<float> pb = {0.3f, 0.3f, 0.3f, 0.5f, 0.1f, 0.7f, 1.0f, 1.0f, 1.0f};
    write_image(a, 3, 1, 3, OIIO::TypeDesc::FLOAT, pa.data());
    write_image(b, 3, 1, 3, OIIO::TypeDesc::FLOAT, pb.data());
    const double de = grey_de2000(0.2f, 0.3f);
    ImageComparisonOptions options = paths(a, b);
    options.heatmap_path = heat;
    options.heatmap_max = de / 0.6;  // pixel 0 at t = 0.6: 3t = 1.8 -> (255, 204, 0)
    auto c = compare_images(options, cmfilter_test::builtin_color_config());
    REQUIRE(c);
    CHECK(c->heatmap_path == heat);
    CHECK(!has_temp_file(temp_dir()));

    auto in = OIIO::ImageInput::open(heat);
    REQUIRE(in);
    CHECK(in->spec().width == 3);
    CHECK(in->spec().height == 1);
    CHECK(in->spec().format == OIIO::TypeDesc::UINT8);
    std::vector<unsigned char> codes(9);
    REQUIRE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, codes.data()));
    // Exact codes: 255 * 0.8 = 204 is 1e-10 or more from a rounding boundary.
    CHECK(codes == std::vector<unsigned char>{255, 204, 0, 0, 0, 0, 255, 255, 255});
}

TEST_CASE("compare: bad input is refused and leaves no heat map")
{
    const std::string a = temp_dir() + "/bad-a.exr", small = temp_dir() + "/bad-small.exr";
    const std::string nan_path = temp_dir() + "/bad-nan.exr", heat = temp_dir() + "/bad-heat.png";
    std::filesystem::remove(heat);
    write_image(a, 4, 2, 3, OIIO::TypeDesc::FLOAT, constant_rgb(4, 2, 0.1f, 0.2f, 0.3f).data());
    write_image(small, 2, 2, 3, OIIO::TypeDesc::FLOAT, constant_rgb(2, 2, 0.1f, 0.2f, 0.3f).data());
    std::vector<float> nan_px = constant_rgb(4, 2, 0.1f, 0.2f, 0.3f);
    nan_px[3 * 5 + 1] = std::nanf("");
    nan_px[3 * 6 + 0] = INFINITY;
    nan_px[3 * 6 + 2] = -INFINITY;
    write_image(nan_path, 4, 2, 3, OIIO::TypeDesc::FLOAT, nan_px.data());

    ImageComparisonOptions options = paths(a, small);
    options.heatmap_path = heat;
    auto mismatch = compare_images(options, cmfilter_test::builtin_color_config());
    REQUIRE(!mismatch);
    CHECK(mismatch.error().kind == ErrorKind::BadInput);
    CHECK(mismatch.error().message ==
          "'" + a + "' is 4 x 2 but '" + small + "' is 2 x 2; expected images of the same size");

    options.path_b = nan_path;
    auto nan = compare_images(options, cmfilter_test::builtin_color_config());
    REQUIRE(!nan);
    CHECK(nan.error().kind == ErrorKind::BadInput);
    // Two pixels hold non-finite values, the first at pixel 5 = (1, 1), green.
    CHECK(nan.error().message.find("'" + nan_path +
                                   "' has 2 pixels with non-finite values "
                                   "(the first at (1, 1) channel 1: nan)") != std::string::npos);

    options.path_b = a;
    options.heatmap_max = 0.0;
    auto zero = compare_images(options, cmfilter_test::builtin_color_config());
    REQUIRE(!zero);
    CHECK(zero.error().kind == ErrorKind::BadInput);

    CHECK(!std::filesystem::exists(heat));
    CHECK(!has_temp_file(temp_dir()));
}
