// SPDX-License-Identifier: Apache-2.0
// Lafortune fits of stacks made from known lobes (lafortune_test_support.h,
// the model written out in the test): the lobes recovered (up to their
// order) and the relit values at held-out lights; convergence from
// perturbed starts; the same result on 1 and 2 threads; the auto lobe count
// on texels of 1, 2 and 3 lobes; bad options refused by name; finite
// parameters and relit values on noise.
#include "cmfilter/stack/lafortune_fit.h"
#include "cmfilter/stack/lafortune_scalar_fit.h"

#include "lafortune_test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

using namespace cmfilter;
using namespace cmfilter_test;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

double angle_between(const Vec3& a, const Vec3& b)
{
    return std::acos(std::clamp(dot(a, b) / (length(a) * length(b)), -1.0, 1.0));
}

// Texels of two separated lobes each (their axes, exponents and scales).
std::vector<AxisTexel> two_lobe_texels()
{
    return {
        {0.20, {scaled_axis({0.3, 0.1, 1}, 0.6, 30), scaled_axis({-0.8, 0.5, 1}, 0.3, 5)}, {30, 5}},
        {0.05, {scaled_axis({0, -0.4, 1}, 1.2, 80), scaled_axis({0.9, 0.9, 1}, 0.4, 3)}, {80, 3}},
        {0.35, {scaled_axis({-0.2, -0.2, 1}, 0.25, 12), scaled_axis({0.7, -0.6, 1}, 0.5, 40)}, {12, 40}},
    };
}

// The fit's lobe i of scalar `s` (rho_d at s[0]) as axis and exponent.
Vec3 fitted_axis(const float* s, int i) { return {s[1 + 4 * i], s[2 + 4 * i], s[3 + 4 * i]}; }
double fitted_exponent(const float* s, int i) { return s[4 + 4 * i]; }

// Each true lobe matched to the fitted lobe nearest in direction: the
// axis within `degrees`, the exponent and the scale |a|^n within `relative`.
void check_lobes(const float* scalar, int slots, const AxisTexel& truth, double degrees, double relative)
{
    CHECK(scalar[0] == doctest::Approx(truth.rho).epsilon(relative).scale(1));
    for (std::size_t j = 0; j < truth.axes.size(); ++j) {
        int best = -1;
        for (int i = 0; i < slots; ++i)
            if (length(fitted_axis(scalar, i)) > 0 &&
                (best < 0 || angle_between(fitted_axis(scalar, i), truth.axes[j]) <
                                 angle_between(fitted_axis(scalar, best), truth.axes[j])))
                best = i;
        REQUIRE(best >= 0);
        const double n = fitted_exponent(scalar, best);
        CHECK(angle_between(fitted_axis(scalar, best), truth.axes[j]) * 180 / 3.14159265358979 < degrees);
        CHECK(n == doctest::Approx(truth.exponents[j]).epsilon(relative));
        CHECK(std::pow(length(fitted_axis(scalar, best)), n) ==
              doctest::Approx(std::pow(length(truth.axes[j]), truth.exponents[j])).epsilon(relative));
    }
}

}  // namespace

TEST_CASE("lafortune fit: luminance lobes recovered from a stack made from them, and relit at held-out lights")
{
    const std::vector<AxisTexel> texels = two_lobe_texels();
    const std::vector<std::vector<double>> colours = {{0.9, 0.6, 0.3}, {0.2, 0.5, 0.8}, {0.7, 0.7, 0.7}};
    const ImageStack stack = stack_from_texels(texels, colours, fibonacci_lights(120, 0.1));
    LafortuneFitOptions options;
    options.spacing_cap = 0;  // lobes sharper than the gaps between lights, recovered exactly
    options.lobes = 2;
    options.threads = 1;
    const auto fit = fit_lafortune(stack, options);
    REQUIRE(fit);
    CHECK(fit->fallbacks == 0);
    CHECK(fit->lobe_histogram() == std::vector<long long>{0, 0, 3});
    // The luminance's f is the colour's luminance times the texel's f: the
    // fitted rho_d and scales carry that factor, the base colour its
    // inverse. Compare f with the factor taken out.
    for (std::size_t t = 0; t < texels.size(); ++t) {
        const double y = 0.2126 * colours[t][0] + 0.7152 * colours[t][1] + 0.0722 * colours[t][2];
        AxisTexel scaled = texels[t];
        scaled.rho *= y;
        for (std::size_t i = 0; i < scaled.axes.size(); ++i)
            scaled.axes[i] = std::pow(y, 1 / scaled.exponents[i]) * scaled.axes[i];
        check_lobes(fit->texel(t), fit->lobes, scaled, 0.5, 0.02);
        for (int c = 0; c < 3; ++c)
            CHECK(fit->texel(t)[fit->scalar_stride() + c] == doctest::Approx(colours[t][c] / y).epsilon(1e-3));
    }
    // Held-out lights: between the training ones.
    double worst = 0;
    for (const Vec3& u : fibonacci_lights(40, 0.12, 1.3)) {
        const std::vector<float> relit = relight_lafortune(*fit, u, 1);
        for (std::size_t t = 0; t < texels.size(); ++t)
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, std::abs(relit[t * 3 + c] - colours[t][c] * texels[t].value(u)));
    }
    CHECK(worst < 5e-3);
}

