// SPDX-License-Identifier: Apache-2.0
// The Lafortune fit's remedies for uneven domes (lafortune_fit.h): density
// weights against a stack whose dense lights are duplicates (a light given
// weight 1/3 three times is one light), the exponent cap against the
// spacing formula, the exponent penalty against the penalised cost written
// out here, the relative weights against the same weights given by hand;
// remedies that change nothing leave the fit bit for bit; bad values
// refused by name.
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

constexpr double kPi = 3.14159265358979323846;

// Texels no 2 lobes fit exactly: 3 lobes, one sharp, plus a cosine dip.
std::vector<AxisTexel> hard_texels()
{
    return {
        {0.20,
         {scaled_axis({0.3, 0.1, 1}, 0.6, 60), scaled_axis({-0.8, 0.5, 1}, 0.3, 5), scaled_axis({0, -0.7, 1}, 0.2, 20)},
         {60, 5, 20}},
        {0.05,
         {scaled_axis({0, -0.4, 1}, 1.2, 150), scaled_axis({0.9, 0.9, 1}, 0.4, 3), scaled_axis({-0.6, 0, 1}, 0.3, 40)},
         {150, 3, 40}},
    };
}

double lobe_half_width_exponent(double spacing) { return std::log(0.5) / std::log(std::cos(spacing / 2)); }

// The fit's exponents in use.
std::vector<double> exponents(const LafortuneFit& fit)
{
    std::vector<double> out;
    for (std::size_t t = 0; t < fit.texels(); ++t)
        for (int i = 0; i < fit.lobes; ++i) {
            const float* s = fit.texel(t) + 1 + 4 * i;
            if (s[0] != 0 || s[1] != 0 || s[2] != 0) out.push_back(s[3]);
        }
    return out;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("lafortune remedies: every remedy at a value that changes nothing leaves the fit bit for bit")
{
    const ImageStack stack = stack_from_texels(hard_texels(), {{0.9, 0.6, 0.3}, {0.2, 0.5, 0.8}}, fibonacci_lights(40));
    LafortuneFitOptions plain;
    plain.lobes = 2;
    plain.threads = 1;
    plain.spacing_cap = 0;
    const auto reference = fit_lafortune(stack, plain);
    REQUIRE(reference);
    // A density radius with no other light inside it (weights all exactly 1),
    // and a cap wider than kLafortuneMaxExponent allows (spacing 1e-4).
    LafortuneFitOptions same = plain;
    same.density_radius = 1e-3;
    same.spacing_cap = 1e-4;
    CHECK(lafortune_max_exponent(stack.lights, same) == kLafortuneMaxExponent);
    for (double w : lafortune_light_weights(stack.lights, same)) CHECK(w == 1.0);
    const auto fit = fit_lafortune(stack, same);
    REQUIRE(fit);
    CHECK(fit->parameters == reference->parameters);
    CHECK(fit->lobe_counts == reference->lobe_counts);
}

TEST_CASE("lafortune remedies: density weights make three coincident lights count as one")
{
    // The dense set: every light of a cluster on a low +x arc three times
    // (coincident); the sparse set: each once. Density weights with a radius
    // that takes in only coincident lights give each copy a third of the
    // others' weight: the weighted fit of the dense set, from the same start,
    // is the fit of the sparse set (its SSE scaled by the weights' mean-1
    // factor).
    const AxisTexel texel = hard_texels()[0];
    std::vector<Vec3> sparse = fibonacci_lights(30, 0.15);
    std::vector<Vec3> arc;
    for (int i = 0; i < 8; ++i) {
        const double a = (-35 + 10 * i) * kPi / 180, e = 12 * kPi / 180;
        arc.push_back({std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)});
    }
    std::vector<Vec3> dense = sparse;
    sparse.insert(sparse.end(), arc.begin(), arc.end());
    for (int copy = 0; copy < 3; ++copy) dense.insert(dense.end(), arc.begin(), arc.end());
    std::vector<double> sparse_values, dense_values;
    for (const Vec3& u : sparse) sparse_values.push_back(texel.value(u));
    for (const Vec3& u : dense) dense_values.push_back(texel.value(u));
    LafortuneFitOptions options;
    options.density_radius = 0.5;  // the nearest distinct lights are over 5 degrees apart
    const std::vector<double> weights = lafortune_light_weights(dense, options);
    const double factor = double(dense.size()) / (30 + 8);  // the mean-1 scaling of weights 1 and 1/3
    for (std::size_t k = 0; k < dense.size(); ++k)
        CHECK(weights[k] == doctest::Approx((k < 30 ? 1.0 : 1.0 / 3) * factor));
    const std::vector<LobeShape> start{lobe_shape({0.2, 0.1, 1}, 30), lobe_shape({-0.5, 0.4, 1}, 4)};
    ScalarLobeSettings settings;
    settings.max_iterations = 50;
    const ScalarLobeFit weighted = refine_lobes(LobeLights(dense, weights), dense_values.data(), start, settings);
    const ScalarLobeFit reference = refine_lobes(LobeLights(sparse), sparse_values.data(), start, settings);
    const ScalarLobeFit unweighted = refine_lobes(LobeLights(dense), dense_values.data(), start, settings);
    CHECK(weighted.sse == doctest::Approx(reference.sse * factor).epsilon(1e-6));
    auto model = [](const ScalarLobeFit& f, const Vec3& u) {
        double v = f.rho;
        for (std::size_t i = 0; i < f.shapes.size(); ++i) {
            const double d = dot(lobe_shape_axis(f.shapes[i]), u);
            if (d > 0) v += f.scales[i] * std::pow(d, lobe_shape_exponent(f.shapes[i]));
        }
        return u.z * v;
    };
    double same = 0, differ = 0;
    for (const Vec3& u : fibonacci_lights(50, 0.1, 0.9)) {
        same = std::max(same, std::abs(model(weighted, u) - model(reference, u)));
        differ = std::max(differ, std::abs(model(unweighted, u) - model(reference, u)));
    }
    CHECK(same < 1e-5);
    // Unweighted, the duplicates pull the fit elsewhere (the check above can fail).
    CHECK(differ > 1e-3);
}

