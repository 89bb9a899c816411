// SPDX-License-Identifier: Apache-2.0
// The fewest sub-footprints for a tolerance (ops/sub_footprint_choice.h):
// its measured errors against an independent supersampled estimate on other
// footprints, the fewest squares chosen when every count meets, none when
// none does, and its options checked.
#include "cmfilter/color/ciede2000.h"
#include "cmfilter/ops/sub_footprint_choice.h"
#include "cmfilter/tables/gaussian_convolution.h"

#include "noise_transition_fixture.h"

#include <doctest/doctest.h>

#include <cmath>
#include <random>

using namespace cmfilter;

namespace {

const cmfilter_test::NoiseTransitionFixture& fixture() { return cmfilter_test::noise_transition_fixture(); }

Rgb exact_colour(double mean, double sigma) { return gaussian_convolution(fixture().map, mean, sigma); }

SubFootprintChoiceOptions small(double tolerance)
{
    SubFootprintChoiceOptions o;
    o.tolerance = tolerance;
    o.lods = {-3.0, 0.0};
    o.candidates = {1, 8};
    o.footprints = 128;
    o.strata = 24;
    return o;
}

// The mean CIEDE2000 of the mixture with up to n x n squares against C0 of
// the noise at 24 x 24 jittered points, over 160 footprints of LOD `lod`
// drawn by another generator.
double independent_error(double lod, int n)
{
    const auto& f = fixture();
    const double p0 = f.noise.noise().base_period(), w = p0 * std::exp2(lod);
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> u(0, 1);
    SubFootprintOptions o;
    o.max_cells = n;
    double sum = 0;
    const int footprints = 160, strata = 24;
    for (int j = 0; j < footprints; ++j) {
        const double x = 256 * p0 * u(rng), y = 256 * p0 * u(rng);
        const Rgb reference = cmfilter_test::supersampled_colour(f, x, y, w, strata, rng);
        const Rgb c =
            sub_footprint_color<Rgb>(f.noise, x, y, w, f.noise.filter(x, y, w), o,
                                     [](const FilteredNoise::Parameters& p) { return exact_colour(p.mean, p.sigma); });
        sum += ciede2000_linear_rgb(reference, c);
    }
    return sum / footprints;
}

}  // namespace

TEST_CASE("the measured errors agree with supersampling on other footprints, and the fewest squares that meet win")
{
    auto choice = choose_sub_footprints(fixture().noise, fixture().map, exact_colour, small(2.0));
    REQUIRE(choice);
    REQUIRE(choice->trials.size() == 2);
    for (std::size_t t = 0; t < 2; ++t)
        for (std::size_t k = 0; k < 2; ++k) {
            const double independent = independent_error(choice->lods[k], choice->trials[t].max_cells);
            INFO("up to " << choice->trials[t].max_cells << " squares at LOD " << choice->lods[k] << ": measured "
                          << choice->trials[t].errors[k] << ", independent " << independent);
            // Two estimates from 128 and 160 footprints with 576 reference
            // points each: within a fifth (plus 0.1 for the
            // reference's own sampling error at small errors).
            CHECK(std::fabs(choice->trials[t].errors[k] - independent) < 0.2 * independent + 0.1);
        }
    // One Gaussian misses 2 in the transition; 8 x 8 squares meet it.
    CHECK(choice->trials[0].worst > 2.0);
    CHECK_FALSE(choice->trials[0].meets);
    REQUIRE(choice->choice());
    CHECK(choice->choice()->max_cells == 8);
    // A tolerance both meet: the fewer squares.
    auto loose = choose_sub_footprints(fixture().noise, fixture().map, exact_colour, small(100));
    REQUIRE(loose);
    REQUIRE(loose->choice());
    CHECK(loose->choice()->max_cells == 1);
}

TEST_CASE("nothing meets a tolerance below every count's error: no choice, and the closest is named")
{
    auto choice = choose_sub_footprints(fixture().noise, fixture().map, exact_colour, small(1e-3));
    REQUIRE(choice);
    CHECK_FALSE(choice->choice());
    REQUIRE(choice->best());
    CHECK(choice->best()->max_cells == 8);
    CHECK(choice->best()->worst == std::min(choice->trials[0].worst, choice->trials[1].worst));
}

TEST_CASE("bad choice options are named")
{
    const auto field_of = [](const SubFootprintChoiceOptions& o) {
        auto r = choose_sub_footprints(fixture().noise, fixture().map, exact_colour, o);
        REQUIRE(!r);
        CHECK(r.error().kind == ErrorKind::BadInput);
        return r.error().field;
    };
    SubFootprintChoiceOptions o = small(1);
    o.tolerance = 0;
    CHECK(field_of(o) == "SubFootprintChoiceOptions::tolerance");
    o = small(1);
    o.candidates = {0};
    CHECK(field_of(o) == "SubFootprintChoiceOptions::candidates");
    o = small(1);
    o.lods = {NAN};
    CHECK(field_of(o) == "SubFootprintChoiceOptions::lods");
    o = small(1);
    o.footprints = 0;
    CHECK(field_of(o) == "SubFootprintChoiceOptions::footprints");
    o = small(1);
    o.strata = 0;
    CHECK(field_of(o) == "SubFootprintChoiceOptions::strata");
}

TEST_CASE("a view's LODs: the integer LODs covering its range, within the sigma table's")
{
    // A table from LOD -9 to 2 (45 rows of 0.25): integer LODs -9 .. 2.
    auto table = NoiseSigmaTable::create(-9, 0.25, std::vector<double>(45, 0.1));
    REQUIRE(table);
    CHECK(sub_footprint_lods_between(*table, -3.4, -1.2) == std::vector<double>{-4, -3, -2, -1});
    CHECK(sub_footprint_lods_between(*table, -2, -2) == std::vector<double>{-2});
    CHECK(sub_footprint_lods_between(*table, 0.5, 7) == std::vector<double>{0, 1, 2});
    CHECK(sub_footprint_lods_between(*table, 5, 7) == std::vector<double>{2});
    CHECK(sub_footprint_lods_between(*table, -20, -15) == std::vector<double>{-9});
    // A table spanning no integer LOD: its first.
    auto short_table = NoiseSigmaTable::create(0.2, 0.25, {0.1, 0.1, 0.1});
    REQUIRE(short_table);
    CHECK(sub_footprint_lods_between(*short_table, -1, 3) == std::vector<double>{0.2});
}
