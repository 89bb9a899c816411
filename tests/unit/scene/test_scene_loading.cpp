// SPDX-License-Identifier: Apache-2.0
// Scene files (docs/scene-format.md): a full scene read to the exact values,
// the defaults, and one test per bad input, each checking that the message
// names the file, the JSON path of the offending value and what was expected.
#include "cmfilter/scene/scene_loading.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

using namespace cmfilter;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

void write_file(const fs::path& path, const std::string& text)
{
    std::ofstream out(path, std::ios::binary);
    out << text;
    REQUIRE(out.good());
}

// A fresh folder under the system's temporary folder holding the files the
// documented scenes refer to, removed with everything in it at the end:
//     scenes/scene.json (where parse() says the scene is), scenes/fbm-sigma.exr,
//     scenes/terrain-table.exr, scenes/driver-moments.exr, luts/terrain.png
// The files are empty: the loader only checks that they exist.
class SceneFolder {
public:
    SceneFolder()
    {
        std::random_device random;
        root_ = fs::temp_directory_path() /
                ("cmfilter-scene-test-" + std::to_string(random()) + "-" + std::to_string(random()));
        fs::create_directories(root_ / "scenes");
        fs::create_directories(root_ / "luts");
        for (const char* name : {"scenes/fbm-sigma.exr", "scenes/terrain-table.exr", "scenes/driver-moments.exr",
                                 "scenes/driver.png", "luts/terrain.png"})
            write_file(root_ / name, "");
    }
    ~SceneFolder()
    {
        std::error_code ec;
        fs::remove_all(root_, ec);
    }
    SceneFolder(const SceneFolder&) = delete;
    SceneFolder& operator=(const SceneFolder&) = delete;

    const fs::path& root() const { return root_; }
    std::string scene_path() const { return (root_ / "scenes" / "scene.json").string(); }
    // What the loader stores for a name relative to the scene's folder.
    std::string resolved(const std::string& name) const { return (root_ / "scenes" / name).string(); }

    Expected<Scene> parse(const json& scene) const { return parse_scene(scene.dump(2), scene_path()); }
    Expected<Scene> parse_text(const std::string& text) const { return parse_scene(text, scene_path()); }

    // The message of the error parsing `scene` gives (a BadInput), or "(parsed)".
    std::string error_of(const json& scene) const { return error_of_result(parse(scene)); }
    std::string error_of_text(const std::string& text) const { return error_of_result(parse_text(text)); }

    // `message` as "<scene path>: <rest>"; rest, or "(not prefixed)".
    std::string after_scene_path(const std::string& message) const
    {
        const std::string prefix = scene_path() + ": ";
        return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : "(not prefixed) " + message;
    }

private:
    static std::string error_of_result(const Expected<Scene>& scene)
    {
        if (scene) return "(parsed)";
        CHECK(scene.error().kind == ErrorKind::BadInput);
        return scene.error().message;
    }

    fs::path root_;
};

// The `index`-th ```json block of docs/scene-format.md, so that the
// documented scenes are the ones tested: 0 is the example, 1 the smallest.
json documented_scene(int index)
{
    std::ifstream in(fs::path(CMFILTER_SOURCE_DIR) / "docs" / "scene-format.md");
    REQUIRE(in);
    std::string line, block;
    int found = -1;
    bool inside = false;
    while (std::getline(in, line)) {
        if (!inside && line == "```json") inside = ++found == index;
        else if (inside && line == "```") break;
        else if (inside) block += line + "\n";
    }
    REQUIRE_MESSAGE(!block.empty(), "docs/scene-format.md has no json block " << index);
    return json::parse(block);
}

json example_scene() { return documented_scene(0); }
json minimal_scene() { return documented_scene(1); }

void check_vec3(const Vec3& v, double x, double y, double z)
{
    CHECK(v.x == doctest::Approx(x).epsilon(1e-15));
    CHECK(v.y == doctest::Approx(y).epsilon(1e-15));
    CHECK(v.z == doctest::Approx(z).epsilon(1e-15));
}

}  // namespace

// ---- valid scenes -------------------------------------------------------------

