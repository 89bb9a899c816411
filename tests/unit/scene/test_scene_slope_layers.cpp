// SPDX-License-Identifier: Apache-2.0
// Scene files with a layered microsurface material (sec. 5.2 slope colour,
// sec. 6 combinations): slope_colormap (by steepness or by slope vector),
// base (a colour map over its own driver) and combine (a weighted sum or a
// product), each key read to its exact value and default, each bad input
// refused with a message naming the scene, the JSON pointer of the offending
// value and what was expected; and prepare_materials on a scene with all
// three layers. Scenes are parsed from text as if they stood in
// examples/scenes/, so that ../../luts/... are the real maps.
#include "cmfilter/color/color_config.h"
#include "cmfilter/scene/scene_loading.h"
#include "cmfilter/scene/scene_materials.h"

#include "slope_layer_test_support.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <variant>
#include <vector>

using namespace cmfilter;
using namespace cmfilter_test;
using nlohmann::json;

namespace {

const std::string kScenePath = std::string(CMFILTER_SOURCE_DIR) + "/examples/scenes/slope-layers-test.json";
const std::string kMaterial = "/surfaces/0/material";

// One plane whose microsurface is coloured by its steepness alone.
json slope_scene()
{
    return json::parse(R"({
      "camera": {"position": [0, 1.2, 0], "look_at": [0, 0.55, 6], "resolution": [32, 24]},
      "light": {"direction": [0.5, 0.45, 1]},
      "surfaces": [
        {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
         "mapping": {"type": "planar", "u_axis": [1, 0, 0], "v_axis": [0, 0, 1]},
         "material": {
           "slope_colormap": {"image": "../../luts/grass-rock.png", "by": "steepness"},
           "microsurface": {"sigma_h": 0.008, "min_wavelength": 0.05, "max_wavelength": 0.4}}}
      ]})");
}

json& material(json& scene) { return scene["surfaces"][0]["material"]; }

json height_colormap() { return json::parse(R"({"image": "../../luts/sand-snow.png", "domain": [-0.03, 0.03]})"); }

// A base layer over the bundled fBm, with the sigma table baked for it (no
// bake in process).
json base_layer()
{
    return json::parse(R"({"colormap": {"image": "../../luts/terrain.png", "domain": [-0.7, 0.7]},
                           "driver": {"noise": "fbm:base=gradient,octaves=6", "sigma_table": "fbm-gradient-6.exr"}})");
}

// All three layers, summed with the given weights.
json three_layer_scene()
{
    json scene = slope_scene();
    material(scene)["colormap"] = height_colormap();
    material(scene)["base"] = base_layer();
    material(scene)["combine"] =
        json::parse(R"({"mode": "sum", "weights": {"base": 0.25, "height": 0.5, "slope": 1.5}})");
    return scene;
}

Expected<Scene> parse(const json& scene, const std::string& path = kScenePath)
{
    return parse_scene(scene.dump(2), path);
}

const MaterialSource& loaded_material(const Expected<Scene>& scene)
{
    REQUIRE_MESSAGE(scene, (scene ? "" : scene.error().message));
    REQUIRE(scene->surfaces.size() == 1);
    return scene->surfaces[0].material;
}

std::string error_of(const json& scene) { return bad_input_after_path(parse(scene), kScenePath); }

const std::string kLuts = std::string(CMFILTER_SOURCE_DIR) + "/examples/scenes/../../luts/";

}  // namespace

// ---- valid layers ---------------------------------------------------------------

TEST_CASE("a steepness slope map loads with its image and the defaults domain 0 to 90 degrees, clamp, no colour space")
{
    const json scene = slope_scene();
    const auto loaded = parse(scene);
    const MaterialSource& m = loaded_material(loaded);
    REQUIRE(m.slope_colormap.has_value());
    const SlopeColorMapSource& s = *m.slope_colormap;
    CHECK(s.kind == SlopeMapKind::Steepness);
    CHECK(s.image_path == kLuts + "grass-rock.png");
    CHECK(s.domain_min == 0);
    CHECK(s.domain_max == 90);
    CHECK(s.wrap == WrapMode::Clamp);
    CHECK(s.colorspace.empty());
    CHECK_FALSE(m.has_colormap());
    CHECK_FALSE(m.base.has_value());
    // One layer: no combine needed, and the default sum of weight 1.
    CHECK(m.combine.mode == CombineMode::Sum);
    CHECK(m.combine.slope == 1);
}

