// SPDX-License-Identifier: Apache-2.0
// make_stack (make_stack.h): the files of one view slot read back by
// load_image_stack equal the images rendered in memory; the record gives
// back the options, and a ground-truth render under a subset of the lights
// reproduces those images exactly; several views write one slot per view
// and the manifest; the refusals (a noise-driven surface, too few lights, a
// view below the horizon) leave nothing.
#include "cmfilter/stack/btf_manifest.h"
#include "cmfilter/stack/image_stack.h"
#include "cmfilter/stack/light_file.h"
#include "cmfilter/synthetic/make_stack.h"
#include "cmfilter/synthetic/stack_record.h"
#include "cmfilter/synthetic/synthetic_stack.h"

#include "synthetic_test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace cmfilter;
using namespace cmfilter_test;
namespace fs = std::filesystem;

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string bumpy_scene(const std::string& dir)
{
    return write_displacement_scene(dir, "bumps", 32, [](int i, int j) {
        return 0.04 * std::sin(2 * kPi * (i + 0.5) / 32) * std::cos(4 * kPi * (j + 0.5) / 32);
    });
}

MakeStackOptions small_options(const std::string& scene, const std::string& output)
{
    MakeStackOptions o;
    o.scene = scene;
    o.output = output;
    o.size = 16;
    o.samples = 4;
    o.dome.kind = DomeKind::Fibonacci;
    o.dome.count = 8;
    o.specular = {SpecularKind::BlinnPhong, 0.2, 30, 0.2};
    o.seed = 9;
    o.threads = 2;
    o.views = {normalize(Vec3{0.2, -0.1, 1})};
    return o;
}

}  // namespace

TEST_CASE("make_stack: the written stack reads back as rendered, and its record renders the same ground truth")
{
    const std::string dir = temp_dir("cmfilter-make-stack");
    fs::remove_all(dir + "/one");
    fs::create_directories(dir + "/one");
    const std::string scene = bumpy_scene(dir);
    const MakeStackOptions o = small_options(scene, dir + "/one/stack.lp");
    const ColorConfig config = builtin_color_config();
    auto made = make_stack(o, config);
    REQUIRE_MESSAGE(made, (made ? "" : made.error().message));
    CHECK(made->lights == 8);
    CHECK(fs::exists(dir + "/one/stack-007.exr"));
    CHECK(fs::exists(dir + "/one/stack.normals.exr"));
    CHECK(fs::exists(dir + "/one/stack.json"));

    StackLoadOptions lo;
    lo.light_file = dir + "/one/stack.lp";
    auto stack = load_image_stack(lo, config);
    REQUIRE_MESSAGE(stack, (stack ? "" : stack.error().message));
    CHECK(stack->width == 16);
    CHECK(stack->channels == 3);
    REQUIRE(stack->count() == 8);
    // In memory, independently of the files.
    const SyntheticSurface s = load_synthetic_surface(scene);
    SyntheticStackOptions so;
    so.view = o.views[0];
    so.size = o.size;
    so.samples = o.samples;
    so.specular = o.specular;
    so.seed = o.seed;
    auto lights = make_dome(o.dome);
    REQUIRE(lights);
    // Under the lights as the .lp gives them.
    auto expected = render_synthetic_stack(s, stack->lights, so);
    REQUIRE(expected);

    for (int k = 0; k < 8; ++k) CHECK(dot(stack->lights[k], (*lights)[k]) == doctest::Approx(1).epsilon(1e-9));
    CHECK(stack->pixels == expected->pixels);

    // The record gives the options back; six of the lights again, in another order, as a file dome.
    auto record = read_stack_record(dir + "/one/stack.json");
    REQUIRE_MESSAGE(record, (record ? "" : record.error().message));
    CHECK(record->size == 16);
    CHECK(record->samples == 4);
    CHECK(record->seed == 9);
    CHECK(record->specular.exponent == 30);
    const int held_index[6] = {2, 5, 6, 0, 1, 3};
    std::vector<LightEntry> held;
    for (int k : held_index) held.push_back({"x.exr", stack->lights[k], 0});
    fs::create_directories(dir + "/held");
    REQUIRE(write_light_file(dir + "/held/lights.lp", held));
    MakeStackOptions again = *record;
    again.dome.kind = DomeKind::File;
    again.dome.path = dir + "/held/lights.lp";
    again.output = dir + "/held/stack.lp";
    again.threads = 1;
    REQUIRE(make_stack(again, config));
    lo.light_file = again.output;
    auto truth = load_image_stack(lo, config);
    REQUIRE(truth);
    const std::size_t n = truth->texels() * 3;
    REQUIRE(truth->count() == 6);
    for (int k = 0; k < 6; ++k) {
        // The same rays lit by the same lights (as the .lp files round them).
        std::size_t same = 0;
        for (std::size_t t = 0; t < n; ++t)
            same += std::abs(truth->image(k)[t] - expected->image(held_index[k])[t]) <= 1e-6f;
        CHECK(same == n);
    }
}

