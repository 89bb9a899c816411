// SPDX-License-Identifier: Apache-2.0
// What synth-apply renders through a map (synthesis_source.h): a stack's or
// a BTF's image by index and by light (view) against the pixels written to
// the file here, a fit relit against relight_stack_fit, and the fields of
// bad requests.
#include "cmfilter/synthesis/synthesis_source.h"

#include "cmfilter/stack/btf_manifest.h"
#include "cmfilter/stack/fit_file.h"
#include "cmfilter/stack/light_file.h"
#include "cmfilter/stack/stack_fit.h"

#include "test_images.h"
#include "unit_test_support.h"

#include <doctest/doctest.h>

#include <fstream>
#include <string>
#include <vector>

using namespace cmfilter;

namespace {

const std::string kDir = cmfilter_test::temp_dir("cmfilter-synthesis-source");

const std::vector<Vec3> kLights = {normalize(Vec3{0.2, 0.1, 0.9}), normalize(Vec3{-0.5, 0.3, 0.7}),
                                   normalize(Vec3{0.6, -0.6, 0.5})};

// Float pixels (taken as linear, as they are) of image `k` of view `v`.
std::vector<float> pixels_of(int v, int k, int w, int h)
{
    std::vector<float> p;
    for (int i = 0; i < w * h * 3; ++i) p.push_back(0.01f * static_cast<float>((i * 7 + k * 13 + v * 29) % 97));
    return p;
}

// A stack of kLights.size() float EXRs in `dir`, its .lp's path.
std::string write_stack(const std::string& dir, int view, int w, int h)
{
    std::filesystem::create_directories(dir);
    std::vector<LightEntry> entries;
    for (std::size_t k = 0; k < kLights.size(); ++k) {
        const std::string name = "img-" + std::to_string(k) + ".exr";
        const std::vector<float> p = pixels_of(view, static_cast<int>(k), w, h);
        cmfilter_test::write_image(dir + "/" + name, w, h, 3, OIIO::TypeDesc::FLOAT, p.data());
        entries.push_back({name, kLights[k], 0});
    }
    REQUIRE(write_light_file(dir + "/stack.lp", entries));
    return dir + "/stack.lp";
}

void check_pixels(const SourceImage& source, const std::vector<float>& expected, int w, int h)
{
    CHECK(source.image.width == w);
    CHECK(source.image.height == h);
    CHECK(source.image.channels == 3);
    REQUIRE(source.image.pixels.size() == expected.size());
    int mismatches = 0;
    for (std::size_t i = 0; i < expected.size(); ++i)
        if (source.image.pixels[i] != expected[i]) ++mismatches;
    CHECK(mismatches == 0);
}

}  // namespace

TEST_CASE("synthesis source: a stack's image by index and by light is the file's pixels")
{
    const auto config = cmfilter_test::builtin_color_config();
    const std::string lp = write_stack(kDir + "/stack", 0, 5, 4);
    SourceOptions o;
    o.path = lp;
    o.image = 2;
    o.periodic = true;
    auto by_index = load_source_image(o, config);
    REQUIRE(by_index);
    check_pixels(*by_index, pixels_of(0, 2, 5, 4), 5, 4);
    CHECK(by_index->image.periodic);
    CHECK_FALSE(by_index->is_fit);

    o.image = -1;
    o.light = Vec3{-0.5 * 3, 0.3 * 3, 0.7 * 3};  // kLights[1], not normalised
    auto by_light = load_source_image(o, config);
    REQUIRE(by_light);
    check_pixels(*by_light, pixels_of(0, 1, 5, 4), 5, 4);

    o.light.reset();
    auto first = load_source_image(o, config);
    REQUIRE(first);
    check_pixels(*first, pixels_of(0, 0, 5, 4), 5, 4);

    // A plain image is its own pixels.
    SourceOptions image;
    image.path = kDir + "/stack/img-1.exr";
    auto plain = load_source_image(image, config);
    REQUIRE(plain);
    check_pixels(*plain, pixels_of(0, 1, 5, 4), 5, 4);
}

