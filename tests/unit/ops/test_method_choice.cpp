// SPDX-License-Identifier: Apache-2.0
// choose_filter_method (ops/method_choice.h) against independent
// computations: naive's measured error against CIEDE2000 of C0(box mean f)
// and the brute-force box mean of C0(f) (tests/support/box_reference.h); a
// map linear over the driver's values, where C0(mean f) is the box mean of
// C0(f) and naive must be chosen; a two-valued driver, where the box
// reference is a two-point mix that the mixture and the histogram reproduce
// and the one Gaussian does not; the cost order; nothing meeting a tolerance;
// bad options naming their field.
#include "cmfilter/color/ciede2000.h"
#include "cmfilter/ops/method_choice.h"
#include "cmfilter/texture/color_pyramid_file.h"
#include "cmfilter/texture/histogram_pyramid.h"

#include "apply_inputs.h"

#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace cmfilter;
using namespace cmfilter_test;

namespace {

const std::string kDir = temp_dir("cmfilter-test-method-choice");
constexpr int kSize = 32;

// A driver of two values, 0.2 and 0.8, in an irregular pattern.
std::vector<float> two_valued()
{
    std::vector<float> f(kSize * kSize);
    for (int i = 0; i < kSize * kSize; ++i) f[i] = ((i * 7 + i / 5 + (i * i) % 11) % 3 == 0) ? 0.8f : 0.2f;
    return f;
}

MethodChoice choose(const ApplyOptions& inputs, double tolerance, std::vector<double> lods = {1, 2, 3})
{
    MethodChoiceOptions o;
    o.tolerance = tolerance;
    o.lods = std::move(lods);
    auto c = choose_filter_method(inputs, builtin_color_config(), o);
    if (!c) FAIL(c.error().message);
    return *c;
}

const MethodTrial& trial(const MethodChoice& c, FilterMethod m)
{
    for (const MethodTrial& t : c.trials)
        if (t.method == m) return t;
    FAIL("no trial of " << to_string(m));
    return c.trials.front();
}

Rgb to_rgb(const Rgb3& c) { return {c[0], c[1], c[2]}; }

// Independently: the mean over level l's texels of CIEDE2000 between
// C0(box mean of f) and the box mean of C0(f), both brute force.
double naive_error(const std::vector<float>& f, int level)
{
    const ReferenceMap m = reference_map();
    const int w = kSize >> level;
    double sum = 0;
    for (int y = 0; y < w; ++y)
        for (int x = 0; x < w; ++x) {
            double mean = 0;
            for (const auto& b : box_weights(kSize, kSize, w, w, x, y)) mean += b.weight * f[b.j * kSize + b.i];
            const Rgb3 naive = reference_map_value(m, mean);
            const Rgb3 box = box_mean_color(m, f, kSize, kSize, w, w, x, y);
            sum += ciede2000_linear_rgb(to_rgb(naive), to_rgb(box));
        }
    return sum / (w * w);
}

}  // namespace

TEST_CASE("method choice: naive's error is CIEDE2000 of C0(box mean f) against the box mean of C0(f)")
{
    const std::vector<float> f = two_valued();
    const ApplyOptions in = apply_inputs(kDir, "naive", f, kSize, kSize, {});
    const MethodChoice c = choose(in, 100);
    REQUIRE(c.lods == std::vector<double>{1, 2, 3});
    const MethodTrial& naive = trial(c, FilterMethod::Naive);
    REQUIRE(naive.errors.size() == 3);
    for (int l = 1; l <= 3; ++l) {
        CAPTURE(l);
        const double want = naive_error(f, l);
        CHECK(want > 1);  // the test means something: the two-point mix is far from C0(mean)
        // float32 moments and colours: well below a thousandth of a unit.
        CHECK(std::abs(naive.errors[l - 1] - want) <= 1e-3 * want);
    }
    CHECK(naive.worst == doctest::Approx(std::max({naive.errors[0], naive.errors[1], naive.errors[2]})));
    // Everything meets a tolerance of 100: the cheapest, naive, is chosen.
    REQUIRE(c.choice());
    CHECK(c.choice()->method == FilterMethod::Naive);
}