TEST_CASE("lafortune fit: rgb lobes recovered per channel")
{
    const std::vector<AxisTexel> texels = two_lobe_texels();
    const std::vector<Vec3> lights = fibonacci_lights(120, 0.1);
    // One texel, channel c made from texels[c].
    ImageStack stack;
    stack.width = stack.height = 1;
    stack.channels = 3;
    stack.lights = lights;
    for (const Vec3& u : lights)
        for (int c = 0; c < 3; ++c) stack.pixels.push_back(static_cast<float>(texels[c].value(u)));
    LafortuneFitOptions options;
    options.spacing_cap = 0;  // lobes sharper than the gaps between lights, recovered exactly
    options.variant = LafortuneVariant::Rgb;
    options.lobes = 2;
    const auto fit = fit_lafortune(stack, options);
    REQUIRE(fit);
    REQUIRE(fit->stride() == 27);
    for (int c = 0; c < 3; ++c) check_lobes(fit->texel(0) + c * fit->scalar_stride(), 2, texels[c], 0.5, 0.02);
    for (const Vec3& u : fibonacci_lights(40, 0.12, 1.3)) {
        const std::vector<float> relit = relight_lafortune(*fit, u);
        for (int c = 0; c < 3; ++c) CHECK(relit[c] == doctest::Approx(texels[c].value(u)).epsilon(1e-3).scale(1));
    }
}

TEST_CASE("lafortune fit: Levenberg-Marquardt converges to the lobes from perturbed starts")
{
    const std::vector<Vec3> lights = fibonacci_lights(100, 0.1);
    const LobeLights solver_lights(lights);
    std::mt19937_64 rng(3);
    std::normal_distribution<double> jitter(0, 1);
    for (const AxisTexel& truth : two_lobe_texels()) {
        std::vector<double> values;
        for (const Vec3& u : lights) values.push_back(truth.value(u));
        for (int trial = 0; trial < 4; ++trial) {
            // Each axis turned by about 8 degrees, each exponent by a
            // factor of about 1.6.
            std::vector<LobeShape> start;
            for (std::size_t i = 0; i < truth.axes.size(); ++i) {
                const Vec3 w = normalize(truth.axes[i]);
                const Vec3 turned = normalize(w + 0.14 * Vec3{jitter(rng), jitter(rng), 0});
                start.push_back(lobe_shape(turned, truth.exponents[i] * std::exp(0.5 * jitter(rng))));
            }
            // The fit's own stopping rule: close; run on: exact.
            ScalarLobeSettings settings;
            const ScalarLobeFit quick = refine_lobes(solver_lights, values.data(), start, settings);
            CHECK(quick.fallbacks == 0);
            CHECK(std::sqrt(quick.sse / lights.size()) < 1e-4);
            settings.max_iterations = 100;
            settings.function_tolerance = 1e-12;
            const ScalarLobeFit fit = refine_lobes(solver_lights, values.data(), start, settings);
            CHECK(fit.fallbacks == 0);
            CHECK(std::sqrt(fit.sse / lights.size()) < 1e-7);
            CHECK(fit.rho == doctest::Approx(truth.rho).epsilon(1e-5));
            for (std::size_t i = 0; i < truth.axes.size(); ++i) {
                CHECK(angle_between(lobe_shape_axis(fit.shapes[i]), truth.axes[i]) < 1e-5);
                CHECK(lobe_shape_exponent(fit.shapes[i]) == doctest::Approx(truth.exponents[i]).epsilon(1e-5));
                CHECK(fit.scales[i] ==
                      doctest::Approx(std::pow(length(truth.axes[i]), truth.exponents[i])).epsilon(1e-5));
            }
        }
    }
}