TEST_CASE("a steepness slope map's domain, wrap and colour space are read exactly")
{
    json scene = slope_scene();
    material(scene)["slope_colormap"] = json::parse(
        R"({"image": "../../luts/grass-rock.png", "by": "steepness", "domain": [12.5, 61.25],
            "wrap": "mirror", "colorspace": "sRGB"})");
    const auto loaded = parse(scene);
    const SlopeColorMapSource& s = *loaded_material(loaded).slope_colormap;
    CHECK(s.kind == SlopeMapKind::Steepness);
    CHECK(s.domain_min == 12.5);
    CHECK(s.domain_max == 61.25);
    CHECK(s.wrap == WrapMode::Mirror);
    CHECK(s.colorspace == "sRGB");
}

TEST_CASE("a slope-vector map is read with its max_slope and colour space")
{
    json scene = slope_scene();
    material(scene)["slope_colormap"] = json::parse(
        R"({"image": "../../luts/slope-wheel.png", "by": "vector", "max_slope": 1.75, "colorspace": "sRGB"})");
    const auto loaded = parse(scene);
    const SlopeColorMapSource& s = *loaded_material(loaded).slope_colormap;
    CHECK(s.kind == SlopeMapKind::Vector);
    CHECK(s.image_path == kLuts + "slope-wheel.png");
    CHECK(s.max_slope == 1.75);
    CHECK(s.colorspace == "sRGB");
}

TEST_CASE("a three-layer material reads its base layer and the weights of its sum exactly")
{
    const json scene = three_layer_scene();
    const auto loaded = parse(scene);
    const MaterialSource& m = loaded_material(loaded);
    CHECK(m.has_colormap());
    CHECK(m.colormap.image_path == kLuts + "sand-snow.png");
    CHECK(m.colormap.domain_min == -0.03);
    CHECK(m.colormap.domain_max == 0.03);
    REQUIRE(m.base.has_value());
    CHECK(m.base->colormap.image_path == kLuts + "terrain.png");
    CHECK(m.base->colormap.domain_min == -0.7);
    CHECK(m.base->colormap.domain_max == 0.7);
    CHECK(m.base->driver.kind == DriverKind::Noise);
    CHECK(m.base->driver.noise_spec == "fbm:base=gradient,octaves=6");
    CHECK(m.base->driver.sigma_table_path == std::string(CMFILTER_SOURCE_DIR) + "/examples/scenes/fbm-gradient-6.exr");
    CHECK(m.combine.mode == CombineMode::Sum);
    CHECK(m.combine.base == 0.25);
    CHECK(m.combine.height == 0.5);
    CHECK(m.combine.slope == 1.5);
}

TEST_CASE("a product takes no weights, and a weight of 0 is allowed in a sum")
{
    json scene = three_layer_scene();
    material(scene)["combine"] = json::parse(R"({"mode": "product"})");
    const auto product = parse(scene);
    CHECK(loaded_material(product).combine.mode == CombineMode::Product);

    scene = slope_scene();
    material(scene)["base"] = base_layer();
    material(scene)["combine"] = json::parse(R"({"mode": "sum", "weights": {"base": 0, "slope": 2}})");
    const auto sum = parse(scene);
    const ColorCombination& c = loaded_material(sum).combine;
    CHECK(c.mode == CombineMode::Sum);
    CHECK(c.base == 0);
    CHECK(c.slope == 2);
}

TEST_CASE("a base layer alone is a microsurface material of its own, its driver an image")
{
    json scene = slope_scene();
    material(scene).erase("slope_colormap");
    material(scene)["base"] = json::parse(R"({"colormap": {"image": "../../luts/terrain.png", "domain": [0, 1]},
                                              "driver": {"image": "snake-scales.exr"}})");
    const auto loaded = parse(scene);
    const MaterialSource& m = loaded_material(loaded);
    REQUIRE(m.base.has_value());
    CHECK_FALSE(m.slope_colormap.has_value());
    CHECK(m.base->driver.kind == DriverKind::Image);
    CHECK(m.base->driver.image_path == std::string(CMFILTER_SOURCE_DIR) + "/examples/scenes/snake-scales.exr");
}

// ---- bad layers -----------------------------------------------------------------