TEST_CASE("method choice: a map linear over the driver's values makes naive exact, and naive is chosen")
{
    // Texel centres at (i + 0.5) / 8: C0 is linear on [1/16, 15/16], where
    // every driver value lies, so C0(mean f) = mean C0(f) for every footprint.
    std::vector<float> linear;
    for (int i = 0; i < 8; ++i) linear.insert(linear.end(), {0.05f + 0.1f * i, 0.9f - 0.1f * i, 0.3f + 0.05f * i});
    std::vector<float> f(kSize * kSize);
    for (int i = 0; i < kSize * kSize; ++i)
        f[i] = static_cast<float>(0.5 + 0.4 * std::sin(0.37 * i + 0.11 * (i / kSize)));
    const ApplyOptions in = apply_inputs(kDir, "linear", f, kSize, kSize, {}, 2, 0, linear);
    const MethodChoice c = choose(in, 0.01);
    REQUIRE(c.choice());
    CHECK(c.choice()->method == FilterMethod::Naive);
    CHECK(c.choice()->worst < 1e-3);
}

TEST_CASE("method choice: a two-valued driver needs the mixture or the histogram, and the cheapest is chosen")
{
    const std::vector<float> f = two_valued();
    const ApplyOptions in = apply_inputs(kDir, "two", f, kSize, kSize, {}, 4);
    {
        const MethodChoice c = choose(in, 0.5);
        // No histograms, colour or segment pyramid: exact, color-pyramid and
        // segments are skipped, and say why.
        REQUIRE(c.trials.size() == 3);
        CHECK(c.trials[0].method == FilterMethod::Naive);
        CHECK(c.trials[1].method == FilterMethod::Gaussian);
        CHECK(c.trials[2].method == FilterMethod::Mixture);
        REQUIRE(c.skipped.size() == 3);
        CHECK(c.skipped[0].find("MethodChoiceOptions::color_pyramid_path") != std::string::npos);
        CHECK(c.skipped[1].find("MethodChoiceOptions::segment_pyramid_path") != std::string::npos);
        CHECK(c.skipped[2].find("ApplyOptions::histograms_path") != std::string::npos);
        // Two values: the mixture's two components are the two values
        // (math/moment_mixture.h), so only the table's interpolation is left;
        // one Gaussian spreads the mass between them.
        CHECK(trial(c, FilterMethod::Mixture).worst < 0.1);
        CHECK(trial(c, FilterMethod::Gaussian).worst > 1);
        REQUIRE(c.choice());
        CHECK(c.choice()->method == FilterMethod::Mixture);
    }
    {
        // The histogram of two values is 8 bytes a texel, half the mixture's:
        // it comes before it, and it is exact.
        ApplyOptions with = in;
        HistogramBakeOptions bake;
        bake.driver_path = kDir + "/two-driver.exr";
        bake.output_path = with.histograms_path = kDir + "/two-histograms.exr";
        REQUIRE(bake_histogram_pyramid(bake));
        const MethodChoice c = choose(with, 0.5);
        REQUIRE(c.trials.size() == 4);
        CHECK(c.trials[2].method == FilterMethod::Exact);
        CHECK(c.trials[2].bytes_per_texel == 8);
        CHECK(c.trials[3].method == FilterMethod::Mixture);
        CHECK(c.trials[2].worst < 1e-3);
        REQUIRE(c.choice());
        CHECK(c.choice()->method == FilterMethod::Exact);
    }
}

