// SPDX-License-Identifier: Apache-2.0
// Scene files with a microsurface material (material/microsurface, sec. 5.1
// of Heitz et al. 2013): a valid one read to its exact values and defaults
// (tile 8 longest wavelengths, 256 cosines, seed 1), and each bad input
// refused with a message naming the scene, the JSON pointer of the offending
// value and what was expected. Scenes are parsed from text as if they stood
// in examples/scenes/, so that ../../luts/sand-snow.png is the real map.
#include "cmfilter/color/color_config.h"
#include "cmfilter/scene/scene_loading.h"
#include "cmfilter/scene/scene_materials.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

using namespace cmfilter;
using nlohmann::json;

namespace {

const std::string kScenePath = std::string(CMFILTER_SOURCE_DIR) + "/examples/scenes/microsurface-test.json";
const std::string kMicro = "/surfaces/0/material/microsurface";

// One plane with a microsurface, every microsurface key but the optional ones given.
json microsurface_scene()
{
    return json::parse(R"({
      "camera": {"position": [0, 1.2, 0], "look_at": [0, 0.55, 6], "resolution": [32, 24]},
      "light": {"direction": [0.5, 0.45, 1]},
      "surfaces": [
        {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
         "mapping": {"type": "planar", "u_axis": [1, 0, 0], "v_axis": [0, 0, 1]},
         "material": {
           "colormap": {"image": "../../luts/sand-snow.png", "domain": [-0.024, 0.024]},
           "microsurface": {"sigma_h": 0.008, "min_wavelength": 0.05, "max_wavelength": 0.4}}}
      ]})");
}

json& micro(json& scene) { return scene["surfaces"][0]["material"]["microsurface"]; }

Expected<Scene> parse(const json& scene) { return parse_scene(scene.dump(2), kScenePath); }

// The BadInput message after "<scene path>: ", or a note saying what went wrong.
std::string error_of(const json& scene)
{
    auto parsed = parse(scene);
    if (parsed) return "(parsed)";
    CHECK(parsed.error().kind == ErrorKind::BadInput);
    const std::string& message = parsed.error().message;
    const std::string prefix = kScenePath + ": ";
    return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : "(not prefixed) " + message;
}

bool starts_with(const std::string& text, const std::string& start) { return text.rfind(start, 0) == 0; }
bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Each value of the microsurface key refused with "expected <expectation>, got <value>".
void check_each_refused(const std::string& key, const std::vector<json>& values, const std::string& expectation)
{
    json scene = microsurface_scene();
    for (const json& bad : values) {
        CAPTURE(bad.dump());
        micro(scene)[key] = bad;
        CHECK(error_of(scene) == kMicro + "/" + key + ": expected " + expectation + ", got " + bad.dump());
    }
}

// The key set to a value below another key's refused: "expected <bound>"
// (the bound's digits as the loader prints them may run on) ", got <value>".
void check_refused_below(const std::string& key, double value, const std::string& bound)
{
    json scene = microsurface_scene();
    micro(scene)[key] = value;
    const std::string error = error_of(scene);
    CHECK(starts_with(error, kMicro + "/" + key + ": expected " + bound));
    CHECK(contains(error, ", got " + json(value).dump()));
}

const GaussianMicrosurfaceOptions& loaded_options(const Expected<Scene>& scene)
{
    REQUIRE_MESSAGE(scene, (scene ? "" : scene.error().message));
    REQUIRE(scene->surfaces.size() == 1);
    REQUIRE(scene->surfaces[0].material.microsurface.has_value());
    return *scene->surfaces[0].material.microsurface;
}

}  // namespace

// ---- valid scenes ---------------------------------------------------------------

TEST_CASE("a microsurface loads with its values and the defaults tile 8 max_wavelength, 256 cosines, seed 1")
{
    const json scene = microsurface_scene();
    const auto loaded = parse(scene);
    const GaussianMicrosurfaceOptions& o = loaded_options(loaded);
    CHECK(o.sigma_h == 0.008);
    CHECK(o.min_wavelength == 0.05);
    CHECK(o.max_wavelength == 0.4);
    CHECK(o.tile == 3.2);  // 8 x 0.4
    CHECK(o.cosines == 256);
    CHECK(o.seed == 1);
    CHECK(loaded->surfaces[0].material.colormap.image_path ==
          std::string(CMFILTER_SOURCE_DIR) + "/examples/scenes/../../luts/sand-snow.png");
}