TEST_CASE("the example scene loads to its exact values, directions normalised, paths beside the scene")
{
    SceneFolder folder;
    json text = example_scene();
    text["surfaces"][0]["normal"] = {0, 3, 4};  // a non-unit normal, normalised on load
    write_file(folder.scene_path(), text.dump(2));
    auto loaded = load_scene(folder.scene_path());
    REQUIRE_MESSAGE(loaded, (loaded ? "" : loaded.error().message));
    const Scene& scene = *loaded;
    CHECK(scene.path == folder.scene_path());

    CHECK(scene.camera.position == Vec3{0, 1.5, 0});
    CHECK(scene.camera.look_at == Vec3{0, 0, 20});
    CHECK(scene.camera.up == Vec3{0, 1, 0});
    CHECK(scene.camera.fov_degrees == 50);
    CHECK(scene.camera.width == 640);
    CHECK(scene.camera.height == 360);

    const double light_length = std::sqrt(0.3 * 0.3 + 1 + 0.2 * 0.2);
    check_vec3(scene.light.direction, 0.3 / light_length, 1 / light_length, -0.2 / light_length);
    CHECK(length(scene.light.direction) == doctest::Approx(1).epsilon(1e-15));
    CHECK((scene.light.radiance.r == 1 && scene.light.radiance.g == 1 && scene.light.radiance.b == 1));
    CHECK((scene.light.ambient.r == 0.05 && scene.light.ambient.g == 0.05 && scene.light.ambient.b == 0.05));
    CHECK((scene.background.r == 0.6 && scene.background.g == 0.7 && scene.background.b == 0.9));

    REQUIRE(scene.surfaces.size() == 2);
    const Surface& plane = scene.surfaces[0];
    CHECK(plane.kind == SurfaceKind::Plane);
    CHECK(plane.point == Vec3{0, 0, 0});
    check_vec3(plane.normal, 0, 0.6, 0.8);
    CHECK(plane.mapping.kind == MappingKind::Planar);
    CHECK(plane.mapping.origin == Vec3{0, 0, 0});
    CHECK(plane.mapping.u_axis == Vec3{1, 0, 0});
    CHECK(plane.mapping.v_axis == Vec3{0, 0, 1});
    const ColorMapSource& map = plane.material.colormap;
    CHECK(map.table_path.empty());
    CHECK(map.image_path == folder.resolved("../luts/terrain.png"));
    CHECK(fs::equivalent(map.image_path, folder.root() / "luts" / "terrain.png"));
    CHECK(map.domain_min == -0.7);
    CHECK(map.domain_max == 0.7);
    CHECK(map.wrap == WrapMode::Clamp);
    CHECK(map.colorspace == "sRGB");
    const DriverSource& noise = plane.material.driver;
    CHECK(noise.kind == DriverKind::Noise);
    CHECK(noise.noise_spec == "fbm:base=gradient,octaves=6");
    CHECK(noise.sigma_table_path == folder.resolved("fbm-sigma.exr"));
    CHECK(noise.moments_path.empty());
    CHECK(noise.image_path.empty());

    const Surface& sphere = scene.surfaces[1];
    CHECK(sphere.kind == SurfaceKind::Sphere);
    CHECK(sphere.center == Vec3{0, 1, 8});
    CHECK(sphere.radius == 1);
    CHECK(sphere.mapping.kind == MappingKind::Spherical);
    CHECK(sphere.mapping.u_scale == 8);
    CHECK(sphere.mapping.v_scale == 4);
    CHECK(sphere.material.colormap.table_path == folder.resolved("terrain-table.exr"));
    CHECK(sphere.material.colormap.image_path.empty());
    CHECK(sphere.material.driver.kind == DriverKind::Moments);
    CHECK(sphere.material.driver.moments_path == folder.resolved("driver-moments.exr"));
}