TEST_CASE("method choice: a colour pyramid of the map is exact at 12 bytes, before the mixture's 16")
{
    const std::vector<float> f = two_valued();
    const ApplyOptions in = apply_inputs(kDir, "pyramid", f, kSize, kSize, {}, 4);
    ColorMap map;
    for (const Rgb3& c : reference_map().texels) map.texels.push_back({c[0], c[1], c[2]});
    ColorPyramidBakeOptions bake;
    bake.driver_path = kDir + "/pyramid-driver.exr";
    bake.output_path = kDir + "/pyramid-colors.exr";
    bake.map = &map;
    REQUIRE(bake_color_pyramid(bake));
    MethodChoiceOptions o;
    o.tolerance = 0.5;
    o.lods = {1, 2, 3};
    o.color_pyramid_path = bake.output_path;
    auto c = choose_filter_method(in, builtin_color_config(), o);
    REQUIRE(c);
    REQUIRE(c->trials.size() == 4);
    CHECK(c->trials[2].method == FilterMethod::ColorPyramid);
    CHECK(c->trials[2].bytes_per_texel == 12);
    CHECK(c->trials[3].method == FilterMethod::Mixture);
    // Independently: naive's error is the brute-force one, so the levels are
    // the same; the colour pyramid's is float rounding of those box means.
    CHECK(trial(*c, FilterMethod::Naive).errors[0] == doctest::Approx(naive_error(f, 1)).epsilon(1e-4));
    CHECK(trial(*c, FilterMethod::ColorPyramid).worst < 1e-3);
    CHECK(trial(*c, FilterMethod::Gaussian).worst > 1);
    REQUIRE(c->choice());
    CHECK(c->choice()->method == FilterMethod::ColorPyramid);

    // Baked through another map: refused, naming the difference.
    ColorMap other = map;
    other.texels[2].r += 0.2;
    bake.map = &other;
    bake.output_path = kDir + "/pyramid-other.exr";
    REQUIRE(bake_color_pyramid(bake));
    o.color_pyramid_path = bake.output_path;
    auto refused = choose_filter_method(in, builtin_color_config(), o);
    REQUIRE_FALSE(refused);
    CHECK(refused.error().message.find("another colour map") != std::string::npos);
}

TEST_CASE("method choice: nothing meets, and the message says what came closest and what was not tried")
{
    const ApplyOptions in = apply_inputs(kDir, "none", two_valued(), kSize, kSize, {});
    const MethodChoice c = choose(in, 1e-6);
    CHECK_FALSE(c.choice());
    const Error e = no_method_meets(c, "the material");
    CHECK(e.kind == ErrorKind::BadInput);
    CHECK(e.field == "MethodChoiceOptions::tolerance");
    CHECK(e.message.find("the material: no method meets MethodChoiceOptions::tolerance 1e-06") == 0);
    CHECK(e.message.find("the closest is gaussian") != std::string::npos);
    CHECK(e.message.find("not tried: mixture: ") != std::string::npos);
    CHECK(e.message.find("MomentBakeOptions::order 4") != std::string::npos);
}

TEST_CASE("method choice: bad options name their field")
{
    const ApplyOptions in = apply_inputs(kDir, "bad", two_valued(), kSize, kSize, {});
    const auto error_of = [&](const MethodChoiceOptions& o) {
        auto c = choose_filter_method(in, builtin_color_config(), o);
        REQUIRE_FALSE(c);
        CHECK(c.error().kind == ErrorKind::BadInput);
        return c.error();
    };
    for (double t : {0.0, -1.0, std::nan(""), HUGE_VAL}) {
        MethodChoiceOptions o;
        o.tolerance = t;
        CHECK(error_of(o).field == "MethodChoiceOptions::tolerance");
    }
    MethodChoiceOptions o;
    o.lods = {1, -0.5};
    CHECK(error_of(o).field == "MethodChoiceOptions::lods");
    o.lods = {40};  // above the top level (5 for 32 x 32)
    CHECK(error_of(o).message.find("all lie above level 5") != std::string::npos);
    o.lods = {};
    o.candidates = {FilterMethod::Reference};
    CHECK(error_of(o).field == "MethodChoiceOptions::candidates");
    o.candidates = {FilterMethod::Mixture};  // order-2 moments
    CHECK(error_of(o).message.find("holds 2 moments") != std::string::npos);
}
