// SPDX-License-Identifier: Apache-2.0
// The small-sigma shortcut's threshold (plain_lookup.h), against the
// brute-force quadrature of eq. 10 (tests/support/reference_convolution.h):
// below the threshold C0(v) is within the bound of the exact T(v, sigma) at
// fresh random points, and one grid step above it the bound fails at a cell
// end, so the threshold is the largest the grid allows.
#include "cmfilter/tables/plain_lookup.h"

#include "cmfilter/color/ciede2000.h"

#include "unit_test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

using namespace cmfilter;
using cmfilter_test::MapPair;

namespace {

// Smooth stretches and hard edges: a ramp, a jump, a ramp, and a one-texel stripe.
MapPair ramps_and_edges(int n)
{
    MapPair p;
    p.map.vmin = p.ref.vmin = -0.5;
    p.map.vmax = p.ref.vmax = 0.7;
    for (int i = 0; i < n; ++i) {
        const double t = static_cast<double>(i) / (n - 1);
        cmfilter_test::Rgb3 c = i < n / 2 ? cmfilter_test::Rgb3{0.05, 0.05 + 0.6 * t, 0.3 - 0.2 * t}
                                          : cmfilter_test::Rgb3{0.9, 0.3 + 0.5 * t, 0.05 + 0.4 * t};
        if (i == (3 * n) / 4) c = {0.02, 0.02, 0.6};
        p.map.texels.push_back({c[0], c[1], c[2]});
        p.ref.texels.push_back(c);
    }
    return p;
}

double reference_difference(const MapPair& p, double v, double sigma)
{
    const cmfilter_test::Rgb3 exact = cmfilter_test::reference_convolution(p.ref, v, sigma);
    const cmfilter_test::Rgb3 plain = cmfilter_test::reference_map_value(p.ref, v);
    return ciede2000_linear_rgb({exact[0], exact[1], exact[2]}, {plain[0], plain[1], plain[2]});
}

}  // namespace

TEST_CASE("below the small-sigma threshold C0 is within the bound of the exact filtered colour")
{
    const MapPair p = ramps_and_edges(32);
    for (double bound : {0.1, 0.5, 2.0}) {
        PlainLookupOptions options;
        options.bound = bound;
        options.sigma_cap = 0.3;
        auto plain = plain_lookup_sigma(p.map, options);
        REQUIRE(plain);
        REQUIRE_FALSE(plain->empty());
        const double h = p.map.texel_width();
        // Fresh points over the domain and a texel beyond, sigma uniform below the threshold there.
        std::minstd_rand rng(11);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        double worst = 0;
        int shortcut_points = 0;
        for (int k = 0; k < 4000; ++k) {
            const double v = p.map.vmin - h + (p.map.vmax - p.map.vmin + 2 * h) * unit(rng);
            const double below = plain->below(v);
            if (below <= 0) continue;
            ++shortcut_points;
            worst = std::max(worst, reference_difference(p, v, below * unit(rng)));
        }
        CAPTURE(bound);
        CAPTURE(worst);
        CHECK(shortcut_points > 2000);  // most values take the shortcut for some sigma
        CHECK(worst <= bound);
        // The hard edges hold the threshold near them far below the smooth stretches'.
        CHECK(plain->smallest() < 0.1 * plain->median());
        CHECK(plain->largest() <= options.sigma_cap);
    }
}

TEST_CASE("one grid step above the small-sigma threshold the bound fails at a cell end")
{
    const MapPair p = ramps_and_edges(24);
    PlainLookupOptions options;
    options.bound = 0.5;
    options.sigma_cap = 0.3;
    options.points_per_texel = 4;
    auto plain = plain_lookup_sigma(p.map, options);
    REQUIRE(plain);
    const double step = plain->v_step(), ratio = std::pow(2.0, 0.125);
    CHECK(step == doctest::Approx(p.map.texel_width() / 4));
    int checked = 0;
    for (std::size_t c = 0; c < plain->cells().size(); ++c) {
        const double below = plain->cells()[c];
        if (below >= options.sigma_cap * (1 - 1e-6)) continue;  // never failed up to the cap
        const double next = below > 0 ? below * ratio : 1e-3 * p.map.texel_width();
        const double a = plain->v_first() + static_cast<double>(c) * step;
        const double worst = std::max(reference_difference(p, a, next), reference_difference(p, a + step, next));
        CAPTURE(c);
        CAPTURE(below);
        CHECK(worst > options.bound * 0.999);
        ++checked;
    }
    CHECK(checked > 50);
    // Outside the sampled range (and for NaN): no shortcut.
    CHECK(plain->below(p.map.vmin - 2 * p.map.texel_width()) == 0.0);
    CHECK(plain->below(p.map.vmax + 2 * p.map.texel_width()) == 0.0);
    CHECK(plain->below(std::nan("")) == 0.0);
}

TEST_CASE("a constant map needs no table at any sigma, and the threshold does not depend on threads")
{
    ColorMap flat;
    flat.texels.assign(16, Rgb{0.3, 0.5, 0.2});
    PlainLookupOptions options;
    options.sigma_cap = 0.25;
    auto plain = plain_lookup_sigma(flat, options);
    REQUIRE(plain);
    CHECK(plain->smallest() == doctest::Approx(0.25));
    CHECK(plain->below(0.5) == doctest::Approx(0.25));

    const MapPair p = ramps_and_edges(40);
    options.threads = 1;
    auto one = plain_lookup_sigma(p.map, options);
    options.threads = 3;
    auto three = plain_lookup_sigma(p.map, options);
    REQUIRE(one);
    REQUIRE(three);
    CHECK(one->cells() == three->cells());
}

TEST_CASE("bad small-sigma options are refused, naming the value")
{
    const MapPair p = ramps_and_edges(8);
    PlainLookupOptions options;
    options.sigma_cap = 0.2;
    options.bound = 0;
    auto zero = plain_lookup_sigma(p.map, options);
    REQUIRE_FALSE(zero);
    CHECK(zero.error().message.find("bound 0 is invalid") != std::string::npos);
    options.bound = 0.1;
    options.sigma_cap = -1;
    auto cap = plain_lookup_sigma(p.map, options);
    REQUIRE_FALSE(cap);
    CHECK(cap.error().message.find("cap -1 is invalid") != std::string::npos);
    options.sigma_cap = 0.2;
    options.points_per_texel = 0;
    CHECK_FALSE(plain_lookup_sigma(p.map, options));
}
