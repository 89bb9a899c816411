// SPDX-License-Identifier: Apache-2.0
// render --method auto's choice for microsurface materials
// (microsurface_method_choice.h), against a second computation: whole
// frames rendered by each method through render() (the row renderer, not
// the choice's own loop), compared pixel by pixel with the exact render over
// the pixels each surface's centre ray hits, banded by the render's LOD AOV;
// the choice must give the same bands, the same errors (up to the float
// pixels' rounding) and the first method
// whose worst band meets the tolerance. RenderOptions::microsurface_methods
// must colour each surface by its own method, pixel for pixel as a render by
// that method alone.
#include "cmfilter/render/microsurface_method_choice.h"

#include "view_choice_test_support.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace cmfilter;
using namespace cmfilter_test;
using nlohmann::json;

namespace {

const std::string kLuts = std::string(CMFILTER_SOURCE_DIR) + "/luts/";

// A ground plane coloured by height (sand to snow) and, behind it, a wall
// coloured by slope steepness: two microsurfaces, with their horizon and
// their meeting in view. `wall_z` < 0 puts the wall behind the camera.
json two_microsurfaces(double wall_z)
{
    json scene = json::parse(R"({
      "camera": {"position": [0, 0.6, 0], "look_at": [0, 0.1, 2], "up": [0, 1, 0], "fov_degrees": 55,
                 "resolution": [40, 30]},
      "light": {"direction": [-0.6, 0.7, -0.4], "radiance": [1, 1, 1], "ambient": [0.1, 0.1, 0.1]},
      "background": [0.5, 0.6, 0.8],
      "surfaces": [
        {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
         "mapping": {"type": "planar", "u_axis": [2, 0, 0], "v_axis": [0, 0, 2]}},
        {"type": "plane", "normal": [0, 0, -1],
         "mapping": {"type": "planar", "u_axis": [1, 0, 0], "v_axis": [0, 1, 0]}}
      ]})");
    scene["surfaces"][1]["point"] = {0, 0, wall_z};
    scene["surfaces"][0]["material"] = {
        {"microsurface", {{"sigma_h", 0.008}, {"min_wavelength", 0.05}, {"max_wavelength", 0.4}, {"seed", 1}}},
        {"colormap", {{"image", kLuts + "sand-snow.png"}, {"domain", {-0.024, 0.024}}}}};
    scene["surfaces"][1]["material"] = {
        {"microsurface", {{"sigma_h", 0.01}, {"min_wavelength", 0.05}, {"max_wavelength", 0.4}, {"seed", 4}}},
        {"slope_colormap", {{"image", kLuts + "grass-rock.png"}, {"by", "steepness"}}}};
    return scene;
}

const std::vector<RenderMethod> kMethods = {RenderMethod::Naive, RenderMethod::Gaussian, RenderMethod::GaussianExact,
                                            RenderMethod::Exact};

}  // namespace

TEST_CASE("each microsurface's choice measures what whole renders by each method show against exact")
{
    const PreparedScene p = prepare_scene(two_microsurfaces(3.0), "two-microsurfaces.json");
    const RenderedImage exact = render_scene(p, one_ray_options(RenderMethod::Exact));
    // The second computation: each method's worst band per surface.
    std::vector<std::vector<BandSums>> expected(2);
    for (int s = 0; s < 2; ++s)
        for (RenderMethod m : kMethods)
            expected[static_cast<std::size_t>(s)].push_back(band_sums(render_scene(p, one_ray_options(m)), exact, s));
    const auto worst = [&](int s, std::size_t m) { return expected[static_cast<std::size_t>(s)][m].worst(); };
    // Naive is far from exact on both, the Gaussian methods close.
    for (int s = 0; s < 2; ++s) {
        CHECK(worst(s, 0) > 3 * worst(s, 1));
        CHECK(worst(s, 0) > 1);
        CHECK(worst(s, 3) == 0);
    }

    // A tolerance above every method, one between naive and gaussian on the
    // ground, one below both Gaussian methods there.
    const double between = 0.5 * (worst(0, 0) + std::max(worst(0, 1), worst(0, 2)));
    const double below = 0.5 * std::min(worst(0, 1), worst(0, 2));
    for (double tolerance : {1000.0, between, below}) {
        CAPTURE(tolerance);
        MicrosurfaceChoiceOptions o;
        o.tolerance = tolerance;
        o.max_pixels = 40 * 30;  // every pixel
        o.render = one_ray_options(RenderMethod::Gaussian);
        auto chosen = choose_microsurface_methods(p.scene, p.materials, o);
        REQUIRE_MESSAGE(chosen, (chosen ? "" : chosen.error().message));
        REQUIRE(chosen->size() == 2);
        for (int s = 0; s < 2; ++s) {
            CAPTURE(s);
            const SurfaceMicrosurfaceChoice& c = (*chosen)[static_cast<std::size_t>(s)];
            CHECK(c.surface == static_cast<std::size_t>(s));
            const auto& bands = expected[static_cast<std::size_t>(s)][0].count;
            std::size_t seen = 0;
            for (const auto& [band, n] : bands) seen += n;
            CHECK(c.choice.surface_pixels == seen);
            CHECK(c.choice.pixels == seen);
            REQUIRE(c.choice.lods.size() == bands.size());
            std::size_t k = 0;
            for (const auto& [band, n] : bands) {
                CHECK(c.choice.lods[k] == band);
                CHECK(c.choice.band_pixels[k] == n);
                ++k;
            }
            REQUIRE(c.choice.trials.size() == kMethods.size());
            std::optional<std::size_t> first_meeting;
            for (std::size_t m = 0; m < kMethods.size(); ++m) {
                const MicrosurfaceTrial& t = c.choice.trials[m];
                CHECK(t.method == kMethods[m]);
                const BandSums& b = expected[static_cast<std::size_t>(s)][m];
                k = 0;
                for (const auto& entry : b.sum) CHECK(std::fabs(t.errors[k++] - b.mean(entry.first)) < kFloatSlack);
                CHECK(std::fabs(t.worst - worst(s, m)) < kFloatSlack);
                CHECK(t.meets == (worst(s, m) <= tolerance));
                if (!first_meeting && worst(s, m) <= tolerance) first_meeting = m;
            }
            REQUIRE(first_meeting);
            REQUIRE(c.choice.choice());
            CHECK(c.choice.chosen == first_meeting);
        }
        if (tolerance == 1000.0) CHECK((*chosen)[0].choice.choice()->method == RenderMethod::Naive);
        if (tolerance == between) CHECK((*chosen)[0].choice.choice()->method != RenderMethod::Naive);
        if (tolerance == below) CHECK((*chosen)[0].choice.choice()->method == RenderMethod::Exact);
    }
}