TEST_CASE("lafortune fit: the same parameters on 1 and 2 threads")
{
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<AxisTexel> texels;
    std::vector<std::vector<double>> colours;
    for (int t = 0; t < 12; ++t) {
        const std::vector<AxisTexel> base = two_lobe_texels();
        texels.push_back(base[t % 3]);
        texels.back().rho *= 0.5 + unit(rng);
        colours.push_back({0.2 + unit(rng), 0.2 + unit(rng), 0.2 + unit(rng)});
    }
    ImageStack stack = stack_from_texels(texels, colours, fibonacci_lights(40, 0.1));
    for (float& v : stack.pixels) v += static_cast<float>(0.01 * (unit(rng) - 0.5));
    stack.width = 4;
    stack.height = 3;
    for (bool automatic : {false, true}) {
        LafortuneFitOptions options;
        options.spacing_cap = 0;  // lobes sharper than the gaps between lights, recovered exactly
        options.lobes = 3;
        options.auto_lobes = automatic;
        options.tolerance = 1e-3;
        options.threads = 1;
        const auto one = fit_lafortune(stack, options);
        options.threads = 2;
        const auto two = fit_lafortune(stack, options);
        REQUIRE(one);
        REQUIRE(two);
        CHECK(one->parameters == two->parameters);
        CHECK(one->lobe_counts == two->lobe_counts);
        CHECK(one->fallbacks == two->fallbacks);
    }
}

TEST_CASE("lafortune fit: auto lobes count 1, 2 and 3 on texels made with 1, 2 and 3 lobes")
{
    const std::vector<AxisTexel> texels = {
        {0.3, {scaled_axis({0.2, 0.3, 1}, 0.6, 20)}, {20}},
        {0.2, {scaled_axis({0.2, 0.3, 1}, 0.6, 20), scaled_axis({-0.9, 0.2, 1}, 0.4, 6)}, {20, 6}},
        {0.1,
         {scaled_axis({0.2, 0.3, 1}, 0.6, 20), scaled_axis({-0.9, 0.2, 1}, 0.4, 6), scaled_axis({0.5, -1, 1}, 0.5, 50)},
         {20, 6, 50}},
        {0.4, {}, {}},
    };
    const std::vector<std::vector<double>> colours(4, {1.0});
    const ImageStack stack = stack_from_texels(texels, colours, fibonacci_lights(120, 0.1));
    LafortuneFitOptions options;
    options.spacing_cap = 0;  // lobes sharper than the gaps between lights, recovered exactly
    options.lobes = 7;
    options.auto_lobes = true;
    options.tolerance = 1e-4;
    const auto fit = fit_lafortune(stack, options);
    REQUIRE(fit);
    CHECK(static_cast<int>(fit->lobe_counts[0]) == 1);
    CHECK(static_cast<int>(fit->lobe_counts[1]) == 2);
    CHECK(static_cast<int>(fit->lobe_counts[2]) == 3);
    CHECK(static_cast<int>(fit->lobe_counts[3]) == 0);
    CHECK(fit->lobe_histogram() == std::vector<long long>{1, 1, 1, 1, 0, 0, 0, 0});
    // Each within the tolerance at the stack's lights.
    for (std::size_t t = 0; t < texels.size(); ++t) {
        double sum = 0;
        for (int k = 0; k < stack.count(); ++k) {
            const double d = relight_lafortune(*fit, stack.lights[k])[t] - texels[t].value(stack.lights[k]);
            sum += d * d;
        }
        CHECK(std::sqrt(sum / stack.count()) <= 1e-4);
    }
}

