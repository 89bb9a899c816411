// SPDX-License-Identifier: Apache-2.0
// The mixture over sub-footprints (noise_sub_footprints.h): against a
// supersampled reference in the transition (where one Gaussian is far off),
// the same as one Gaussian outside it, continuous across every change of the
// number of squares, the squares where they belong, and its options checked.
#include "cmfilter/color/ciede2000.h"
#include "cmfilter/noise/noise_sub_footprints.h"
#include "cmfilter/tables/gaussian_convolution.h"

#include "noise_transition_fixture.h"

#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace cmfilter;

namespace {

using Fixture = cmfilter_test::NoiseTransitionFixture;
const Fixture& fixture() { return cmfilter_test::noise_transition_fixture(); }

Rgb colour_of(const FilteredNoise::Parameters& p) { return gaussian_convolution(fixture().map, p.mean, p.sigma); }

Rgb mixture(double x, double y, double w, const SubFootprintOptions& options = {})
{
    const FilteredNoise& n = fixture().noise;
    return sub_footprint_color<Rgb>(n, x, y, w, n.filter(x, y, w), options, colour_of);
}

double lod_of_level(double s)
{
    // s = (L - L_N + 2.5) / 1.5, L_N = log2(p_5 / p_0) = -5 for lacunarity 2.
    return -5.0 - 2.5 + 1.5 * s;
}

double max_abs_diff(const Rgb& a, const Rgb& b)
{
    return std::max({std::fabs(a.r - b.r), std::fabs(a.g - b.g), std::fabs(a.b - b.b)});
}

}  // namespace

TEST_CASE("in the transition the mixture comes within 1.5 of supersampling, one Gaussian does not")
{
    const Fixture& f = fixture();
    const double p0 = f.noise.noise().base_period();
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    for (double lod : {-2.0, 0.0}) {
        const double w = p0 * std::exp2(lod);
        double mixture_error = 0, gaussian_error = 0;
        const int footprints = 48, strata = 24;
        for (int j = 0; j < footprints; ++j) {
            const double x = 256 * p0 * u(rng), y = 256 * p0 * u(rng);
            const Rgb reference = cmfilter_test::supersampled_colour(f, x, y, w, strata, rng);
            mixture_error += ciede2000_linear_rgb(reference, mixture(x, y, w));
            gaussian_error += ciede2000_linear_rgb(reference, colour_of(f.noise.filter(x, y, w)));
        }
        mixture_error /= footprints;
        gaussian_error /= footprints;
        INFO("LOD " << lod << ": mixture " << mixture_error << ", gaussian " << gaussian_error);
        CHECK(mixture_error < 1.5);
        CHECK(gaussian_error > 3 * mixture_error);
    }
}

TEST_CASE("outside the transition the mixture is the one Gaussian, bit for bit")
{
    const Fixture& f = fixture();
    for (double lod : {lod_of_level(-0.3), lod_of_level(-2), -9.0, 3.0, 3.5, 6.0}) {
        CAPTURE(lod);
        const double w = std::exp2(lod) * f.noise.noise().base_period();
        const Rgb one = colour_of(f.noise.filter(1.3, 7.9, w));
        const Rgb mix = mixture(1.3, 7.9, w);
        CHECK(mix.r == one.r);
        CHECK(mix.g == one.g);
        CHECK(mix.b == one.b);
    }
    // A point, and one square at most.
    const Rgb point = colour_of(f.noise.filter(1.3, 7.9, 0));
    CHECK(max_abs_diff(mixture(1.3, 7.9, 0), point) == 0);
    SubFootprintOptions one;
    one.max_cells = 1;
    const double w = f.noise.noise().base_period();
    CHECK(max_abs_diff(mixture(1.3, 7.9, w, one), colour_of(f.noise.filter(1.3, 7.9, w))) == 0);
}

TEST_CASE("the colour is continuous across every change of the number of squares")
{
    const Fixture& f = fixture();
    const double p0 = f.noise.noise().base_period();
    // Each level boundary s = k (k = 0..3: 1 -> 2 -> 4 -> 8 squares) and the
    // return to one Gaussian at lod_last (3).
    std::vector<double> lods;
    for (int k = 0; k <= 3; ++k) lods.push_back(lod_of_level(k));
    lods.push_back(SubFootprintOptions{}.lod_last - 0.5);
    lods.push_back(SubFootprintOptions{}.lod_last);
    for (double lod : lods) {
        const double eps = 1e-9;
        double jump = 0, without_blend = 0;
        for (int j = 0; j < 8; ++j) {
            const double x = 3.7 + 11.1 * j, y = 0.9 + 5.3 * j;
            const Rgb below = mixture(x, y, p0 * std::exp2(lod - eps));
            const Rgb above = mixture(x, y, p0 * std::exp2(lod + eps));
            jump = std::max(jump, max_abs_diff(below, above));
            // What switching without a blend would jump by, for scale: the
            // two counts' mixtures at the same width.
            const SubFootprintPlan plan = plan_sub_footprints(f.noise.noise(), lod - eps, {});
            if (plan.blend_cells != plan.cells) {
                const double w = p0 * std::exp2(lod);
                const auto mix_of = [&](int n) {
                    return n > 1 ? sub_footprint_mixture<Rgb>(f.noise, x, y, w, n, colour_of)
                                 : colour_of(f.noise.filter(x, y, w));
                };
                without_blend = std::max(without_blend, max_abs_diff(mix_of(plan.cells), mix_of(plan.blend_cells)));
            }
        }
        INFO("LOD " << lod << ": jump " << jump << ", the counts differ by " << without_blend);
        CHECK(jump < 1e-6);
    }
    // A lod_last whose half LOD of return to one Gaussian holds a change of
    // count (4 -> 8 at s = 2) and its blend (from s = 1.75).
    SubFootprintOptions early;
    early.lod_last = lod_of_level(2) + 0.1;
    for (double lod : {early.lod_last - 0.5, lod_of_level(1.75), lod_of_level(2), early.lod_last}) {
        double jump = 0;
        for (int j = 0; j < 8; ++j) {
            const double x = 3.7 + 11.1 * j, y = 0.9 + 5.3 * j;
            jump = std::max(jump, max_abs_diff(mixture(x, y, p0 * std::exp2(lod - 1e-9), early),
                                               mixture(x, y, p0 * std::exp2(lod + 1e-9), early)));
        }
        INFO("lod_last " << early.lod_last << ", LOD " << lod << ": jump " << jump);
        CHECK(jump < 1e-6);
    }
}