TEST_CASE("optional keys take the defaults of scene.h")
{
    SceneFolder folder;
    json text = minimal_scene();
    text["surfaces"].push_back(json::parse(R"({"type": "plane", "point": [0, -1, 0], "normal": [0, 1, 0],
        "material": {"colormap": {"image": "../luts/terrain.png", "domain": [0, 1]},
                     "driver": {"noise": "gradient"}}})"));
    auto scene = folder.parse(text);
    REQUIRE_MESSAGE(scene, (scene ? "" : scene.error().message));
    const SceneCamera defaults;
    CHECK(scene->camera.up == defaults.up);
    CHECK(scene->camera.fov_degrees == defaults.fov_degrees);
    CHECK(scene->camera.width == defaults.width);
    CHECK(scene->camera.height == defaults.height);
    const SceneLight light;
    CHECK(scene->light.direction == light.direction);
    CHECK((scene->light.radiance.r == light.radiance.r && scene->light.radiance.b == light.radiance.b));
    CHECK((scene->light.ambient.r == 0 && scene->light.ambient.g == 0 && scene->light.ambient.b == 0));
    CHECK((scene->background.r == 0 && scene->background.g == 0 && scene->background.b == 0));

    REQUIRE(scene->surfaces.size() == 2);
    const Surface& sphere = scene->surfaces[0];
    CHECK(sphere.mapping.kind == MappingKind::Spherical);
    CHECK(sphere.mapping.u_scale == 1);
    CHECK(sphere.mapping.v_scale == 1);
    CHECK(sphere.material.driver.kind == DriverKind::Image);
    CHECK(sphere.material.driver.image_path == folder.resolved("driver.png"));

    const Surface& plane = scene->surfaces[1];
    CHECK(plane.mapping.kind == MappingKind::Planar);
    CHECK(plane.mapping.origin == Vec3{0, 0, 0});
    CHECK(plane.mapping.u_axis == Vec3{1, 0, 0});
    CHECK(plane.mapping.v_axis == Vec3{0, 0, 1});
    CHECK(plane.material.colormap.wrap == WrapMode::Clamp);
    CHECK(plane.material.colormap.colorspace.empty());
    CHECK(plane.material.driver.kind == DriverKind::Noise);
    CHECK(plane.material.driver.sigma_table_path.empty());
}

TEST_CASE("a mapping without a type takes the surface's default kind")
{
    SceneFolder folder;
    json text = minimal_scene();
    text["surfaces"][0]["mapping"] = {{"v_scale", 3}};
    auto scene = folder.parse(text);
    REQUIRE_MESSAGE(scene, (scene ? "" : scene.error().message));
    CHECK(scene->surfaces[0].mapping.kind == MappingKind::Spherical);
    CHECK(scene->surfaces[0].mapping.u_scale == 1);
    CHECK(scene->surfaces[0].mapping.v_scale == 3);
}

TEST_CASE("an absolute referenced path is kept as it is")
{
    SceneFolder folder;
    json text = minimal_scene();
    const std::string table = (folder.root() / "luts" / "terrain.png").string();
    text["surfaces"][0]["material"]["colormap"]["table"] = table;
    auto scene = folder.parse(text);
    REQUIRE_MESSAGE(scene, (scene ? "" : scene.error().message));
    CHECK(scene->surfaces[0].material.colormap.table_path == table);
}

// ---- the file and its JSON -----------------------------------------------------

TEST_CASE("a scene file that does not exist is an I/O error naming it")
{
    SceneFolder folder;
    auto scene = load_scene(folder.scene_path());
    REQUIRE_FALSE(scene);
    CHECK(scene.error().kind == ErrorKind::Io);
    CHECK(scene.error().message == folder.scene_path() + ": cannot read the scene: no such file");
}

TEST_CASE("malformed JSON is reported with its line and column")
{
    SceneFolder folder;
    const std::string message = folder.error_of_text("{\n  \"camera\": {\n    \"position\": [0, 1, 0],,\n");
    // Line 3 is `    "position": [0, 1, 0],,`: the second comma, column 27, is where it stops.
    CHECK(folder.after_scene_path(message).rfind("malformed JSON at line 3, column 27 (byte ", 0) == 0);
    CHECK(contains(message, "syntax error"));
}

TEST_CASE("an empty scene file is malformed JSON at line 1, column 1")
{
    SceneFolder folder;
    CHECK(folder.after_scene_path(folder.error_of_text("")).rfind("malformed JSON at line 1, column 1 (byte 1)", 0) ==
          0);
}