TEST_CASE("synthesis source: a BTF's image by index across views and by view and light")
{
    const auto config = cmfilter_test::builtin_color_config();
    const std::string dir = kDir + "/btf";
    write_stack(dir + "/view-0", 0, 4, 3);
    write_stack(dir + "/view-1", 1, 4, 3);
    const Vec3 second_view = normalize(Vec3{0.5, 0, 0.866});
    REQUIRE(
        write_btf_manifest(dir + "/btf.json", {{"view-0/stack.lp", Vec3{0, 0, 1}}, {"view-1/stack.lp", second_view}}));
    SourceOptions o;
    o.path = dir + "/btf.json";
    o.image = 4;  // view 1, image 1
    auto by_index = load_source_image(o, config);
    REQUIRE(by_index);
    check_pixels(*by_index, pixels_of(1, 1, 4, 3), 4, 3);

    o.image = -1;
    o.view = second_view;
    o.light = kLights[2];
    auto by_light = load_source_image(o, config);
    REQUIRE(by_light);
    check_pixels(*by_light, pixels_of(1, 2, 4, 3), 4, 3);

    o.view = normalize(Vec3{0, 0.5, 0.866});
    auto missing = load_source_image(o, config);
    REQUIRE_FALSE(missing);
    CHECK(missing.error().field == "SourceOptions::view");
}

TEST_CASE("synthesis source: a fit relit at a light is relight_stack_fit's image")
{
    const auto config = cmfilter_test::builtin_color_config();
    LinearFit fit;
    fit.model = LinearModel::PtmRgb;
    fit.width = 3;
    fit.height = 2;
    fit.channels = 3;
    fit.colorspace = "lin_rec709";
    for (int i = 0; i < 6 * 18; ++i) fit.coefficients.push_back(0.01f * static_cast<float>(i % 11) + 0.02f);
    const std::string path = kDir + "/fit.exr";
    REQUIRE(write_fit_exr(path, fit, FitFileInfo{}));

    const Vec3 light = normalize(Vec3{0.3, -0.2, 0.9});
    SourceOptions o;
    o.path = path;
    o.light = light;
    auto source = load_source_image(o, config);
    REQUIRE(source);
    CHECK(source->is_fit);
    auto expected = relight_stack_fit(StackFit{fit}, light);
    REQUIRE(expected);
    check_pixels(*source, *expected, 3, 2);
    // PTM RGB at texel 0, channel 0 (Malzbender et al. 2001, eq. 2).
    const double lu = light.x, lv = light.y;
    const float* a = fit.coefficients.data();
    const double ptm = a[0] * lu * lu + a[1] * lv * lv + a[2] * lu * lv + a[3] * lu + a[4] * lv + a[5];
    CHECK(source->image.pixels[0] == doctest::Approx(ptm).epsilon(1e-5));

    o.view = normalize(Vec3{0.4, 0, 0.9});
    auto view = load_source_image(o, config);
    REQUIRE_FALSE(view);
    CHECK(view.error().kind == ErrorKind::BadInput);
    CHECK(view.error().field == "SourceOptions::view");

    o.view.reset();
    o.light = Vec3{0.3, 0.1, -0.5};
    auto below = load_source_image(o, config);
    REQUIRE_FALSE(below);
    CHECK(below.error().field == "SourceOptions::light");
}

TEST_CASE("synthesis source: an image outside the sample or a light it lacks is named")
{
    const auto config = cmfilter_test::builtin_color_config();
    const std::string lp = write_stack(kDir + "/bad", 0, 3, 3);
    SourceOptions o;
    o.path = lp;
    o.image = 3;
    auto outside = load_source_image(o, config);
    REQUIRE_FALSE(outside);
    CHECK(outside.error().kind == ErrorKind::BadInput);
    CHECK(outside.error().field == "SourceOptions::image");
    CHECK(outside.error().message.find("0 .. 2") != std::string::npos);

    o.image = -1;
    o.light = Vec3{0, 0, 1};
    auto unlit = load_source_image(o, config);
    REQUIRE_FALSE(unlit);
    CHECK(unlit.error().field == "SourceOptions::light");
    CHECK(unlit.error().message.find("stack.lp") != std::string::npos);

    o.light.reset();
    o.image = -4;
    auto negative = load_source_image(o, config);
    REQUIRE_FALSE(negative);
    CHECK(negative.error().field == "SourceOptions::image");

    SourceOptions missing;
    missing.path = kDir + "/absent.lp";
    auto absent = load_source_image(missing, config);
    REQUIRE_FALSE(absent);
    CHECK(absent.error().kind == ErrorKind::Io);
}