TEST_CASE("a microsurface's optional keys are read exactly, at the ends of their ranges too")
{
    json scene = microsurface_scene();
    micro(scene) = json::parse(R"({"sigma_h": 0, "min_wavelength": 0.25, "max_wavelength": 0.25,
                                   "cosines": 4096, "seed": 18446744073709551615, "tile": 0.25})");
    const auto loaded = parse(scene);
    const GaussianMicrosurfaceOptions& o = loaded_options(loaded);
    CHECK(o.sigma_h == 0);  // a flat microsurface
    CHECK(o.min_wavelength == 0.25);
    CHECK(o.max_wavelength == 0.25);
    CHECK(o.tile == 0.25);  // a period of exactly max_wavelength
    CHECK(o.cosines == 4096);
    CHECK(o.seed == UINT64_MAX);

    micro(scene) = json::parse(R"({"sigma_h": 0.01, "min_wavelength": 0.01, "max_wavelength": 0.1,
                                   "cosines": 1, "seed": 0, "tile": 7.5})");
    const auto other = parse(scene);
    const GaussianMicrosurfaceOptions& p = loaded_options(other);
    CHECK(p.cosines == 1);
    CHECK(p.seed == 0);
    CHECK(p.tile == 7.5);
}

TEST_CASE("a microsurface takes any scaled isometry of its plane as mapping")
{
    json scene = microsurface_scene();
    // Half-length axes, rotated about the normal.
    scene["surfaces"][0]["mapping"] = json::parse(R"({"u_axis": [0.3, 0, 0.4], "v_axis": [-0.4, 0, 0.3]})");
    CHECK(error_of(scene) == "(parsed)");
    // A tilted plane (normal (0, 3, 4), normalised on load) with axes in it.
    scene["surfaces"][0]["normal"] = {0, 3, 4};
    scene["surfaces"][0]["mapping"] = json::parse(R"({"u_axis": [2, 0, 0], "v_axis": [0, 1.6, -1.2]})");
    CHECK(error_of(scene) == "(parsed)");
}

TEST_CASE("the bundled microsurface example loads, and its material gets the surface and height scale")
{
    const std::string path = std::string(CMFILTER_SOURCE_DIR) + "/examples/scenes/plane-microsurface-sand-snow.json";
    auto scene = load_scene(path);
    const GaussianMicrosurfaceOptions& o = loaded_options(scene);
    CHECK(o.sigma_h == 0.008);
    CHECK(o.min_wavelength == 0.05);
    CHECK(o.max_wavelength == 0.4);
    CHECK(o.cosines == 256);
    CHECK(o.seed == 1);
    CHECK(o.tile == 3.2);

    // Axes of length 0.5: heights in texture units are 2 scene units each.
    json text = microsurface_scene();
    text["surfaces"][0]["mapping"] = json::parse(R"({"u_axis": [0.5, 0, 0], "v_axis": [0, 0, 0.5]})");
    auto halved = parse(text);
    REQUIRE_MESSAGE(halved, (halved ? "" : halved.error().message));
    auto config = ColorConfig::load("");
    REQUIRE(config);
    MaterialOptions options;
    options.threads = 1;
    auto materials = prepare_materials(*halved, *config, options);
    REQUIRE_MESSAGE(materials, (materials ? "" : materials.error().message));
    REQUIRE(materials->size() == 1);
    const Material& material = (*materials)[0];
    REQUIRE(std::holds_alternative<MicrosurfaceDriver>(material.driver));
    CHECK_FALSE(std::holds_alternative<NoiseDriver>(material.driver));
    CHECK_FALSE(std::holds_alternative<TextureDriver>(material.driver));
    const MicrosurfaceDriver& m = std::get<MicrosurfaceDriver>(material.driver);
    CHECK(m.height_scale == 2);
    CHECK(m.surface.sigma_h() == 0.008);
    CHECK(m.surface.tile() == 3.2);
    CHECK(m.surface.cosines().size() == 256);
}

// ---- bad microsurfaces ----------------------------------------------------------

TEST_CASE("a microsurface without sigma_h is an error naming the key")
{
    json scene = microsurface_scene();
    micro(scene).erase("sigma_h");
    CHECK(error_of(scene) == kMicro + "/sigma_h: required key is missing");
}

TEST_CASE("a microsurface without a wavelength is an error naming the key")
{
    json scene = microsurface_scene();
    micro(scene).erase("min_wavelength");
    CHECK(error_of(scene) == kMicro + "/min_wavelength: required key is missing");
    scene = microsurface_scene();
    micro(scene).erase("max_wavelength");
    CHECK(error_of(scene) == kMicro + "/max_wavelength: required key is missing");
}

TEST_CASE("a negative or non-numeric sigma_h is an error")
{
    json scene = microsurface_scene();
    micro(scene)["sigma_h"] = -0.008;
    CHECK(error_of(scene) == kMicro + "/sigma_h: expected a number >= 0, got -0.008");
    micro(scene)["sigma_h"] = "0.008";
    CHECK(error_of(scene) == kMicro + "/sigma_h: expected a number, got \"0.008\"");
}