TEST_CASE("RenderOptions::microsurface_methods colours each surface by its own method")
{
    const PreparedScene p = prepare_scene(two_microsurfaces(3.0), "two-microsurfaces.json");
    const RenderedImage exact = render_scene(p, one_ray_options(RenderMethod::Exact));
    const RenderedImage naive = render_scene(p, one_ray_options(RenderMethod::Naive));
    RenderOptions mixed = one_ray_options(RenderMethod::Gaussian);
    mixed.microsurface_methods = {RenderMethod::Exact, RenderMethod::Naive};
    const RenderedImage both = render_scene(p, mixed);
    std::size_t on[2] = {0, 0};
    for (std::size_t q = 0; q < both.surface.size(); ++q) {
        const int s = both.surface[q];
        if (s < 0) continue;
        ++on[s];
        const RenderedImage& by = s == 0 ? exact : naive;
        CHECK(pixel_rgb(both, q).r == pixel_rgb(by, q).r);
        CHECK(pixel_rgb(both, q).g == pixel_rgb(by, q).g);
        CHECK(pixel_rgb(both, q).b == pixel_rgb(by, q).b);
    }
    CHECK(on[0] > 100);
    CHECK(on[1] > 100);
}

TEST_CASE("microsurface choice: a tile on one thread chooses as the frame on two, unseen surfaces left out")
{
    const PreparedScene p =
        prepare_scene(two_microsurfaces(-1.0), "two-microsurfaces.json");  // the wall behind the camera
    MicrosurfaceChoiceOptions o;
    o.tolerance = 1;
    o.max_pixels = 50;
    o.render = one_ray_options(RenderMethod::Gaussian);
    auto chosen = choose_microsurface_methods(p.scene, p.materials, o);
    REQUIRE_MESSAGE(chosen, (chosen ? "" : chosen.error().message));
    REQUIRE(chosen->size() == 1);
    CHECK((*chosen)[0].surface == 0);
    CHECK((*chosen)[0].choice.pixels == 50);
    CHECK((*chosen)[0].choice.surface_pixels > 50);
    std::size_t banded = 0;
    for (std::size_t n : (*chosen)[0].choice.band_pixels) banded += n;
    CHECK(banded == 50);

    // A region of the frame (a farm tile) makes the same choice: the whole
    // frame is measured either way, with any thread count.
    o.render.region = PixelRegion{0, 20, 8, 30};
    o.render.threads = 1;
    auto tile = choose_microsurface_methods(p.scene, p.materials, o);
    REQUIRE(tile);
    REQUIRE(tile->size() == 1);
    CHECK((*tile)[0].choice.lods == (*chosen)[0].choice.lods);
    REQUIRE((*tile)[0].choice.trials.size() == (*chosen)[0].choice.trials.size());
    for (std::size_t m = 0; m < (*tile)[0].choice.trials.size(); ++m)
        CHECK((*tile)[0].choice.trials[m].errors == (*chosen)[0].choice.trials[m].errors);
    CHECK((*tile)[0].choice.chosen == (*chosen)[0].choice.chosen);
}

TEST_CASE("the microsurface choice and render refuse out-of-range options, naming the field")
{
    const PreparedScene p = prepare_scene(two_microsurfaces(3.0), "two-microsurfaces.json");
    const auto field_of = [&](const MicrosurfaceChoiceOptions& o) {
        auto chosen = choose_microsurface_methods(p.scene, p.materials, o);
        REQUIRE_FALSE(chosen);
        CHECK(chosen.error().kind == ErrorKind::BadInput);
        return chosen.error().field;
    };
    MicrosurfaceChoiceOptions o;
    o.tolerance = 0;
    CHECK(field_of(o) == "MicrosurfaceChoiceOptions::tolerance");
    o.tolerance = std::nan("");
    CHECK(field_of(o) == "MicrosurfaceChoiceOptions::tolerance");
    o.tolerance = 1;
    o.candidates = {RenderMethod::Gaussian, RenderMethod::Supersample};
    CHECK(field_of(o) == "MicrosurfaceChoiceOptions::candidates");
    o.candidates.clear();
    o.max_pixels = 0;
    CHECK(field_of(o) == "MicrosurfaceChoiceOptions::max_pixels");

    RenderOptions r = one_ray_options(RenderMethod::Gaussian);
    r.microsurface_methods = {RenderMethod::Gaussian, RenderMethod::Mixture};
    auto image = render(p.scene, p.materials, r);
    REQUIRE_FALSE(image);
    CHECK(image.error().field == "RenderOptions::microsurface_methods");
    CHECK(image.error().message.find("mixture for surface 1") != std::string::npos);
}