TEST_CASE("lafortune fit: bad options and stacks refused by name")
{
    const std::vector<AxisTexel> texels = two_lobe_texels();
    const ImageStack stack = stack_from_texels(texels, {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}}, fibonacci_lights(12));
    auto refused = [&](const LafortuneFitOptions& options, const std::string& field, const std::string& words,
                       const ImageStack& s) {
        const auto fit = fit_lafortune(s, options);
        REQUIRE_FALSE(fit);
        CHECK(fit.error().kind == ErrorKind::BadInput);
        CHECK(fit.error().field == field);
        CHECK(contains(fit.error().message, field));
        CHECK(contains(fit.error().message, words));
    };
    LafortuneFitOptions o;
    o.lobes = 3;  // 13 parameters for 12 lights
    refused(o, "LafortuneFitOptions::lobes", "needs at least 13 lights", stack);
    o.lobes = 2;  // 9: fits
    CHECK(fit_lafortune(stack, o));
    o.lobes = 0;
    refused(o, "LafortuneFitOptions::lobes", "1 to 7", stack);
    o.lobes = 8;
    refused(o, "LafortuneFitOptions::lobes", "1 to 7", stack);
    o = {};
    o.variant = LafortuneVariant::Rgb;
    o.lobes = 3;
    refused(o, "LafortuneFitOptions::lobes", "1 to 2", stack);
    o = {};
    o.auto_lobes = true;
    o.tolerance = 0;
    refused(o, "LafortuneFitOptions::tolerance", "above 0", stack);
    o.tolerance = -1;
    refused(o, "LafortuneFitOptions::tolerance", "above 0", stack);
    o = {};
    o.view = {0.5, 0, -0.1};
    refused(o, "LafortuneFitOptions::view", "above the horizon", stack);
    o.view = {1, 0, 0};
    refused(o, "LafortuneFitOptions::view", "above the horizon", stack);
    o = {};
    o.min_gain = 1;
    refused(o, "LafortuneFitOptions::min_gain", "[0, 1)", stack);
    o = {};
    o.max_iterations = 0;
    refused(o, "LafortuneFitOptions::max_iterations", "at least 1", stack);
    o = {};
    o.function_tolerance = 0;
    refused(o, "LafortuneFitOptions::function_tolerance", "(0, 1)", stack);
    // Channels: rgb takes 3, luminance 1 or 3.
    ImageStack grey = stack_from_texels(texels, {{1}, {1}, {1}}, fibonacci_lights(12));
    o = {};
    CHECK(fit_lafortune(grey, o));
    o.variant = LafortuneVariant::Rgb;
    refused(o, "LafortuneFitOptions::variant", "3-channel", grey);
    ImageStack four = stack_from_texels(texels, {{1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 1}}, fibonacci_lights(12));
    refused(o, "LafortuneFitOptions::variant", "4 channels", four);
    o.variant = LafortuneVariant::Luminance;
    refused(o, "LafortuneFitOptions::variant", "4 channels", four);
}

TEST_CASE("lafortune fit: finite parameters and relit values on noise, for random lights and views")
{
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<float> unit(0, 1);
    const std::vector<Vec3> lights = fibonacci_lights(30, 0.05);
    ImageStack stack;
    stack.width = 4;
    stack.height = 2;
    stack.channels = 3;
    stack.lights = lights;
    stack.pixels.resize(lights.size() * stack.texels() * 3);
    // Noise, spikes, zeros and negative values.
    for (std::size_t i = 0; i < stack.pixels.size(); ++i) {
        const float r = unit(rng);
        stack.pixels[i] = i % 97 == 0 ? 20.0f : i % 13 == 0 ? 0.0f : i % 17 == 0 ? -0.2f : r;
    }
    for (auto variant : {LafortuneVariant::Luminance, LafortuneVariant::Rgb}) {
        LafortuneFitOptions options;
        options.variant = variant;
        options.lobes = 2;
        const auto fit = fit_lafortune(stack, options);
        REQUIRE(fit);
        for (float p : fit->parameters) CHECK(std::isfinite(p));
        std::uniform_real_distribution<double> z(0, 1), phi(0, 6.283185307179586);
        for (int trial = 0; trial < 50; ++trial) {
            const double lz = z(rng), lr = std::sqrt(1 - lz * lz), lp = phi(rng);
            const double vz = 0.01 + 0.99 * z(rng), vr = std::sqrt(1 - vz * vz), vp = phi(rng);
            const Vec3 u{lr * std::cos(lp), lr * std::sin(lp), lz}, v{vr * std::cos(vp), vr * std::sin(vp), vz};
            for (float x : relight_lafortune(*fit, u, v, 1)) CHECK(std::isfinite(x));
        }
    }
}