TEST_CASE("a wavelength of 0 or below is an error")
{
    json scene = microsurface_scene();
    micro(scene)["min_wavelength"] = 0;
    CHECK(error_of(scene) == kMicro + "/min_wavelength: expected a number > 0, got 0");
    scene = microsurface_scene();
    micro(scene)["max_wavelength"] = -0.4;
    CHECK(error_of(scene) == kMicro + "/max_wavelength: expected a number > 0, got -0.4");
}

TEST_CASE("max_wavelength below min_wavelength is an error naming both")
{
    check_refused_below("max_wavelength", 0.01, "a number >= min_wavelength 0.05");
}

TEST_CASE("a cosine count of 0, above the limit or not an integer is an error naming the range")
{
    check_each_refused("cosines", {json(0), json(4097), json(-3), json(2.5), json("64")}, "an integer from 1 to 4096");
}

TEST_CASE("a seed that is not a non-negative integer is an error")
{
    check_each_refused("seed", {json(1.5), json(-1), json("1"), json(true)}, "an integer >= 0");
}

TEST_CASE("a tile shorter than max_wavelength or not positive is an error")
{
    check_refused_below("tile", 0.2, "a period >= max_wavelength 0.4");
    json scene = microsurface_scene();
    micro(scene)["tile"] = 0;
    CHECK(error_of(scene) == kMicro + "/tile: expected a number > 0, got 0");
}

TEST_CASE("an unknown key in a microsurface is an error listing the known ones")
{
    json scene = microsurface_scene();
    micro(scene)["sigma"] = 0.1;
    CHECK(error_of(scene) ==
          kMicro +
              "/sigma: unknown key (expected one of sigma_h, min_wavelength, max_wavelength, cosines, seed, tile)");
}

TEST_CASE("a microsurface that is not an object is an error")
{
    json scene = microsurface_scene();
    micro(scene) = 0.008;
    CHECK(error_of(scene) == kMicro + ": expected an object, got 0.008");
}

TEST_CASE("a material with both a driver and a microsurface, or neither, is an error")
{
    json scene = microsurface_scene();
    scene["surfaces"][0]["material"]["driver"] = {{"noise", "gradient"}};
    CHECK(
        error_of(scene) ==
        "/surfaces/0/material: expected exactly one of driver, microsurface or displacement, got driver and microsurface");
    scene["surfaces"][0]["material"].erase("driver");
    scene["surfaces"][0]["material"].erase("microsurface");
    CHECK(error_of(scene) ==
          "/surfaces/0/material: expected exactly one of driver, microsurface or displacement, got none");
}

TEST_CASE("a microsurface on a sphere is an error")
{
    json scene = microsurface_scene();
    json& surface = scene["surfaces"][0];
    surface.erase("point");
    surface.erase("normal");
    surface.erase("mapping");
    surface["type"] = "sphere";
    surface["center"] = {0, 0, 6};
    surface["radius"] = 1;
    CHECK(error_of(scene) ==
          kMicro + ": a microsurface needs a plane (it displaces the plane along its normal), not a sphere");
}

TEST_CASE(
    "a microsurface mapping whose axes are not perpendicular, not of equal length or not in the plane is an error")
{
    const std::string expected =
        "/surfaces/0/mapping: a microsurface needs a planar mapping whose u_axis and v_axis are perpendicular, of "
        "equal length and in the plane";
    struct Bad {
        const char* what;
        json u, v;
        const char* got;
    };
    const Bad bad[] = {
        {"not perpendicular",
         {1, 0, 0.3},
         {0, 0, 1},
         "got u_axis [1.0,0.0,0.3] and v_axis [0.0,0.0,1.0] on a plane of normal [0.0,1.0,0.0]"},
        {"not of equal length", {2, 0, 0}, {0, 0, 1}, "got u_axis [2.0,0.0,0.0] and v_axis [0.0,0.0,1.0]"},
        {"not in the plane", {1, 0, 0}, {0, 0.6, 0.8}, "got u_axis [1.0,0.0,0.0] and v_axis [0.0,0.6,0.8]"},
    };
    for (const Bad& b : bad) {
        CAPTURE(b.what);
        json scene = microsurface_scene();
        scene["surfaces"][0]["mapping"]["u_axis"] = b.u;
        scene["surfaces"][0]["mapping"]["v_axis"] = b.v;
        const std::string error = error_of(scene);
        CHECK(starts_with(error, expected));
        CHECK(contains(error, b.got));
    }
    // The same axes with a driver are a valid texture mapping: the rule is the microsurface's.
    json scene = microsurface_scene();
    scene["surfaces"][0]["mapping"]["u_axis"] = {1, 0, 0.3};
    scene["surfaces"][0]["material"].erase("microsurface");
    scene["surfaces"][0]["material"]["driver"] = {{"noise", "gradient"}};
    CHECK(error_of(scene) == "(parsed)");
}