TEST_CASE("lafortune remedies: the exponent cap is the spacing formula, and no exponent exceeds it")
{
    const std::vector<Vec3> lights = fibonacci_lights(60, 0.1);
    // The mean nearest-neighbour spacing by brute force.
    double spacing = 0;
    for (const Vec3& a : lights) {
        double nearest = kPi;
        for (const Vec3& b : lights)
            if (&a != &b) nearest = std::min(nearest, std::acos(std::clamp(dot(a, b), -1.0, 1.0)));
        spacing += nearest / lights.size();
    }
    LafortuneFitOptions options;
    options.lobes = 3;
    options.threads = 1;
    options.spacing_cap = 1;
    const double cap = lafortune_max_exponent(lights, options);
    CHECK(cap == doctest::Approx(lobe_half_width_exponent(spacing)).epsilon(1e-9));
    CHECK(cap < 150);  // the sharpest true lobe is capped
    options.spacing_cap = 1.5;
    CHECK(lafortune_max_exponent(lights, options) ==
          doctest::Approx(lobe_half_width_exponent(1.5 * spacing)).epsilon(1e-9));
    options.spacing_cap = 100;  // wider than any lobe: the floor of 2
    CHECK(lafortune_max_exponent(lights, options) == 2);
    options.spacing_cap = 1;
    const auto fit = fit_lafortune(stack_from_texels(hard_texels(), {{1.0}, {1.0}}, lights), options);
    REQUIRE(fit);
    const std::vector<double> n = exponents(*fit);
    REQUIRE(!n.empty());
    for (double x : n) CHECK(x <= cap * (1 + 1e-6));
    options.spacing_cap = 0;
    const auto free_fit = fit_lafortune(stack_from_texels(hard_texels(), {{1.0}, {1.0}}, lights), options);
    REQUIRE(free_fit);
    const std::vector<double> m = exponents(*free_fit);
    CHECK(*std::max_element(m.begin(), m.end()) > cap);  // without the cap, sharper lobes are fitted
}

