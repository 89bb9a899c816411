// SPDX-License-Identifier: Apache-2.0
// render --method auto's probe choice (surface_probe_choice.h), against a
// second computation: whole frames rendered through render() with each
// probe count, compared pixel by pixel with the render at the ceiling over
// each surface's pixels, banded by the ceiling's LOD AOV; the choice must
// give the same errors (up to the float pixels' rounding) and the fewest
// probes whose worst band meets the tolerance. RenderOptions::surface_probes
// must give each surface its own count, pixel for pixel as a render with
// that count for every surface.
#include "cmfilter/render/surface_probe_choice.h"

#include "view_choice_test_support.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>
#include <vector>

using namespace cmfilter;
using namespace cmfilter_test;
using nlohmann::json;

namespace {

const std::string kLuts = std::string(CMFILTER_SOURCE_DIR) + "/luts/";
const std::string kExamples = std::string(CMFILTER_SOURCE_DIR) + "/examples/scenes/";

// A ground plane of fBm through the terrain map seen towards its horizon
// (footprints from square to slivers) and a wall, a microsurface coloured
// by slope steepness, behind it.
json noise_ground_and_wall()
{
    json scene = json::parse(R"({
      "camera": {"position": [0, 0.5, 0], "look_at": [0, 0.2, 2], "up": [0, 1, 0], "fov_degrees": 55,
                 "resolution": [40, 30]},
      "light": {"direction": [-0.6, 0.7, -0.4], "radiance": [1, 1, 1], "ambient": [0.1, 0.1, 0.1]},
      "background": [0.5, 0.6, 0.8],
      "surfaces": [
        {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
         "mapping": {"type": "planar", "u_axis": [0.5, 0, 0], "v_axis": [0, 0, 0.5]}},
        {"type": "plane", "point": [0, 0, 6], "normal": [0, 0, -1],
         "mapping": {"type": "planar", "u_axis": [1, 0, 0], "v_axis": [0, 1, 0]}}
      ]})");
    scene["surfaces"][0]["material"] = {
        {"colormap", {{"image", kLuts + "terrain.png"}, {"domain", {-0.7, 0.7}}}},
        {"driver", {{"noise", "fbm:base=gradient,octaves=6"}, {"sigma_table", kExamples + "fbm-gradient-6.exr"}}}};
    scene["surfaces"][1]["material"] = {
        {"microsurface", {{"sigma_h", 0.01}, {"min_wavelength", 0.05}, {"max_wavelength", 0.4}, {"seed", 4}}},
        {"slope_colormap", {{"image", kLuts + "grass-rock.png"}, {"by", "steepness"}}}};
    return scene;
}

RenderOptions with_probes(int probes)
{
    RenderOptions o = one_ray_options(RenderMethod::Gaussian);
    o.max_probes = probes;
    return o;
}

const std::vector<int> kCounts = {1, 2, 4, 8, 16};

}  // namespace

TEST_CASE("each surface's probe choice measures what whole renders with each count show against the ceiling")
{
    const PreparedScene p = prepare_scene(noise_ground_and_wall(), "noise-ground-and-wall.json");
    const RenderedImage ceiling = render_scene(p, with_probes(16));
    std::vector<std::vector<BandSums>> expected(2);
    for (int s = 0; s < 2; ++s)
        for (int n : kCounts)
            expected[static_cast<std::size_t>(s)].push_back(band_sums(render_scene(p, with_probes(n)), ceiling, s));
    const auto worst = [&](int s, std::size_t k) { return expected[static_cast<std::size_t>(s)][k].worst(); };
    // One probe is far from the ceiling towards the ground's horizon, and
    // the error falls with more.
    CHECK(worst(0, 0) > 1);
    CHECK(worst(0, 3) < worst(0, 0));
    for (int s = 0; s < 2; ++s) CHECK(worst(s, 4) == 0);

    // Every count tried (a tolerance only the ceiling meets), then one
    // between one probe and the ceiling.
    const double between = 0.5 * worst(0, 0);
    for (double tolerance : {1e-9, between}) {
        CAPTURE(tolerance);
        ProbeChoiceOptions o;
        o.tolerance = tolerance;
        o.max_pixels = 40 * 30;  // every pixel
        o.render = with_probes(16);
        auto chosen = choose_surface_probes(p.scene, p.materials, o);
        REQUIRE_MESSAGE(chosen, (chosen ? "" : chosen.error().message));
        REQUIRE(chosen->size() == 2);
        for (int s = 0; s < 2; ++s) {
            CAPTURE(s);
            const ProbeChoice& c = (*chosen)[static_cast<std::size_t>(s)].choice;
            CHECK((*chosen)[static_cast<std::size_t>(s)].surface == static_cast<std::size_t>(s));
            CHECK(c.ceiling == 16);
            const BandSums& reference = expected[static_cast<std::size_t>(s)][0];
            REQUIRE(c.lods.size() == reference.count.size());
            std::size_t first = kCounts.size();
            for (std::size_t k = 0; k < kCounts.size() && first == kCounts.size(); ++k)
                if (worst(s, k) <= tolerance) first = k;
            REQUIRE(first < kCounts.size());
            // Tried fewest first, up to the first that meets.
            REQUIRE(c.trials.size() == first + 1);
            for (std::size_t k = 0; k <= first; ++k) {
                const ProbeTrial& t = c.trials[k];
                CHECK(t.probes == kCounts[k]);
                std::size_t b = 0;
                for (const auto& entry : expected[static_cast<std::size_t>(s)][k].sum)
                    CHECK(std::fabs(t.errors[b++] - expected[static_cast<std::size_t>(s)][k].mean(entry.first)) <
                          kFloatSlack);
                CHECK(std::fabs(t.worst - worst(s, k)) < kFloatSlack);
                CHECK(t.meets == (k == first));
            }
            REQUIRE(c.choice());
            CHECK(c.choice()->probes == kCounts[first]);
        }
        if (tolerance == between) CHECK((*chosen)[0].choice.choice()->probes > 1);
        if (tolerance == between) CHECK((*chosen)[0].choice.choice()->probes < 16);

        // A region of the frame (a farm tile), on one thread, chooses as the
        // frame: the whole frame is measured either way.
        o.render.region = PixelRegion{0, 0, 8, 6};
        o.render.threads = 1;
        auto tile = choose_surface_probes(p.scene, p.materials, o);
        REQUIRE(tile);
        REQUIRE(tile->size() == chosen->size());
        for (std::size_t s = 0; s < tile->size(); ++s) {
            CHECK((*tile)[s].choice.chosen == (*chosen)[s].choice.chosen);
            REQUIRE((*tile)[s].choice.trials.size() == (*chosen)[s].choice.trials.size());
            for (std::size_t k = 0; k < (*tile)[s].choice.trials.size(); ++k)
                CHECK((*tile)[s].choice.trials[k].errors == (*chosen)[s].choice.trials[k].errors);
        }
    }
}

