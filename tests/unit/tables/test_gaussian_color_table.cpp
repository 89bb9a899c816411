// SPDX-License-Identifier: Apache-2.0
// The baked table: every node against brute-force quadrature, row 0 against the
// map, the axes' geometry, bilinear lookup and its out-of-range rules.
#include "cmfilter/tables/gaussian_color_table.h"

#include "unit_test_support.h"

#include <doctest/doctest.h>

#include <random>

using namespace cmfilter;
using cmfilter_test::MapPair;
using cmfilter_test::ReferenceMap;

namespace {

MapPair stripes_and_noise(WrapMode wrap, int n, std::uint64_t seed)
{
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    MapPair p;
    p.map.wrap = wrap;
    p.ref.wrap = to_string(wrap);
    for (int i = 0; i < n; ++i) {
        const double stripe = (i / 8) % 2 ? 0.9 : 0.05;  // hard stripes plus noise
        const cmfilter_test::Rgb3 c = {stripe, unit(rng), 0.3 * unit(rng)};
        p.map.texels.push_back({c[0], c[1], c[2]});
        p.ref.texels.push_back(c);
    }
    return p;
}

}  // namespace

using Rgb3fix = cmfilter_test::Rgb3;

TEST_CASE("every table node equals the exact convolution to 1e-6")
{
    for (WrapMode wrap : {WrapMode::Clamp, WrapMode::Repeat, WrapMode::Mirror})
        for (SigmaSpacing spacing : {SigmaSpacing::Linear, SigmaSpacing::Sqrt}) {
            const MapPair p = stripes_and_noise(wrap, 64, 1);
            GaussianColorTableOptions opt;
            opt.values = 40;
            opt.sigmas = 12;
            opt.spacing = spacing;
            opt.sigma_max = 0.3;
            auto table = GaussianColorTable::bake(p.map, opt);
            REQUIRE(table);
            const TableAxes& ax = table->axes();
            double worst = 0;
            for (int j = 0; j < ax.sigmas; ++j)
                for (int i = 0; i < ax.values; ++i) {
                    const Rgb3fix ref = cmfilter_test::reference_convolution(p.ref, ax.value_at(i), ax.sigma_at(j));
                    const Rgb got = table->node(i, j);
                    for (int ch = 0; ch < 3; ++ch) worst = std::max(worst, std::fabs(got[ch] - ref[ch]));
                }
            CAPTURE(to_string(wrap));
            CAPTURE(to_string(spacing));
            // The documented bound (docs/bake-colormap.md): nodes are float32, so this also bounds storage rounding.
            CHECK(worst < 1e-6);
        }
}

TEST_CASE("table axes follow the documented geometry")
{
    MapPair p = stripes_and_noise(WrapMode::Clamp, 16, 2);
    p.map.vmin = -1;
    p.map.vmax = 3;
    GaussianColorTableOptions opt;
    opt.values = 9;
    opt.sigmas = 5;
    auto table = GaussianColorTable::bake(p.map, opt);
    REQUIRE(table);
    const TableAxes& ax = table->axes();
    CHECK(ax.sigma_max == doctest::Approx(1.0));       // default: a quarter of the domain width
    CHECK(ax.margin == doctest::Approx(3.0));          // default: 3 sigma_max
    CHECK(ax.value_first() == doctest::Approx(-4.0));  // clamp: domain plus margin, end-inclusive
    CHECK(ax.value_last() == doctest::Approx(6.0));
    CHECK(ax.value_at(4) == doctest::Approx(1.0));
    CHECK(ax.sigma_at(0) == 0.0);
    CHECK(ax.sigma_at(2) == doctest::Approx(0.25));  // sqrt spacing (default): (2/4)^2
    CHECK(ax.sigma_at(4) == 1.0);

    p.map.wrap = WrapMode::Repeat;
    opt.spacing = SigmaSpacing::Linear;
    auto periodic = GaussianColorTable::bake(p.map, opt);
    REQUIRE(periodic);
    CHECK(periodic->axes().value_at(0) == doctest::Approx(-1.0));  // repeat: n nodes over one period
    CHECK(periodic->axes().value_at(8) == doctest::Approx(-1.0 + 4.0 * 8 / 9));
    CHECK(periodic->axes().sigma_at(2) == doctest::Approx(0.5));
}

TEST_CASE("row sigma = 0 equals the map at every value node")
{
    const MapPair p = stripes_and_noise(WrapMode::Clamp, 256, 3);
    auto table = GaussianColorTable::bake(p.map, {});
    REQUIRE(table);
    for (int i = 0; i < table->axes().values; ++i) {
        const Rgb3fix ref = cmfilter_test::reference_map_value(p.ref, table->axes().value_at(i));
        const Rgb got = table->node(i, 0);
        for (int ch = 0; ch < 3; ++ch) CHECK(std::fabs(got[ch] - ref[ch]) < 1e-7);  // float rounding
    }
}