TEST_CASE("lafortune remedies: the exponent penalty lowers the exponent and the penalised cost")
{
    // One lobe of exponent 60 fitted with 1 lobe: exact without the penalty.
    const std::vector<Vec3> lights = fibonacci_lights(80, 0.1);
    const AxisTexel texel{0.1, {scaled_axis({0.2, -0.1, 1}, 0.8, 60)}, {60}};
    std::vector<double> values;
    double energy = 0;
    for (const Vec3& u : lights) {
        values.push_back(texel.value(u));
        energy += values.back() * values.back();
    }
    const LobeLights lobe_lights(lights);
    ScalarLobeSettings settings;
    settings.lobes = 1;
    const ScalarLobeFit plain = fit_scalar_lobes(lobe_lights, values.data(), settings);
    REQUIRE(plain.shapes.size() == 1);
    CHECK(lobe_shape_exponent(plain.shapes[0]) == doctest::Approx(60).epsilon(1e-3));
    settings.exponent_penalty = 0.01;
    const ScalarLobeFit penalised = fit_scalar_lobes(lobe_lights, values.data(), settings);
    REQUIRE(penalised.shapes.size() == 1);
    const double n = lobe_shape_exponent(penalised.shapes[0]);
    CHECK(n < 0.98 * 60);
    // The penalised cost, written out: SSE + 0.01 E (ln n / ln 500)^2.
    auto cost = [&](const ScalarLobeFit& f) {
        const double e = lobe_shape_exponent(f.shapes[0]);
        const Vec3 w = lobe_shape_axis(f.shapes[0]);
        double sse = 0;
        for (std::size_t k = 0; k < lights.size(); ++k) {
            const double d = dot(w, lights[k]);
            const double model = lights[k].z * (f.rho + (d > 0 ? f.scales[0] * std::pow(d, e) : 0));
            sse += (model - values[k]) * (model - values[k]);
        }
        const double r = std::log(e) / std::log(500.0);
        return sse + 0.01 * energy * r * r;
    };
    CHECK(cost(penalised) < cost(plain));
    CHECK(penalised.penalty == doctest::Approx(0.01 * energy * std::pow(std::log(n) / std::log(500.0), 2)));
}

