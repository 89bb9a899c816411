// SPDX-License-Identifier: Apache-2.0
// Colour management: the built-in OpenColorIO config decodes each transfer
// function and primaries set to the published formulas and matrices.
#include "cmfilter/color/color_config.h"

#include "test_images.h"
#include "unit_test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

using namespace cmfilter;

TEST_CASE("sRGB decoding matches the IEC 61966-2-1 formula for every 8-bit code")
{
    const ColorConfig config = cmfilter_test::builtin_color_config();
    std::vector<float> rgb;
    for (int code = 0; code < 256; ++code)
        for (int ch = 0; ch < 3; ++ch) rgb.push_back(code / 255.0f);
    REQUIRE(config.to_scene_linear(rgb, "sRGB"));
    double worst_iec = 0, worst_moncurve = 0;
    for (int code = 0; code < 256; ++code) {
        const double e = code / 255.0;
        worst_iec = std::max(worst_iec, std::fabs(rgb[3 * code + 1] - cmfilter_test::srgb_to_linear(e)));
        worst_moncurve =
            std::max(worst_moncurve, std::fabs(rgb[3 * code + 1] - cmfilter_test::srgb_moncurve_to_linear(e)));
    }
    // The built-in sRGB space is OpenColorIO's C1 moncurve: it matches the IEC
    // formula except in the toe (codes 10 and below), where the two curves'
    // breakpoints differ by 0.0012 and the values by < 7.6e-7.
    CHECK(worst_iec < 7.6e-7);
    // Against the moncurve formula itself only float32 rounding remains.
    CHECK(worst_moncurve < 1e-7);
}

TEST_CASE("gamma 2.2 decoding is a pure power law, not the sRGB curve")
{
    const ColorConfig config = cmfilter_test::builtin_color_config();
    std::vector<float> rgb = {0.0f, 0.02f, 0.5f, 0.25f, 0.75f, 1.0f};
    const std::vector<float> in = rgb;
    REQUIRE(config.to_scene_linear(rgb, "g22_rec709"));
    for (std::size_t i = 0; i < rgb.size(); ++i) CHECK(rgb[i] == doctest::Approx(std::pow(in[i], 2.2)).epsilon(1e-5));
    // At 0.02 the sRGB curve is in its linear toe (0.00155); gamma 2.2 gives 1.8e-4.
    CHECK(std::fabs(rgb[1] - cmfilter_test::srgb_to_linear(0.02)) > 1e-3);
}

TEST_CASE("ACEScg converts to linear Rec.709 with the published matrix")
{
    const ColorConfig config = cmfilter_test::builtin_color_config();
    // ACEScg primaries and white, as three pixels.
    std::vector<float> rgb = {1, 0, 0, 0, 1, 0, 1, 1, 1};
    REQUIRE(config.to_scene_linear(rgb, "ACEScg"));
    // Published AP1 -> Rec.709 (Bradford D60 -> D65) matrix columns, to 4 decimals.
    CHECK(rgb[0] == doctest::Approx(1.7051).epsilon(1e-4));
    CHECK(rgb[1] == doctest::Approx(-0.1303).epsilon(1e-3));
    CHECK(rgb[2] == doctest::Approx(-0.0240).epsilon(1e-3));
    CHECK(rgb[3] == doctest::Approx(-0.6218).epsilon(1e-4));
    CHECK(rgb[4] == doctest::Approx(1.1408).epsilon(1e-4));
    CHECK(rgb[5] == doctest::Approx(-0.1290).epsilon(1e-3));
    // White stays white.
    for (int ch = 6; ch < 9; ++ch) CHECK(rgb[ch] == doctest::Approx(1.0).epsilon(1e-6));
}

TEST_CASE("names resolve through aliases, unknown names list the known ones")
{
    const ColorConfig config = cmfilter_test::builtin_color_config();
    CHECK(*config.resolve("srgb_tx") == "sRGB Encoded Rec.709");
    CHECK(*config.resolve("Linear") == "Linear Rec.709");
    CHECK(config.scene_linear_name() == "Linear Rec.709");
    CHECK(config.is_data(*config.resolve("raw")));
    auto bad = config.resolve("AdobeRGB-ish");
    REQUIRE(!bad);
    CHECK(bad.error().kind == ErrorKind::BadInput);
    CHECK(bad.error().message.find("unknown colour space 'AdobeRGB-ish'") != std::string::npos);
    CHECK(bad.error().message.find("ACEScg") != std::string::npos);
    CHECK(bad.error().message.find("sRGB Encoded Rec.709") != std::string::npos);
}

TEST_CASE("a config file that does not exist is a clear error")
{
    auto config = ColorConfig::load("/no/such/config.ocio");
    REQUIRE(!config);
    CHECK(config.error().message.find("/no/such/config.ocio") != std::string::npos);
}