TEST_CASE("the plan doubles the squares every 1.5 LOD from 2.5 below the finest octave, up to max_cells")
{
    const FractalNoise& n = fixture().noise.noise();
    const auto cells_at = [&](double s, const SubFootprintOptions& o = {}) {
        return plan_sub_footprints(n, lod_of_level(s), o);
    };
    CHECK(cells_at(-0.5).cells == 1);
    CHECK(cells_at(0.5).cells == 2);
    CHECK(cells_at(0.5).blend == 0);
    CHECK(cells_at(1.5).cells == 4);
    CHECK(cells_at(2.5).cells == 8);
    CHECK(cells_at(5.0).cells == 8);  // LOD 0
    // The last quarter of a level blends towards the next count.
    const SubFootprintPlan mid = cells_at(1.875);
    CHECK(mid.cells == 4);
    CHECK(mid.blend_cells == 8);
    CHECK(mid.blend == doctest::Approx(0.5));
    SubFootprintOptions four;
    four.max_cells = 4;
    CHECK(cells_at(5.0, four).cells == 4);
    CHECK(cells_at(1.875, four).blend == 0);
    // Over the half LOD below lod_last: back to one.
    const SubFootprintPlan top = plan_sub_footprints(n, 2.75, {});
    CHECK(top.cells == 8);
    CHECK(top.blend == 0);
    CHECK(top.one == doctest::Approx(0.5));
    CHECK(plan_sub_footprints(n, NAN, {}).cells == 1);
    CHECK(plan_sub_footprints(n, -INFINITY, {}).cells == 1);
}

TEST_CASE("the squares tile the footprint: two by two are its quadrants")
{
    const FilteredNoise& n = fixture().noise;
    const double x = 10.25, y = -3.5, w = 0.6;
    const auto mean_of = [](const FilteredNoise::Parameters& p) { return p.mean; };
    const double quadrants = 0.25 *
                             (n.filter(x - w / 4, y - w / 4, w / 2).mean + n.filter(x + w / 4, y - w / 4, w / 2).mean +
                              n.filter(x - w / 4, y + w / 4, w / 2).mean + n.filter(x + w / 4, y + w / 4, w / 2).mean);
    CHECK(sub_footprint_mixture<double>(n, x, y, w, 2, mean_of) == doctest::Approx(quadrants).epsilon(1e-14));
}

TEST_CASE("a sheared, turned footprint is cut along its own edges")
{
    // A rhombus at 30 degrees (edges of length w, 53 degrees apart), as a
    // pixel's footprint on a curved surface: the pieces tile it, so the
    // mixture follows a supersampling of the rhombus itself; the square of
    // the same width around its centre covers another region.
    const Fixture& f = fixture();
    const double p0 = f.noise.noise().base_period();
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0, 1);
    for (double lod : {-2.0, 0.0}) {
        const double w = p0 * std::exp2(lod), a = M_PI / 6, b = a + 0.927;
        const FootprintEdges e{w * std::cos(a), w * std::sin(a), w * std::cos(b), w * std::sin(b)};
        double along = 0, square = 0;
        const int footprints = 48, strata = 24;
        for (int j = 0; j < footprints; ++j) {
            const double x = 256 * p0 * u(rng), y = 256 * p0 * u(rng);
            const Rgb reference = cmfilter_test::supersampled_colour(f, x, y, e, strata, rng);
            const FilteredNoise::Parameters whole = f.noise.filter(x, y, w);
            along +=
                ciede2000_linear_rgb(reference, sub_footprint_color<Rgb>(f.noise, x, y, w, e, whole, {}, colour_of));
            square += ciede2000_linear_rgb(reference, mixture(x, y, w));
        }
        along /= footprints;
        square /= footprints;
        INFO("LOD " << lod << ": along the edges " << along << ", as a square " << square);
        CHECK(along < 1.5);
        CHECK(square > 2 * along);
    }
}

TEST_CASE("bad sub-footprint options are named")
{
    SubFootprintOptions o;
    CHECK(check_sub_footprint_options(o));
    o.max_cells = 0;
    auto bad = check_sub_footprint_options(o);
    REQUIRE(!bad);
    CHECK(bad.error().field == "SubFootprintOptions::max_cells");
    o.max_cells = kMaxSubFootprintCells + 1;
    CHECK(!check_sub_footprint_options(o));
    o.max_cells = 4;
    o.lod_last = NAN;
    bad = check_sub_footprint_options(o);
    REQUIRE(!bad);
    CHECK(bad.error().field == "SubFootprintOptions::lod_last");
}