TEST_CASE("a number too large for a double is malformed JSON")
{
    SceneFolder folder;
    json text = minimal_scene();
    std::string body = text.dump();
    body.replace(body.find("\"radius\":2"), 10, "\"radius\":1e400");
    const std::string message = folder.error_of_text(body);
    CHECK(folder.after_scene_path(message).rfind("malformed JSON: ", 0) == 0);
    CHECK(contains(message, "1e400"));
}

TEST_CASE("a key given twice in one object is an error naming its path")
{
    SceneFolder folder;
    const std::string body = minimal_scene().dump();
    std::string twice = body;
    twice.replace(twice.find("\"radius\":2"), 10, "\"radius\":2,\"radius\":3");
    CHECK(folder.after_scene_path(folder.error_of_text(twice)) == "/surfaces/0/radius: key given twice in one object");
}

TEST_CASE("a scene that is not a JSON object is an error at the root")
{
    SceneFolder folder;
    CHECK(folder.after_scene_path(folder.error_of(json::array({1, 2}))) == "(root): expected an object, got [1,2]");
}

// ---- keys and types --------------------------------------------------------------

TEST_CASE("an unknown top-level key is an error listing the known ones")
{
    SceneFolder folder;
    json text = minimal_scene();
    text["lights"] = json::object();
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/lights: unknown key (expected one of camera, light, background, surfaces)");
}

TEST_CASE("an unknown nested key is an error listing the known ones")
{
    SceneFolder folder;
    json text = minimal_scene();
    text["camera"]["fovv"] = 40;
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/camera/fovv: unknown key (expected one of position, look_at, up, fov_degrees, resolution)");
}

TEST_CASE("a key of the other surface kind is unknown")
{
    SceneFolder folder;
    json text = minimal_scene();
    text["surfaces"][0]["normal"] = {0, 1, 0};
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/surfaces/0/normal: unknown key (expected one of type, center, radius, mapping, material)");
}

TEST_CASE("a value of the wrong JSON type is an error naming the type expected")
{
    SceneFolder folder;
    json text = minimal_scene();
    text["camera"] = json::array({0, 0, 0});
    CHECK(folder.after_scene_path(folder.error_of(text)) == "/camera: expected an object, got [0,0,0]");
}

TEST_CASE("a string where a number is expected is an error at the element")
{
    SceneFolder folder;
    json text = minimal_scene();
    text["camera"]["position"] = {0, "NaN", 0};
    CHECK(folder.after_scene_path(folder.error_of(text)) == "/camera/position/1: expected a number, got \"NaN\"");
}

TEST_CASE("a vector of 2 numbers is an error")
{
    SceneFolder folder;
    json text = minimal_scene();
    text["surfaces"][0]["center"] = {0, 1};
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/surfaces/0/center: expected an array of 3 numbers, got [0,1]");
}

TEST_CASE("a missing camera is an error")
{
    SceneFolder folder;
    json text = minimal_scene();
    text.erase("camera");
    CHECK(folder.after_scene_path(folder.error_of(text)) == "/camera: required key is missing");
}

TEST_CASE("missing surfaces are an error")
{
    SceneFolder folder;
    json text = minimal_scene();
    text.erase("surfaces");
    CHECK(folder.after_scene_path(folder.error_of(text)) == "/surfaces: required key is missing");
}

TEST_CASE("a sphere without a radius is an error")
{
    SceneFolder folder;
    json text = minimal_scene();
    text["surfaces"][0].erase("radius");
    CHECK(folder.after_scene_path(folder.error_of(text)) == "/surfaces/0/radius: required key is missing");
}

TEST_CASE("an empty surfaces array is an error")
{
    SceneFolder folder;
    json text = minimal_scene();
    text["surfaces"] = json::array();
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/surfaces: expected a non-empty array of surfaces, got []");
}

TEST_CASE("an unknown surface type is an error")
{
    SceneFolder folder;
    json text = minimal_scene();
    text["surfaces"][0]["type"] = "cube";
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/surfaces/0/type: expected \"plane\" or \"sphere\", got \"cube\"");
}