TEST_CASE("two layers without combine is an error naming /material/combine and both forms")
{
    json scene = slope_scene();
    material(scene)["colormap"] = height_colormap();
    const std::string error = error_of(scene);
    CHECK(starts_with(error, kMaterial + "/combine: required with more than one of colormap, slope_colormap and base"));
    CHECK(contains(error, R"({"mode": "sum", "weights": {...}})"));
    CHECK(contains(error, R"({"mode": "product"})"));

    scene = slope_scene();
    material(scene)["base"] = base_layer();
    CHECK(starts_with(error_of(scene), kMaterial + "/combine: required with more than one"));
}

TEST_CASE("a weight for a layer the material lacks is an error naming the weight and the layer")
{
    json scene = slope_scene();
    material(scene)["colormap"] = height_colormap();
    material(scene)["combine"] = json::parse(R"({"mode": "sum", "weights": {"height": 1, "slope": 1, "base": 1}})");
    CHECK(error_of(scene) == kMaterial + "/combine/weights/base: the material has no base to weigh");

    scene = slope_scene();
    material(scene)["base"] = base_layer();
    material(scene)["combine"] = json::parse(R"({"mode": "sum", "weights": {"base": 1, "slope": 1, "height": 1}})");
    CHECK(error_of(scene) == kMaterial + "/combine/weights/height: the material has no colormap to weigh");

    scene = slope_scene();
    material(scene).erase("slope_colormap");
    material(scene)["colormap"] = height_colormap();
    material(scene)["base"] = base_layer();
    material(scene)["combine"] = json::parse(R"({"mode": "sum", "weights": {"base": 1, "height": 1, "slope": 1}})");
    CHECK(error_of(scene) == kMaterial + "/combine/weights/slope: the material has no slope_colormap to weigh");
}

TEST_CASE("a missing weight, a negative one and a sum without weights are errors naming the key")
{
    json scene = three_layer_scene();
    material(scene)["combine"]["weights"].erase("slope");
    CHECK(error_of(scene) == kMaterial + "/combine/weights/slope: required key is missing");

    scene = three_layer_scene();
    material(scene)["combine"]["weights"].erase("base");
    CHECK(error_of(scene) == kMaterial + "/combine/weights/base: required key is missing");

    scene = three_layer_scene();
    material(scene)["combine"]["weights"]["height"] = -0.5;
    CHECK(error_of(scene) == kMaterial + "/combine/weights/height: expected a number >= 0, got -0.5");

    scene = three_layer_scene();
    material(scene)["combine"]["weights"]["base"] = "1";
    CHECK(error_of(scene) == kMaterial + "/combine/weights/base: expected a number, got \"1\"");

    scene = three_layer_scene();
    material(scene)["combine"].erase("weights");
    CHECK(error_of(scene) == kMaterial + "/combine/weights: required key is missing");
}

TEST_CASE("a product with weights, an unknown mode and a missing mode are errors")
{
    json scene = three_layer_scene();
    material(scene)["combine"]["mode"] = "product";
    CHECK(error_of(scene) == kMaterial + "/combine/weights: applies only to a sum (a product has no weights)");

    scene = three_layer_scene();
    material(scene)["combine"]["mode"] = "max";
    CHECK(error_of(scene) == kMaterial + "/combine/mode: expected \"sum\" or \"product\", got \"max\"");

    scene = three_layer_scene();
    material(scene)["combine"].erase("mode");
    CHECK(error_of(scene) == kMaterial + "/combine/mode: required key is missing");
}

TEST_CASE("max_slope on a steepness map and domain or wrap on a vector map are errors naming the key")
{
    json scene = slope_scene();
    material(scene)["slope_colormap"]["max_slope"] = 1;
    CHECK(error_of(scene) ==
          kMaterial + "/slope_colormap/max_slope: applies only to a slope-vector map (\"by\": \"vector\")");

    scene = slope_scene();
    material(scene)["slope_colormap"] =
        json::parse(R"({"image": "../../luts/slope-wheel.png", "by": "vector", "max_slope": 1, "domain": [0, 45]})");
    CHECK(starts_with(error_of(scene),
                      kMaterial + "/slope_colormap/domain: applies only to a steepness map (\"by\": \"steepness\")"));

    scene = slope_scene();
    material(scene)["slope_colormap"] =
        json::parse(R"({"image": "../../luts/slope-wheel.png", "by": "vector", "max_slope": 1, "wrap": "repeat"})");
    CHECK(starts_with(error_of(scene),
                      kMaterial + "/slope_colormap/wrap: applies only to a steepness map (\"by\": \"steepness\")"));
}