TEST_CASE("make_stack: several views write a slot per view and the BTF manifest")
{
    const std::string dir = temp_dir("cmfilter-make-stack-btf");
    fs::remove_all(dir + "/btf");
    fs::create_directories(dir + "/btf");
    MakeStackOptions o = small_options(bumpy_scene(dir), dir + "/btf/btf.json");
    o.views = {{0, 0, 1}, {0.5, 0, 0.866}};
    o.size = 8;
    auto made = make_stack(o, builtin_color_config());
    REQUIRE_MESSAGE(made, (made ? "" : made.error().message));
    auto manifest = read_btf_manifest(dir + "/btf/btf.json");
    REQUIRE_MESSAGE(manifest, (manifest ? "" : manifest.error().message));
    REQUIRE(manifest->views.size() == 2);
    CHECK(manifest->views[1].view.x == doctest::Approx(0.5).epsilon(1e-3));
    CHECK(fs::exists(manifest->light_file_path(1)));
    CHECK(fs::exists(dir + "/btf/view-01/stack.json"));
}

TEST_CASE("make_stack: refusals name the surface, the lights or the view, and leave no files")
{
    const std::string dir = temp_dir("cmfilter-make-stack-bad");
    fs::remove_all(dir + "/bad");
    fs::create_directories(dir + "/bad");
    const ColorConfig config = builtin_color_config();
    // A noise-driven plane.
    const std::string noise = dir + "/noise.json";
    std::ofstream(noise) << R"({"camera": {"position": [0, 1, 0], "look_at": [0, 0, 4], "resolution": [8, 8]},
      "surfaces": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
        "mapping": {"type": "planar", "u_axis": [1, 0, 0], "v_axis": [0, 0, 1]},
        "material": {"colormap": {"image": ")" +
                                std::string(CMFILTER_SOURCE_DIR) + R"(/luts/terrain.png", "domain": [-1, 1]},
                     "driver": {"noise": "gradient"}}}]})";
    auto e = make_stack(small_options(noise, dir + "/bad/stack.lp"), config);
    REQUIRE_FALSE(e);
    CHECK(e.error().message.find("/surfaces/0") != std::string::npos);
    CHECK(e.error().message.find("noise driver") != std::string::npos);

    MakeStackOptions few = small_options(bumpy_scene(dir), dir + "/bad/stack.lp");
    few.dome.count = 5;
    e = make_stack(few, config);
    REQUIRE_FALSE(e);
    CHECK(e.error().field == "MakeStackOptions::dome");

    MakeStackOptions low = small_options(bumpy_scene(dir), dir + "/bad/stack.lp");
    low.views = {{0.5, 0, -0.1}};
    e = make_stack(low, config);
    REQUIRE_FALSE(e);
    CHECK(e.error().field == "MakeStackOptions::views");
    CHECK(fs::is_empty(dir + "/bad"));
}