// ---- camera ----------------------------------------------------------------------

TEST_CASE("a camera looking at its own position is an error")
{
    SceneFolder folder;
    json text = minimal_scene();
    text["camera"]["look_at"] = {0, 0, 0};
    const std::string message = folder.after_scene_path(folder.error_of(text));
    CHECK(message.rfind("/camera/look_at: expected a point other than position", 0) == 0);
    CHECK(contains(message, "view direction look_at - position is zero"));
}

TEST_CASE("a zero camera up vector is an error")
{
    SceneFolder folder;
    json text = minimal_scene();
    text["camera"]["up"] = {0, 0, 0};
    CHECK(folder.after_scene_path(folder.error_of(text)) == "/camera/up: expected a non-zero vector, got [0,0,0]");
}

TEST_CASE("a camera up vector parallel to the view direction is an error")
{
    SceneFolder folder;
    json text = minimal_scene();
    text["camera"]["up"] = {0, 0, -2};
    const std::string message = folder.after_scene_path(folder.error_of(text));
    CHECK(message.rfind("/camera/up: expected a vector not parallel to the view direction look_at - position", 0) == 0);
    CHECK(contains(message, "got [0.0,0.0,-2.0]"));
}

TEST_CASE("the default up vector parallel to the view direction is an error at up")
{
    SceneFolder folder;
    json text = minimal_scene();
    text["camera"]["look_at"] = {0, -1, 0};
    const std::string message = folder.after_scene_path(folder.error_of(text));
    CHECK(message.rfind("/camera/up: expected a vector not parallel", 0) == 0);
    CHECK(contains(message, "(the default)"));
}

TEST_CASE("a resolution of 0 is an error")
{
    SceneFolder folder;
    json text = minimal_scene();
    text["camera"]["resolution"] = {0, 360};
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/camera/resolution/0: expected a width in 1..16384 (an integer), got 0");
}

TEST_CASE("a resolution side above the limit is an error naming the limit")
{
    SceneFolder folder;
    json text = minimal_scene();
    text["camera"]["resolution"] = {640, kMaxImageSide + 1};
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/camera/resolution/1: expected a height in 1..16384 (an integer), got 16385");
}

TEST_CASE("a fractional resolution is an error")
{
    SceneFolder folder;
    json text = minimal_scene();
    text["camera"]["resolution"] = {640.5, 360};
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/camera/resolution/0: expected a width in 1..16384 (an integer), got 640.5");
}

TEST_CASE("a resolution above the pixel limit is an error naming the limit")
{
    SceneFolder folder;
    json text = minimal_scene();
    text["camera"]["resolution"] = {kMaxImageSide, kMaxImageSide / 2 + 1};
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/camera/resolution: expected width * height <= 67108864 pixels, got 16384 x 8193 = 134234112");
}

TEST_CASE("a field of view of 0 degrees is an error")
{
    SceneFolder folder;
    json text = minimal_scene();
    text["camera"]["fov_degrees"] = 0;
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/camera/fov_degrees: expected a number of degrees in (0, 180), got 0");
}

TEST_CASE("a field of view of 180 degrees is an error")
{
    SceneFolder folder;
    json text = minimal_scene();
    text["camera"]["fov_degrees"] = 180;
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/camera/fov_degrees: expected a number of degrees in (0, 180), got 180");
}

// ---- light and surfaces ----------------------------------------------------------

TEST_CASE("a zero light direction is an error")
{
    SceneFolder folder;
    json text = minimal_scene();
    text["light"] = {{"direction", {0, 0, 0}}};
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/light/direction: expected a non-zero vector, got [0,0,0]");
}

TEST_CASE("a negative colour is an error")
{
    SceneFolder folder;
    json text = minimal_scene();
    text["background"] = {0.5, -0.1, 0};
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/background: expected a colour of 3 numbers >= 0, got [0.5,-0.1,0]");
}

TEST_CASE("a negative sphere radius is an error")
{
    SceneFolder folder;
    json text = example_scene();
    text["surfaces"][1]["radius"] = -2;
    CHECK(folder.error_of(text) == folder.scene_path() + ": /surfaces/1/radius: expected a number > 0, got -2");
}