TEST_CASE("a vector map without max_slope or with max_slope <= 0 is an error")
{
    json scene = slope_scene();
    material(scene)["slope_colormap"] = json::parse(R"({"image": "../../luts/slope-wheel.png", "by": "vector"})");
    CHECK(error_of(scene) == kMaterial + "/slope_colormap/max_slope: required key is missing");
    for (const json bad : {json(0), json(-1.5)}) {
        CAPTURE(bad.dump());
        material(scene)["slope_colormap"]["max_slope"] = bad;
        CHECK(error_of(scene) == kMaterial + "/slope_colormap/max_slope: expected a number > 0, got " + bad.dump());
    }
}

TEST_CASE("an unknown or missing by, a missing image and an empty steepness domain are errors")
{
    json scene = slope_scene();
    material(scene)["slope_colormap"]["by"] = "aspect";
    CHECK(error_of(scene) == kMaterial + "/slope_colormap/by: expected \"steepness\" or \"vector\", got \"aspect\"");

    scene = slope_scene();
    material(scene)["slope_colormap"].erase("by");
    CHECK(error_of(scene) == kMaterial + "/slope_colormap/by: required key is missing");

    scene = slope_scene();
    material(scene)["slope_colormap"].erase("image");
    CHECK(error_of(scene) == kMaterial + "/slope_colormap/image: required key is missing");

    scene = slope_scene();
    material(scene)["slope_colormap"]["domain"] = {60, 30};
    CHECK(error_of(scene) == kMaterial + "/slope_colormap/domain: expected [min, max] with min < max, got [60,30]");

    scene = slope_scene();
    material(scene)["slope_colormap"]["image"] = "no-such-slope-map.png";
    const std::string error = error_of(scene);
    CHECK(starts_with(error, kMaterial + "/slope_colormap/image: file not found: "));
    CHECK(contains(error, "no-such-slope-map.png"));
}

TEST_CASE("slope_colormap, base and combine on a driven material are errors naming the key")
{
    const json driven = json::parse(R"({"colormap": {"image": "../../luts/terrain.png", "domain": [-0.7, 0.7]},
                                        "driver": {"noise": "fbm:base=gradient,octaves=6"}})");
    const std::string why = ": needs a microsurface (a driven material has its colormap alone)";
    json scene = slope_scene();
    material(scene) = driven;
    CHECK(error_of(scene) == "(parsed)");  // the driven material itself is fine
    material(scene)["slope_colormap"] = json::parse(R"({"image": "../../luts/grass-rock.png", "by": "steepness"})");
    CHECK(error_of(scene) == kMaterial + "/slope_colormap" + why);

    material(scene) = driven;
    material(scene)["base"] = base_layer();
    CHECK(error_of(scene) == kMaterial + "/base" + why);

    material(scene) = driven;
    material(scene)["combine"] = json::parse(R"({"mode": "product"})");
    CHECK(error_of(scene) == kMaterial + "/combine" + why);
}

TEST_CASE("a microsurface with no layer at all is an error naming the material and the three layers")
{
    json scene = slope_scene();
    material(scene).erase("slope_colormap");
    CHECK(error_of(scene) ==
          kMaterial + ": a microsurface or displacement material needs at least one of colormap (over heights), "
                      "slope_colormap and base");
    // combine alone is no layer either.
    material(scene)["combine"] = json::parse(R"({"mode": "product"})");
    CHECK(starts_with(error_of(scene), kMaterial + ": a microsurface or displacement material needs at least one of"));
}

TEST_CASE("a tolerance inside the base layer's colour map is an error naming it, and base keys are checked")
{
    json scene = three_layer_scene();
    material(scene)["base"]["colormap"]["tolerance"] = 1;
    const std::string error = error_of(scene);
    CHECK(
        starts_with(error, kMaterial + "/base/colormap/tolerance: a base layer's colour map takes the default table"));

    scene = three_layer_scene();
    material(scene)["base"].erase("driver");
    CHECK(error_of(scene) == kMaterial + "/base/driver: required key is missing");

    scene = three_layer_scene();
    material(scene)["base"].erase("colormap");
    CHECK(error_of(scene) == kMaterial + "/base/colormap: required key is missing");

    scene = three_layer_scene();
    material(scene)["base"]["weight"] = 1;
    CHECK(starts_with(error_of(scene), kMaterial + "/base/weight: unknown key (expected one of colormap, driver)"));
}

// ---- prepared materials ---------------------------------------------------------