TEST_CASE("lookup interpolates bilinearly between nodes")
{
    const MapPair p = stripes_and_noise(WrapMode::Clamp, 32, 4);
    GaussianColorTableOptions opt;
    opt.values = 17;
    opt.sigmas = 9;
    opt.spacing = SigmaSpacing::Linear;
    opt.sigma_max = 0.2;
    auto table = GaussianColorTable::bake(p.map, opt);
    REQUIRE(table);
    const TableAxes& ax = table->axes();
    // A point a third of the way across cell (5, 3) in value, a quarter in sigma.
    const double v = ax.value_at(5) + (ax.value_at(6) - ax.value_at(5)) / 3.0;
    const double s = ax.sigma_at(3) + (ax.sigma_at(4) - ax.sigma_at(3)) / 4.0;
    const Rgb got = table->lookup(v, s);
    for (int ch = 0; ch < 3; ++ch) {
        const double bottom = table->node(5, 3)[ch] * 2 / 3 + table->node(6, 3)[ch] / 3;
        const double top = table->node(5, 4)[ch] * 2 / 3 + table->node(6, 4)[ch] / 3;
        CHECK(got[ch] == doctest::Approx(bottom * 0.75 + top * 0.25).epsilon(1e-12));
    }
    // At the nodes, the lookup is the node.
    CHECK(table->lookup(ax.value_at(7), ax.sigma_at(8)).g == doctest::Approx(table->node(7, 8).g).epsilon(1e-12));
}

TEST_CASE("lookups outside the table follow the rules and are counted, never NaN")
{
    const MapPair p = stripes_and_noise(WrapMode::Clamp, 32, 5);
    GaussianColorTableOptions opt;
    opt.sigma_max = 0.1;
    auto table = GaussianColorTable::bake(p.map, opt);
    REQUIRE(table);
    LookupCounters count;
    const Rgb at_max = table->lookup(0.4, 0.1, &count);
    const Rgb beyond = table->lookup(0.4, 5.0, &count);
    CHECK(beyond.r == at_max.r);
    CHECK(count.sigma_clamped == 1);
    const Rgb far = table->lookup(1e9, 0.0, &count);
    CHECK(far.g == doctest::Approx(p.map.texels.back().g).epsilon(1e-6));
    CHECK(count.value_clamped == 1);
    const Rgb nan = table->lookup(std::nan(""), 0.05, &count);
    CHECK(nan.r == 0.0);
    CHECK(count.invalid == 1);
    const Rgb inf = table->lookup(-INFINITY, INFINITY, &count);
    CHECK(std::isfinite(inf.r));
    CHECK(count.lookups == 5);
}

TEST_CASE("periodic lookups wrap: repeat shifts by the period, mirror reflects")
{
    for (WrapMode wrap : {WrapMode::Repeat, WrapMode::Mirror}) {
        const MapPair p = stripes_and_noise(wrap, 48, 6);
        auto table = GaussianColorTable::bake(p.map, {});
        REQUIRE(table);
        for (double v : {0.013, 0.5, 0.97})
            for (double s : {0.0, 0.01, 0.2}) {
                const Rgb base = table->lookup(v, s);
                const Rgb shifted = wrap == WrapMode::Repeat ? table->lookup(v + 3.0, s) : table->lookup(-v, s);
                CHECK(shifted.b == doctest::Approx(base.b).epsilon(1e-9));
                // And the lookup approximates the exact value (a loose, independent check).
                const Rgb3fix ref = cmfilter_test::reference_convolution(p.ref, v, s);
                CHECK(std::fabs(base.g - ref[1]) < 0.05);
            }
    }
}

TEST_CASE("invalid table options are rejected with the value named")
{
    const MapPair p = stripes_and_noise(WrapMode::Clamp, 8, 7);
    GaussianColorTableOptions opt;
    opt.values = 1;
    auto r = GaussianColorTable::bake(p.map, opt);
    REQUIRE(!r);
    CHECK(r.error().kind == ErrorKind::BadInput);
    CHECK(r.error().message.find("GaussianColorTableOptions::values 1") != std::string::npos);
    opt = {};
    opt.sigmas = 0;
    CHECK(GaussianColorTable::bake(p.map, opt).error().message.find("GaussianColorTableOptions::sigmas 0") !=
          std::string::npos);
    opt = {};
    opt.sigma_max = -0.5;
    CHECK(GaussianColorTable::bake(p.map, opt).error().message.find("GaussianColorTableOptions::sigma_max -0.5") !=
          std::string::npos);
    opt.sigma_max = std::nan("");
    CHECK(!GaussianColorTable::bake(p.map, opt));
    opt = {};
    opt.margin = -1;
    CHECK(GaussianColorTable::bake(p.map, opt).error().message.find("GaussianColorTableOptions::margin -1") !=
          std::string::npos);
}