TEST_CASE("a zero plane normal is an error")
{
    SceneFolder folder;
    json text = example_scene();
    text["surfaces"][0]["normal"] = {0, 0, 0};
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/surfaces/0/normal: expected a non-zero vector, got [0,0,0]");
}

TEST_CASE("spherical mapping on a plane is an error")
{
    SceneFolder folder;
    json text = example_scene();
    text["surfaces"][0]["mapping"] = {{"type", "spherical"}};
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/surfaces/0/mapping/type: expected \"planar\" (spherical mapping needs a sphere), got \"spherical\"");
}

TEST_CASE("parallel planar mapping axes are an error")
{
    SceneFolder folder;
    json text = example_scene();
    text["surfaces"][0]["mapping"]["v_axis"] = {-2, 0, 0};
    const std::string message = folder.after_scene_path(folder.error_of(text));
    CHECK(message.rfind("/surfaces/0/mapping/v_axis: expected a vector not parallel to u_axis", 0) == 0);
}

TEST_CASE("a planar mapping whose axes are degenerate on its plane is an error")
{
    SceneFolder folder;
    json text = example_scene();
    text["surfaces"][0]["normal"] = {1, 0, 0};  // a wall: the default u = x is constant on it
    text["surfaces"][0].erase("mapping");
    const std::string message = folder.after_scene_path(folder.error_of(text));
    CHECK(message.rfind("/surfaces/0/mapping: expected u_axis and v_axis whose cross product is not parallel to "
                        "the plane",
                        0) == 0);
    CHECK(contains(message, "(the default mapping)"));
    text["surfaces"][0]["mapping"] = {{"u_axis", {0, 0, 1}}, {"v_axis", {0, 1, 0}}};
    CHECK(folder.error_of(text) == "(parsed)");
}

TEST_CASE("a planar mapping key on a spherical mapping is unknown")
{
    SceneFolder folder;
    json text = example_scene();
    text["surfaces"][1]["mapping"]["origin"] = {0, 0, 0};
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/surfaces/1/mapping/origin: unknown key (expected one of type, u_scale, v_scale)");
}

// ---- material ----------------------------------------------------------------------

TEST_CASE("a colour map with both table and image is an error")
{
    SceneFolder folder;
    json text = example_scene();
    text["surfaces"][1]["material"]["colormap"]["image"] = "../luts/terrain.png";
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/surfaces/1/material/colormap: expected exactly one of table or image, got table and image");
}

TEST_CASE("a colour map with neither table nor image is an error")
{
    SceneFolder folder;
    json text = example_scene();
    text["surfaces"][1]["material"]["colormap"] = json::object();
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/surfaces/1/material/colormap: expected exactly one of table or image, got none");
}

TEST_CASE("a table colour map with an image key is an error")
{
    SceneFolder folder;
    json text = example_scene();
    text["surfaces"][1]["material"]["colormap"]["wrap"] = "repeat";
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/surfaces/1/material/colormap/wrap: applies only to an image colour map, not to a table");
}

TEST_CASE("an image colour map takes a tolerance: a CIEDE2000 > 0, not beside a table")
{
    SceneFolder folder;
    json text = example_scene();
    auto plain = folder.parse(text);
    REQUIRE(plain);
    CHECK_FALSE(plain->surfaces[0].material.colormap.tolerance.has_value());
    text["surfaces"][0]["material"]["colormap"]["tolerance"] = 0.5;
    auto scene = folder.parse(text);
    REQUIRE(scene);
    REQUIRE(scene->surfaces[0].material.colormap.tolerance.has_value());
    CHECK(*scene->surfaces[0].material.colormap.tolerance == 0.5);
    text["surfaces"][0]["material"]["colormap"]["tolerance"] = 0;
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/surfaces/0/material/colormap/tolerance: expected a number > 0, got 0");
    text["surfaces"][0]["material"]["colormap"]["tolerance"] = "1";
    CHECK(contains(folder.error_of(text), "/surfaces/0/material/colormap/tolerance"));
    text = example_scene();
    text["surfaces"][1]["material"]["colormap"]["tolerance"] = 1;
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/surfaces/1/material/colormap/tolerance: applies only to an image colour map, not to a table");
    text = example_scene();
    text["surfaces"][0]["material"]["colormap"]["tolerence"] = 1;
    CHECK(contains(folder.error_of(text), "/surfaces/0/material/colormap/tolerence: unknown key"));
}