TEST_CASE("lafortune remedies: relative weights are 1 / (value + epsilon)^2, scaled to mean 1")
{
    const std::vector<Vec3> lights = fibonacci_lights(40, 0.1);
    const ImageStack stack = stack_from_texels(hard_texels(), {{1.0}, {1.0}}, lights);
    LafortuneFitOptions options;
    options.lobes = 2;
    options.threads = 1;
    options.relative_epsilon = 0.02;
    options.spacing_cap = 0;
    const auto fit = fit_lafortune(stack, options);
    REQUIRE(fit);
    ScalarLobeSettings settings;
    settings.lobes = 2;
    for (int t = 0; t < stack.width; ++t) {
        std::vector<double> values, weights;
        double sum = 0;
        for (int k = 0; k < stack.count(); ++k) {
            values.push_back(stack.image(k)[t]);
            weights.push_back(1 / std::pow(values.back() + 0.02, 2));
            sum += weights.back();
        }
        for (double& w : weights) w *= stack.count() / sum;
        const ScalarLobeFit s = fit_scalar_lobes(LobeLights(lights, weights), values.data(), settings);
        // The same fit (up to the weights' rounding): the same relit values.
        for (const Vec3& u : fibonacci_lights(20, 0.2, 0.7)) {
            double expected = s.rho;
            for (std::size_t i = 0; i < s.shapes.size(); ++i) {
                const double d = dot(lobe_shape_axis(s.shapes[i]), u);
                if (d > 0) expected += s.scales[i] * std::pow(d, lobe_shape_exponent(s.shapes[i]));
            }
            // The base colour of a one-channel stack (lafortune_model.h):
            // sum_k I_k Yf_k / sum_k Yf_k^2 over the training lights.
            double cross = 0, fitted2 = 0;
            for (int k = 0; k < stack.count(); ++k) {
                const Vec3& l = lights[k];
                double yf = s.rho;
                for (std::size_t i = 0; i < s.shapes.size(); ++i) {
                    const double d = dot(lobe_shape_axis(s.shapes[i]), l);
                    if (d > 0) yf += s.scales[i] * std::pow(d, lobe_shape_exponent(s.shapes[i]));
                }
                yf *= l.z;
                cross += values[k] * yf;
                fitted2 += yf * yf;
            }
            expected *= u.z * cross / fitted2;
            CHECK(relight_lafortune(*fit, u, 1)[t] == doctest::Approx(expected).epsilon(1e-4).scale(1e-3));
        }
    }
    // Relative weighting fits the darkest values relatively better.
    options.relative_epsilon = 0;
    const auto absolute = fit_lafortune(stack, options);
    REQUIRE(absolute);
    auto worst_dark = [&](const LafortuneFit& f) {
        double worst = 0;
        for (int k = 0; k < stack.count(); ++k) {
            const std::vector<float> relit = relight_lafortune(f, stack.lights[k], 1);
            for (int t = 0; t < stack.width; ++t) {
                const double y = stack.image(k)[t];
                if (y < 0.05) worst = std::max(worst, std::abs(relit[t] - y) / (y + 0.02));
            }
        }
        return worst;
    };
    CHECK(worst_dark(*fit) < worst_dark(*absolute));
}

TEST_CASE("lafortune remedies: bad values refused by name")
{
    const ImageStack stack = stack_from_texels(hard_texels(), {{1.0}, {1.0}}, fibonacci_lights(30));
    auto refused = [&](LafortuneFitOptions o, const std::string& field) {
        const auto fit = fit_lafortune(stack, o);
        REQUIRE(!fit);
        CHECK(fit.error().field == field);
        CHECK(contains(fit.error().message, field));
    };
    LafortuneFitOptions o;
    o.density_radius = -1;
    refused(o, "LafortuneFitOptions::density_radius");
    o.density_radius = 91;
    refused(o, "LafortuneFitOptions::density_radius");
    o = {};
    o.spacing_cap = -0.5;
    refused(o, "LafortuneFitOptions::spacing_cap");
    o.spacing_cap = std::nan("");
    refused(o, "LafortuneFitOptions::spacing_cap");
    o = {};
    o.exponent_penalty = -1e-3;
    refused(o, "LafortuneFitOptions::exponent_penalty");
    o = {};
    o.relative_epsilon = INFINITY;
    refused(o, "LafortuneFitOptions::relative_epsilon");
}

TEST_CASE("lafortune remedies: the default cap is twice the spacing")
{
    const std::vector<Vec3> lights = fibonacci_lights(64, 0.1);
    const LafortuneFitOptions defaults;
    CHECK(defaults.spacing_cap == 2);
    LafortuneFitOptions off;
    off.spacing_cap = 0;
    CHECK(lafortune_max_exponent(lights, off) == kLafortuneMaxExponent);
    double spacing = 0;
    for (const Vec3& a : lights) {
        double nearest = kPi;
        for (const Vec3& b : lights)
            if (&a != &b) nearest = std::min(nearest, std::acos(std::clamp(dot(a, b), -1.0, 1.0)));
        spacing += nearest / lights.size();
    }
    CHECK(lafortune_max_exponent(lights, defaults) == doctest::Approx(lobe_half_width_exponent(2 * spacing)));
}