TEST_CASE("RenderOptions::surface_probes gives each surface its own probe count")
{
    const PreparedScene p = prepare_scene(noise_ground_and_wall(), "noise-ground-and-wall.json");
    const RenderedImage two = render_scene(p, with_probes(2));
    const RenderedImage sixteen = render_scene(p, with_probes(16));
    RenderOptions mixed = with_probes(16);
    mixed.surface_probes = {2, 0};  // the ground 2, the wall the ceiling
    const RenderedImage both = render_scene(p, mixed);
    std::size_t on[2] = {0, 0}, differ = 0;
    for (std::size_t q = 0; q < both.surface.size(); ++q) {
        const int s = both.surface[q];
        if (s < 0) continue;
        ++on[s];
        const RenderedImage& by = s == 0 ? two : sixteen;
        CHECK(pixel_rgb(both, q).r == pixel_rgb(by, q).r);
        CHECK(pixel_rgb(both, q).g == pixel_rgb(by, q).g);
        CHECK(pixel_rgb(both, q).b == pixel_rgb(by, q).b);
        if (s == 0 && pixel_rgb(two, q).r != pixel_rgb(sixteen, q).r) ++differ;
    }
    CHECK(on[0] > 100);
    CHECK(on[1] > 50);
    CHECK(differ > 50);  // the ground's two renders differ: the test can tell them apart
}

TEST_CASE("the probe choice and render refuse out-of-range options, naming the field")
{
    const PreparedScene p = prepare_scene(noise_ground_and_wall(), "noise-ground-and-wall.json");
    const auto field_of = [&](const ProbeChoiceOptions& o) {
        auto chosen = choose_surface_probes(p.scene, p.materials, o);
        REQUIRE_FALSE(chosen);
        CHECK(chosen.error().kind == ErrorKind::BadInput);
        return chosen.error().field;
    };
    ProbeChoiceOptions o;
    o.render = with_probes(16);
    o.tolerance = -1;
    CHECK(field_of(o) == "ProbeChoiceOptions::tolerance");
    o.tolerance = 1;
    for (const std::vector<int>& bad : {std::vector<int>{0, 4}, {4, 2}, {4, 32}}) {
        o.candidates = bad;
        CHECK(field_of(o) == "ProbeChoiceOptions::candidates");
    }
    o.candidates.clear();
    o.max_pixels = 0;
    CHECK(field_of(o) == "ProbeChoiceOptions::max_pixels");
    o.max_pixels = 16;
    o.render.max_probes = 0;
    CHECK(field_of(o) == "RenderOptions::max_probes");

    RenderOptions r = with_probes(16);
    r.surface_probes = {4, kMaxProbes + 1};
    auto image = render(p.scene, p.materials, r);
    REQUIRE_FALSE(image);
    CHECK(image.error().field == "RenderOptions::surface_probes");
    CHECK(image.error().message.find("65 for surface 1") != std::string::npos);
}
