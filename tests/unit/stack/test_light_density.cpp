// SPDX-License-Identifier: Apache-2.0
// Light-density weights against a brute-force count by cosines, the mean
// spacing of rings of lights against the spherical law of cosines, and the
// lobe-width exponent against its definition (the lobe at half its peak).
#include "cmfilter/stack/light_density.h"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using namespace cmfilter;

namespace {

constexpr double kPi = 3.14159265358979323846;

Vec3 at(double azimuth_deg, double elevation_deg)
{
    const double a = azimuth_deg * kPi / 180, e = elevation_deg * kPi / 180;
    return {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
}

}  // namespace

TEST_CASE("light density: weights are 1 / (lights within the radius), mean 1, as counted by cosines")
{
    // A dense low arc on +x and a few lights elsewhere.
    std::vector<Vec3> lights;
    for (int i = 0; i < 12; ++i) lights.push_back(at(-30 + 5 * i, 10));
    for (int i = 0; i < 6; ++i) lights.push_back(at(60 * i + 90, 45));
    lights.push_back(at(0, 90));
    const double radius = 12 * kPi / 180;
    const std::vector<double> w = light_density_weights(lights, radius);
    REQUIRE(w.size() == lights.size());
    std::vector<double> expected(lights.size());
    double sum = 0;
    for (std::size_t k = 0; k < lights.size(); ++k) {
        int count = 0;
        for (const Vec3& l : lights)
            if (l.x * lights[k].x + l.y * lights[k].y + l.z * lights[k].z >= std::cos(radius) - 1e-12) ++count;
        expected[k] = 1.0 / count;
        sum += expected[k];
    }
    double mean = 0;
    for (std::size_t k = 0; k < lights.size(); ++k) {
        CHECK(w[k] == doctest::Approx(expected[k] * lights.size() / sum).epsilon(1e-12));
        mean += w[k] / lights.size();
    }
    CHECK(mean == doctest::Approx(1.0).epsilon(1e-12));
    // The arc's end lights (2 neighbours within 12 degrees: 3 lights) weigh
    // more than its middle ones (5), the isolated ones most.
    CHECK(w[0] > w[5]);
    CHECK(w[12] > w[0]);
    // No radius, or no light within it: every weight exactly 1.
    for (double r : {0.0, 1e-3})
        for (double x : light_density_weights(lights, r)) CHECK(x == 1.0);
}

TEST_CASE("light density: the mean spacing of rings of lights, by the spherical law of cosines")
{
    for (int n : {8, 24})
        for (double elevation : {0.0, 30.0, 60.0}) {
            std::vector<Vec3> ring;
            for (int i = 0; i < n; ++i) ring.push_back(at(360.0 * i / n, elevation));
            const double e = elevation * kPi / 180;
            const double expected =
                std::acos(std::sin(e) * std::sin(e) + std::cos(e) * std::cos(e) * std::cos(2 * kPi / n));
            CHECK(mean_light_spacing(ring) == doctest::Approx(expected).epsilon(1e-9));
        }
    // Two rings: the inner lights' nearest is their ring's neighbour, the
    // outer ones' too; the mean of both.
    std::vector<Vec3> two;
    for (int i = 0; i < 6; ++i) two.push_back(at(60 * i, 80));
    for (int i = 0; i < 36; ++i) two.push_back(at(10 * i, 5));
    const double inner =
        std::acos(std::pow(std::sin(80 * kPi / 180), 2) + std::pow(std::cos(80 * kPi / 180), 2) * std::cos(kPi / 3));
    const double outer =
        std::acos(std::pow(std::sin(5 * kPi / 180), 2) + std::pow(std::cos(5 * kPi / 180), 2) * std::cos(kPi / 18));
    CHECK(mean_light_spacing(two) == doctest::Approx((6 * inner + 36 * outer) / 42).epsilon(1e-9));
    CHECK(mean_light_spacing({at(0, 30)}) == 0);
}

TEST_CASE("light density: the exponent whose lobe is half its peak at half the spacing")
{
    for (double degrees : {2.0, 10.0, 18.0, 40.0, 90.0}) {
        const double s = degrees * kPi / 180;
        const double n = exponent_for_lobe_width(s);
        CHECK(std::pow(std::cos(s / 2), n) == doctest::Approx(0.5).epsilon(1e-12));
        // Narrower lobes (larger n) are below half at s / 2.
        CHECK(std::pow(std::cos(s / 2), n * 1.1) < 0.5);
    }
    CHECK(std::isinf(exponent_for_lobe_width(0)));
}
