// SPDX-License-Identifier: Apache-2.0
// Normals from linear fits: the maximum of a PTM made from a polynomial
// with a known maximum, a Lambertian surface's normals recovered by PTM and
// HSH fits, the degenerate polynomials counted and their maxima over the
// hemisphere against a brute-force search.
#include "cmfilter/stack/fit_normals.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

using namespace cmfilter;

namespace {

constexpr double kPi = 3.14159265358979323846;

Vec3 direction(double elevation_deg, double azimuth_deg)
{
    const double e = elevation_deg * kPi / 180, a = azimuth_deg * kPi / 180;
    return {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
}

double angle_deg(const Vec3& a, const Vec3& b)
{
    const double c = dot(a, b) / std::sqrt(dot(a, a) * dot(b, b));
    return std::acos(std::clamp(c, -1.0, 1.0)) * 180 / kPi;
}

Vec3 normal_of(const FitNormals& n, std::size_t t)
{
    return {n.normals[3 * t], n.normals[3 * t + 1], n.normals[3 * t + 2]};
}

// Rings of lights from `min_elevation` to 80 degrees and one at the pole.
std::vector<Vec3> dome(double min_elevation)
{
    std::vector<Vec3> lights{{0, 0, 1}};
    for (int ring = 0; ring < 4; ++ring) {
        const double el = min_elevation + (80 - min_elevation) * ring / 3;
        for (int i = 0; i < 12; ++i) lights.push_back(direction(el, 30.0 * i + 11 * ring));
    }
    return lights;
}

// A PTM fit of one channel whose texels hold the given coefficients.
LinearFit ptm_fit(const std::vector<std::array<double, 6>>& texels)
{
    LinearFit fit;
    fit.model = LinearModel::PtmRgb;
    fit.width = static_cast<int>(texels.size());
    fit.height = 1;
    fit.channels = 1;
    for (const auto& a : texels)
        for (double v : a) fit.coefficients.push_back(static_cast<float>(v));
    return fit;
}

// The maximum of f over the hemisphere by brute force: a fine grid in
// (elevation, azimuth) of 0.2 degrees.
template <typename F>
Vec3 brute_force_maximum(F f)
{
    Vec3 best{0, 0, 1};
    double best_value = f(best);
    for (int i = 0; i <= 450; ++i)
        for (int j = 0; j < 1800; j += (i == 450 ? 1800 : 1)) {
            const Vec3 l = direction(0.2 * i, 0.2 * j);
            const double v = f(l);
            if (v > best_value) {
                best_value = v;
                best = l;
            }
        }
    return best;
}

}  // namespace

TEST_CASE("fit normals: a PTM's interior maximum is its stationary point")
{
    // P = -(1.2 du^2 + 0.8 dv^2 - 0.4 du dv) + 0.6, du = lu - u0, dv = lv - v0:
    // negative definite, so its maximum is at (u0, v0).
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> centre(-0.6, 0.6);
    std::vector<std::array<double, 6>> texels;
    std::vector<Vec3> truth;
    for (int i = 0; i < 20; ++i) {
        const double u0 = centre(rng), v0 = centre(rng) * 0.6;
        const double p = 1.2, q = 0.8, r = -0.4;  // -(p du^2 + q dv^2 + r du dv)
        texels.push_back(
            {-p, -q, -r, 2 * p * u0 + r * v0, 2 * q * v0 + r * u0, 0.6 - p * u0 * u0 - q * v0 * v0 - r * u0 * v0});
        truth.push_back({u0, v0, std::sqrt(1 - u0 * u0 - v0 * v0)});
    }
    const FitNormals n = fit_normals(ptm_fit(texels), 2);
    CHECK(n.width == 20);
    CHECK(n.height == 1);
    CHECK(n.degenerate == 0);
    for (std::size_t t = 0; t < truth.size(); ++t) {
        CHECK(n.normals[3 * t] == doctest::Approx(truth[t].x).epsilon(1e-5));
        CHECK(n.normals[3 * t + 1] == doctest::Approx(truth[t].y).epsilon(1e-5));
        CHECK(n.normals[3 * t + 2] == doctest::Approx(truth[t].z).epsilon(1e-5));
    }
}

TEST_CASE("fit normals: degenerate polynomials are counted and maximised over the hemisphere")
{
    const std::vector<std::array<double, 6>> texels = {
        {1, -1, 0, 0.2, 0, 0},        // saddle
        {1, 1, 0.5, 0.1, -0.3, 0},    // minimum
        {-1, -1, 0, 3, 0, 0},         // maximum at (1.5, 0), outside the disc
        {0, 0, 0, 0, 0, 0.7},         // flat
        {0, 0, 0, 0.3, 0.4, 0.1},     // a plane: no stationary point
        {-1, -1, 0, 0.4, -0.2, 0.5},  // a proper maximum, not degenerate
    };
    const FitNormals n = fit_normals(ptm_fit(texels), 1);
    CHECK(n.degenerate == 5);
    for (std::size_t t = 0; t < texels.size(); ++t) {
        CAPTURE(t);
        const auto& a = texels[t];
        const auto poly = [&](const Vec3& l) {
            return a[0] * l.x * l.x + a[1] * l.y * l.y + a[2] * l.x * l.y + a[3] * l.x + a[4] * l.y + a[5];
        };
        const Vec3 got = normal_of(n, t);
        CHECK(dot(got, got) == doctest::Approx(1.0).epsilon(1e-6));
        CHECK(got.z >= 0);
        if (t == 3) {
            CHECK(got.z == doctest::Approx(1.0));
            continue;
        }
        // The value reached is the brute-force maximum's (to its grid).
        const Vec3 best = brute_force_maximum(poly);
        CHECK(poly(got) >= poly(best) - 1e-6);
        CHECK(angle_deg(got, best) < 0.5);
    }
}

TEST_CASE("fit normals: PTM and HSH fits of a Lambertian surface recover its normals")
{
    // Normals within 25 degrees of the pole and lights from 40 degrees of
    // elevation up: n . l > 0 for every pair, so the clamp never bites and
    // each texel's value is albedo n . l. A PTM's quadratic only
    // approximates the n_z sqrt(1 - lu^2 - lv^2) part, so its maximum is a
    // few degrees off (under 3 degrees here); HSH 3 comes closer.
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> tilt(0, 25), azimuth(0, 360), albedo(0.3, 0.9);
    const auto lights = dome(40);
    ImageStack stack;
    stack.width = 8;
    stack.height = 6;
    stack.channels = 3;
    stack.lights = lights;
    stack.pixels.resize(lights.size() * stack.texels() * 3);
    std::vector<Vec3> truth;
    for (std::size_t t = 0; t < stack.texels(); ++t) {
        const Vec3 n = direction(90 - tilt(rng), azimuth(rng));
        truth.push_back(n);
        const double rho[3] = {albedo(rng), albedo(rng), albedo(rng)};
        for (int k = 0; k < stack.count(); ++k) {
            const double d = dot(n, lights[static_cast<std::size_t>(k)]);
            REQUIRE(d > 0);
            for (int c = 0; c < 3; ++c) stack.image(k)[t * 3 + c] = static_cast<float>(rho[c] * d);
        }
    }
    for (LinearModel model : {LinearModel::PtmRgb, LinearModel::PtmLrgb, LinearModel::Hsh3}) {
        const std::string model_name = to_string(model);
        CAPTURE(model_name);
        LinearFitOptions options;
        options.model = model;
        auto fit = fit_linear(stack, options);
        REQUIRE(fit);
        const FitNormals n = fit_normals(*fit, 2);
        REQUIRE(n.normals.size() == stack.texels() * 3);
        double worst = 0;
        for (std::size_t t = 0; t < stack.texels(); ++t) worst = std::max(worst, angle_deg(normal_of(n, t), truth[t]));
        MESSAGE(std::string(to_string(model))
                << ": largest normal error " << worst << " degrees, " << n.degenerate << " degenerate");
        CHECK(worst < (model == LinearModel::Hsh3 ? 1.0 : 4.0));
        if (model != LinearModel::Hsh3) CHECK(n.degenerate == 0);
    }
}

TEST_CASE("fit normals: an RGB fit uses the Rec. 709 luminance of its channels")
{
    // Each channel a paraboloid with its own maximum; the luminance is the
    // weighted sum, whose maximum is found here by brute force.
    LinearFit fit;
    fit.model = LinearModel::PtmRgb;
    fit.width = 1;
    fit.height = 1;
    fit.channels = 3;
    const double centres[3][2] = {{0.5, 0.1}, {-0.2, 0.3}, {0.1, -0.7}};
    for (const auto& c : centres) {
        const double coefficients[6] = {-1, -1, 0, 2 * c[0], 2 * c[1], 1 - c[0] * c[0] - c[1] * c[1]};
        for (double v : coefficients) fit.coefficients.push_back(static_cast<float>(v));
    }
    const auto luminance = [&](const Vec3& l) {
        double y = 0;
        const double w[3] = {0.2126, 0.7152, 0.0722};
        for (int c = 0; c < 3; ++c)
            y += w[c] * (1 - std::pow(l.x - centres[c][0], 2) - std::pow(l.y - centres[c][1], 2));
        return y;
    };
    const FitNormals n = fit_normals(fit, 1);
    CHECK(n.degenerate == 0);
    CHECK(angle_deg(normal_of(n, 0), brute_force_maximum(luminance)) < 0.15);
}

TEST_CASE("fit normals: an HSH fit's normal is the maximum over the hemisphere")
{
    // Six texels of random HSH 3 coefficients and a flat one (h0 alone).
    std::mt19937_64 rng(6);
    std::uniform_real_distribution<float> coefficient(-1, 1);
    LinearFit fit;
    fit.model = LinearModel::Hsh3;
    fit.width = 7;
    fit.height = 1;
    fit.channels = 1;
    for (int i = 0; i < 6 * 9; ++i) fit.coefficients.push_back(coefficient(rng));
    fit.coefficients.push_back(0.5f);
    for (int k = 1; k < 9; ++k) fit.coefficients.push_back(0.0f);
    const FitNormals n = fit_normals(fit, 2);
    std::size_t on_horizon = 0;
    for (std::size_t t = 0; t < 6; ++t) {
        CAPTURE(t);
        const auto value = [&](const Vec3& l) {
            const auto b = evaluate_basis(LinearModel::Hsh3, l);
            double v = 0;
            for (int k = 0; k < 9; ++k) v += fit.texel(t)[k] * b[static_cast<std::size_t>(k)];
            return v;
        };
        const Vec3 best = brute_force_maximum(value);
        if (best.z < 1e-12) ++on_horizon;
        const Vec3 got = normal_of(n, t);
        CHECK(value(got) >= value(best) - 1e-6);
        CHECK(angle_deg(got, best) < 0.5);
    }
    CHECK(normal_of(n, 6).z == 1.0);
    CHECK(n.degenerate == on_horizon + 1);
}
