// SPDX-License-Identifier: Apache-2.0
// Light domes (light_dome.h): counts, unit length and elevation bounds of
// every kind; the Fibonacci dome's uniformity in solid angle (its mean z
// against (1 + sin e0) / 2, and its share of lights in zones and azimuth
// quadrants against their areas); the regular dome's even spacing and the
// stage's unevenness, both by nearest-neighbour angles; a hand-written .lp;
// the option strings.
#include "cmfilter/synthetic/light_dome.h"

#include "test_images.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

using namespace cmfilter;

namespace {

constexpr double kPi = 3.14159265358979323846;

std::vector<Vec3> dome(DomeKind kind, int count, double min_elevation = 10)
{
    DomeOptions o;
    o.kind = kind;
    o.count = count;
    o.min_elevation_degrees = min_elevation;
    auto d = make_dome(o);
    REQUIRE_MESSAGE(d, (d ? "" : d.error().message));
    return *d;
}

// The smallest and largest of each light's angle to its nearest neighbour.
std::pair<double, double> nearest_angles(const std::vector<Vec3>& lights)
{
    double lo = 1e9, hi = 0;
    for (std::size_t a = 0; a < lights.size(); ++a) {
        double nearest = 1e9;
        for (std::size_t b = 0; b < lights.size(); ++b)
            if (a != b) nearest = std::min(nearest, std::acos(std::min(1.0, dot(lights[a], lights[b]))));
        lo = std::min(lo, nearest);
        hi = std::max(hi, nearest);
    }
    return {lo, hi};
}

}  // namespace

TEST_CASE("light dome: every kind has its count of unit lights above the minimum elevation")
{
    for (DomeKind kind : {DomeKind::Regular, DomeKind::Fibonacci, DomeKind::Stage})
        for (int count : {6, 7, 16, 64, 101})
            for (double e : {0.0, 10.0, 30.0}) {
                const auto lights = dome(kind, count, e);
                CHECK(lights.size() == static_cast<std::size_t>(count));
                for (const Vec3& l : lights) {
                    CHECK(length(l) == doctest::Approx(1).epsilon(1e-12));
                    CHECK(l.z >= std::sin(e * kPi / 180) - 1e-12);
                }
                CHECK(dome(kind, count, e) == lights);  // deterministic
            }
}

TEST_CASE("light dome: the Fibonacci spiral is uniform in solid angle above the minimum elevation")
{
    for (double e : {0.0, 15.0, 40.0}) {
        const auto lights = dome(DomeKind::Fibonacci, 400, e);
        const double z0 = std::sin(e * kPi / 180);
        double mean_z = 0;
        int quadrant[4] = {0, 0, 0, 0}, upper = 0;
        for (const Vec3& l : lights) {
            mean_z += l.z / lights.size();
            const double phi = std::atan2(l.y, l.x) + kPi;
            ++quadrant[std::min(3, static_cast<int>(phi / (0.5 * kPi)))];
            // The zone above the middle height holds half the solid angle.
            upper += l.z > 0.5 * (1 + z0);
        }
        CHECK(mean_z == doctest::Approx(0.5 * (1 + z0)).epsilon(1e-3));
        CHECK(std::abs(upper - 200) <= 2);
        for (int q : quadrant) CHECK(std::abs(q - 100) <= 6);
    }
}

TEST_CASE("light dome: regular rings are evenly spaced, the stage's lights are not")
{
    for (int count : {32, 64, 128}) {
        const auto regular = dome(DomeKind::Regular, count);
        const auto [lo, hi] = nearest_angles(regular);
        CHECK(hi / lo < 2.0);
        CHECK(std::count(regular.begin(), regular.end(), Vec3{0, 0, 1}) == 1);  // the zenith
        const auto stage = dome(DomeKind::Stage, count);
        const auto [slo, shi] = nearest_angles(stage);
        CHECK(shi / slo > 4.0);
        // Half the lights on the +x low arc, a small part of the dome's solid angle.
        const double e0 = 10 * kPi / 180, e1 = e0 + (0.5 * kPi - e0) / 6;
        int arc = 0;
        for (const Vec3& l : stage)
            arc += l.z <= std::sin(e1) + 1e-12 && std::abs(std::atan2(l.y, l.x)) <= 75.0 * kPi / 180 + 1e-12;
        const double arc_share = (std::sin(e1) - std::sin(e0)) * (150.0 / 360) / (1 - std::sin(e0));
        CHECK(arc >= count / 2);
        CHECK(arc_share < 0.12);
        CHECK(double(arc) / count / arc_share > 4);  // over four times the mean density
    }
}

TEST_CASE("light dome: a file dome reads a hand-written .lp in its order")
{
    const std::string path = cmfilter_test::temp_dir("cmfilter-light-dome") + "/dome.lp";
    std::ofstream(path) << "3\na.png 0 0 1\nb.png 0.6 0 0.8\nc.png 0 -3 4\n";
    auto d = parse_dome("file:" + path);
    REQUIRE(d);
    auto lights = make_dome(*d);
    REQUIRE(lights);
    REQUIRE(lights->size() == 3);
    CHECK((*lights)[1].x == doctest::Approx(0.6));
    CHECK((*lights)[2].y == doctest::Approx(-0.6));
    CHECK((*lights)[2].z == doctest::Approx(0.8));
}

TEST_CASE("light dome: option strings, and the errors that name what was expected")
{
    auto f = parse_dome("fibonacci:64");
    REQUIRE(f);
    CHECK(f->kind == DomeKind::Fibonacci);
    CHECK(f->count == 64);
    CHECK(dome_text(*f) == "fibonacci:64");
    auto s = parse_dome("stage:7");
    REQUIRE(s);
    CHECK(s->kind == DomeKind::Stage);
    CHECK(s->count == 7);
    for (const char* bad :
         {"fibonaci:64", "fibonacci", "fibonacci:", "regular:6x", "regular:-3", "file:", "stage:1.5"}) {
        auto e = parse_dome(bad);
        REQUIRE_FALSE(e);
        CHECK(e.error().message.find(std::string("'") + bad + "'") != std::string::npos);
        CHECK(e.error().message.find("expected regular:N, fibonacci:N") != std::string::npos);
    }
    DomeOptions o;
    o.count = 0;
    auto zero = make_dome(o);
    REQUIRE_FALSE(zero);
    CHECK(zero.error().field == "DomeOptions::count");
    o.count = 10;
    o.kind = DomeKind::Regular;
    o.min_elevation_degrees = 85;
    auto high = make_dome(o);
    REQUIRE_FALSE(high);
    CHECK(high.error().field == "DomeOptions::min_elevation_degrees");
}