TEST_CASE("an image colour map without a domain is an error")
{
    SceneFolder folder;
    json text = example_scene();
    text["surfaces"][0]["material"]["colormap"].erase("domain");
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/surfaces/0/material/colormap/domain: required key is missing");
}

TEST_CASE("a domain with min >= max is an error")
{
    SceneFolder folder;
    json text = example_scene();
    text["surfaces"][0]["material"]["colormap"]["domain"] = {0.5, 0.5};
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/surfaces/0/material/colormap/domain: expected [min, max] with min < max, got [0.5,0.5]");
    text["surfaces"][0]["material"]["colormap"]["domain"] = {1, -1};
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/surfaces/0/material/colormap/domain: expected [min, max] with min < max, got [1,-1]");
}

TEST_CASE("an unknown wrap word is an error")
{
    SceneFolder folder;
    json text = example_scene();
    text["surfaces"][0]["material"]["colormap"]["wrap"] = "wrap-around";
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/surfaces/0/material/colormap/wrap: unknown wrap mode 'wrap-around' (expected clamp, repeat or mirror)");
}

TEST_CASE("a bad noise spec is an error quoting the noise spec parser")
{
    SceneFolder folder;
    json text = example_scene();
    text["surfaces"][0]["material"]["driver"]["noise"] = "fbm:base=simplex";
    const std::string message = folder.after_scene_path(folder.error_of(text));
    CHECK(message.rfind("/surfaces/0/material/driver/noise: expected a noise spec (docs/noise.md), got "
                        "\"fbm:base=simplex\": ",
                        0) == 0);
    CHECK(contains(message, "noise basis 'simplex' is unknown"));
}

TEST_CASE("a sigma table without a noise driver is an error")
{
    SceneFolder folder;
    json text = example_scene();
    text["surfaces"][1]["material"]["driver"]["sigma_table"] = "fbm-sigma.exr";
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/surfaces/1/material/driver/sigma_table: applies only to a noise driver, not to moments");
}

TEST_CASE("a segment pyramid beside a noise driver is an error, and beside moments must exist")
{
    SceneFolder folder;
    json text = example_scene();
    text["surfaces"][0]["material"]["driver"]["segments"] = "segments.exr";
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/surfaces/0/material/driver/segments: applies only to a texture driver (moments or image), not to a noise");
    text = example_scene();
    text["surfaces"][1]["material"]["driver"]["segments"] = "no-such-segments.exr";
    const std::string message = folder.after_scene_path(folder.error_of(text));
    CHECK(message.rfind("/surfaces/1/material/driver/segments: file not found: ", 0) == 0);
    CHECK(contains(message, "no-such-segments.exr"));
}

TEST_CASE("a driver with two sources is an error")
{
    SceneFolder folder;
    json text = example_scene();
    text["surfaces"][1]["material"]["driver"]["image"] = "driver.png";
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/surfaces/1/material/driver: expected exactly one of noise, moments or image, got moments and image");
}

TEST_CASE("a referenced file that does not exist is an error with its resolved path")
{
    SceneFolder folder;
    json text = example_scene();
    text["surfaces"][0]["material"]["driver"]["sigma_table"] = "missing-sigma.exr";
    CHECK(folder.error_of(text) == folder.scene_path() + ": /surfaces/0/material/driver/sigma_table: file not found: " +
                                       folder.resolved("missing-sigma.exr"));
}

TEST_CASE("a referenced path that is a folder is an error")
{
    SceneFolder folder;
    json text = example_scene();
    text["surfaces"][1]["material"]["colormap"]["table"] = "../luts";
    CHECK(folder.after_scene_path(folder.error_of(text)) ==
          "/surfaces/1/material/colormap/table: expected a file, got a directory: " + folder.resolved("../luts"));
}