TEST_CASE("prepare_materials gives a three-layer material its base noise, its steepness map and its height map")
{
    const auto scene = parse(three_layer_scene());
    REQUIRE_MESSAGE(scene, (scene ? "" : scene.error().message));
    const std::vector<Material> materials = prepared_materials(*scene, 2);
    REQUIRE(materials.size() == 1);
    REQUIRE(std::holds_alternative<MicrosurfaceDriver>(materials[0].driver));
    const MicrosurfaceDriver& m = std::get<MicrosurfaceDriver>(materials[0].driver);
    CHECK(m.colors.height.has_value());
    REQUIRE(m.colors.height);
    CHECK(m.colors.height->map.vmin == -0.03);
    CHECK(m.colors.height->map.vmax == 0.03);
    REQUIRE(m.colors.slope.has_value());
    REQUIRE(std::holds_alternative<SteepnessColorMap>(*m.colors.slope));
    const ColorMap& by_angle = std::get<SteepnessColorMap>(*m.colors.slope).by_angle;
    CHECK(by_angle.vmin == 0);
    CHECK(by_angle.vmax == 90);
    CHECK(materials[0].provenance.slope_map_path == kLuts + "grass-rock.png");
    REQUIRE(m.base != nullptr);
    CHECK(std::holds_alternative<NoiseDriver>(m.base->driver));
    CHECK_FALSE(std::holds_alternative<TextureDriver>(m.base->driver));
    CHECK_FALSE(std::holds_alternative<MicrosurfaceDriver>(m.base->driver));
    CHECK(m.base->color.map.vmin == -0.7);
    CHECK(m.base->color.map.vmax == 0.7);
    CHECK(m.colors.combine.mode == CombineMode::Sum);
    CHECK(m.colors.combine.base == 0.25);
    CHECK(m.colors.combine.height == 0.5);
    CHECK(m.colors.combine.slope == 1.5);
}

TEST_CASE("prepare_materials gives a vector slope map its max_slope, and no height map without a colormap")
{
    json text = slope_scene();
    material(text)["slope_colormap"] =
        json::parse(R"({"image": "../../luts/slope-wheel.png", "by": "vector", "max_slope": 1.25})");
    const auto scene = parse(text);
    REQUIRE_MESSAGE(scene, (scene ? "" : scene.error().message));
    const std::vector<Material> materials = prepared_materials(*scene, 1);
    REQUIRE(materials.size() == 1);
    REQUIRE(std::holds_alternative<MicrosurfaceDriver>(materials[0].driver));
    const MicrosurfaceDriver& m = std::get<MicrosurfaceDriver>(materials[0].driver);
    CHECK_FALSE(m.colors.height.has_value());
    CHECK(m.base == nullptr);
    REQUIRE(m.colors.slope.has_value());
    REQUIRE(std::holds_alternative<SlopeVectorColorMap>(*m.colors.slope));
    const SlopeVectorColorMap& v = std::get<SlopeVectorColorMap>(*m.colors.slope);
    CHECK(v.s_max == 1.25);
    CHECK(v.width > 0);
    CHECK(v.height > 0);
    CHECK(v.texels.size() == static_cast<std::size_t>(v.width) * static_cast<std::size_t>(v.height));
}

TEST_CASE("prepare_materials refuses a slope map image gone since loading, naming /material/slope_colormap")
{
    namespace fs = std::filesystem;
    const fs::path folder = fs::temp_directory_path() / ("cmfilter-slope-gone-" + std::to_string(::getpid()));
    fs::create_directories(folder);
    const fs::path image = folder / "slope.png";
    fs::copy_file(std::string(CMFILTER_SOURCE_DIR) + "/luts/grass-rock.png", image,
                  fs::copy_options::overwrite_existing);
    json text = slope_scene();
    material(text)["slope_colormap"]["image"] = "slope.png";
    const std::string path = (folder / "scene.json").string();
    const auto scene = parse(text, path);
    REQUIRE_MESSAGE(scene, (scene ? "" : scene.error().message));
    fs::remove(image);
    auto config = ColorConfig::load("");
    REQUIRE(config);
    MaterialOptions options;
    options.threads = 1;
    auto materials = prepare_materials(*scene, *config, options);
    fs::remove_all(folder);
    REQUIRE_FALSE(materials);
    CHECK(materials.error().kind == ErrorKind::Io);
    const std::string& message = materials.error().message;
    CHECK(starts_with(message, path + ": /surfaces/0/material/slope_colormap: "));
    CHECK(contains(message, "slope.png"));
}