namespace {

// A small studio-style config: scene_linear ACEScg (the reference), an sRGB
// texture space under a name cmfilter's built-in config does not use for
// it, a data role, and a file rule for *_rec709.exr.
std::string write_studio_config()
{
    const std::string path = cmfilter_test::temp_dir("cmfilter_color_config") + "/studio.ocio";
    std::ofstream(path) << R"(ocio_profile_version: 2.1
name: unit-studio
strictparsing: true
roles:
  scene_linear: ACEScg
  color_picking: Texture sRGB
  data: Raw
  default: ACEScg
file_rules:
  - !<Rule> {name: maps, colorspace: lin_rec709, pattern: "*_rec709", extension: "exr"}
  - !<Rule> {name: Default, colorspace: default}
displays:
  d:
    - !<View> {name: Raw, colorspace: Raw}
colorspaces:
  - !<ColorSpace> {name: ACEScg, aliases: [lin_ap1], isdata: false}
  - !<ColorSpace>
    name: Linear Rec.709 (sRGB)
    aliases: [lin_rec709]
    isdata: false
    to_scene_reference: !<MatrixTransform> {matrix: [0.6130974024, 0.3395231462, 0.0473794514, 0, 0.0701937225, 0.9163538791, 0.0134523985, 0, 0.0206155929, 0.1095697729, 0.8698146342, 0, 0, 0, 0, 1]}
  - !<ColorSpace>
    name: Texture sRGB
    aliases: [srgb_tx]
    isdata: false
    to_scene_reference: !<ExponentWithLinearTransform> {gamma: 2.4, offset: 0.055}
  - !<ColorSpace> {name: Raw, isdata: true}
)";
    return path;
}

// A resolved name, or the error's message (so that a failed CHECK shows it).
std::string text(const Expected<std::string>& name) { return name ? *name : "error: " + name.error().message; }

}  // namespace

TEST_CASE("a studio config: built-in names, roles, file rules and interop IDs resolve through it")
{
    auto config = ColorConfig::load(write_studio_config());
    REQUIRE_MESSAGE(config, (config ? std::string() : config.error().message));
    // Names cmfilter's own files record, through the built-in config's aliases.
    CHECK(text(config->resolve("Linear Rec.709")) == "Linear Rec.709 (sRGB)");
    CHECK(text(config->resolve("lin_ap1_scene")) == "ACEScg");
    CHECK(text(config->resolve("sRGB")) == "Texture sRGB");
    CHECK_FALSE(config->resolve("Display P3"));  // no name of it in this config
    // Roles.
    CHECK(config->role_space("scene_linear") == "ACEScg");
    CHECK(config->role_space("data") == "Raw");
    CHECK(config->role_space("texture_paint").empty());
    // File rules: only a rule other than Default counts.
    CHECK(config->file_rule_space("/maps/ramp_rec709.exr") == "Linear Rec.709 (sRGB)");
    CHECK(config->file_rule_space("/maps/ramp.exr").empty());
    CHECK(config->file_rule_space("/maps/ramp_rec709.png").empty());
    // Interop IDs of this config's spaces, through the built-in names.
    CHECK(config->interop_id("ACEScg") == "lin_ap1_scene");
    CHECK(config->interop_id("Linear Rec.709 (sRGB)") == "lin_rec709_scene");
    CHECK(config->interop_id("Raw").empty());
    // The sRGB texture space decodes with the IEC formula; linear Rec.709
    // converts to ACEScg with the published matrix (white stays white).
    std::vector<float> rgb = {0.5f, 0.5f, 0.5f, 1, 0, 0};
    REQUIRE(config->to_scene_linear(rgb, *config->srgb_texture_name()));
    CHECK(rgb[0] == doctest::Approx(cmfilter_test::srgb_moncurve_to_linear(0.5)).epsilon(1e-6));
    rgb = {1, 1, 1, 1, 0, 0};
    REQUIRE(config->to_scene_linear(rgb, "Linear Rec.709"));
    for (int c = 0; c < 3; ++c) CHECK(rgb[c] == doctest::Approx(1.0).epsilon(1e-6));
    CHECK(rgb[3] == doctest::Approx(0.6131).epsilon(1e-4));
    CHECK(rgb[4] == doctest::Approx(0.0702).epsilon(1e-3));
    CHECK(rgb[5] == doctest::Approx(0.0206).epsilon(1e-3));
}

TEST_CASE("the built-in config's own interop IDs and its sRGB texture space")
{
    const ColorConfig config = cmfilter_test::builtin_color_config();
    CHECK(config.interop_id(config.scene_linear_name()) == "lin_rec709_scene");
    CHECK(config.interop_id("ACES2065-1") == "lin_ap0_scene");
    CHECK(text(config.srgb_texture_name()) == "sRGB Encoded Rec.709");
    CHECK(config.file_rule_space("anything.png").empty());
}
