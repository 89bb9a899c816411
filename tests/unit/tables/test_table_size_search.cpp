// SPDX-License-Identifier: Apache-2.0
// The smallest table for a tolerance (table_size_search.h): the chosen table
// meets the tolerance when measured independently (brute-force quadrature of
// eq. 10, tests/support/reference_convolution.h, at fresh random points, not
// measure_lookup_error), its next smaller neighbours in the search grid do
// not, no measured candidate of fewer bytes passed, and bad options and
// impossible tolerances are refused with messages that name them.
#include "cmfilter/tables/table_size_search.h"

#include "cmfilter/color/ciede2000.h"
#include "cmfilter/color/error_summary.h"
#include "cmfilter/tables/gaussian_color_table_file.h"

#include "test_images.h"
#include "unit_test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace cmfilter;
using cmfilter_test::MapPair;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A map with smooth stretches and one hard edge: texels 0..n/2-1 ramp
// from dark blue to green, then a jump to orange ramping to pale yellow.
MapPair ramp_and_edge(int n, WrapMode wrap)
{
    MapPair p;
    p.map.wrap = wrap;
    p.ref.wrap = to_string(wrap);
    for (int i = 0; i < n; ++i) {
        const double t = static_cast<double>(i) / (n - 1);
        const cmfilter_test::Rgb3 c = i < n / 2 ? cmfilter_test::Rgb3{0.02, 0.05 + 0.6 * t, 0.3 - 0.2 * t}
                                                : cmfilter_test::Rgb3{0.9, 0.3 + 0.5 * t, 0.05 + 0.4 * t};
        p.map.texels.push_back({c[0], c[1], c[2]});
        p.ref.texels.push_back(c);
    }
    return p;
}

// The nearest-rank q-quantile of CIEDE2000 between the table's lookups and
// the reference quadrature at n fresh points drawn as the measurement draws
// them (v uniform over the domain, sigma = sigma_max u^2), from a generator
// of its own.
double independent_error(const GaussianColorTable& table, const MapPair& p, double q, int n, unsigned seed)
{
    std::minstd_rand rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const TableAxes& ax = table.axes();
    std::vector<double> errors;
    for (int i = 0; i < n; ++i) {
        const double v = p.ref.vmin + (p.ref.vmax - p.ref.vmin) * unit(rng);
        const double u = unit(rng);
        const double sigma = ax.sigma_max * u * u;
        const cmfilter_test::Rgb3 exact = cmfilter_test::reference_convolution(p.ref, v, sigma);
        errors.push_back(ciede2000_linear_rgb({exact[0], exact[1], exact[2]}, table.lookup(v, sigma)));
    }
    std::sort(errors.begin(), errors.end());
    const std::size_t rank = static_cast<std::size_t>(std::ceil(q * n - 1e-9));
    return errors[std::max<std::size_t>(rank, 1) - 1];
}

GaussianColorTable bake(const MapPair& p, const TableSize& size, double sigma_max)
{
    GaussianColorTableOptions options;
    options.values = size.values;
    options.sigmas = size.sigmas;
    options.spacing = size.spacing;
    options.sigma_max = sigma_max;
    auto table = GaussianColorTable::bake(p.map, options);
    REQUIRE(table);
    return *table;
}

// The count before `n` in `counts`, or 0 when n is the first.
int previous_count(const std::vector<int>& counts, int n)
{
    auto it = std::find(counts.begin(), counts.end(), n);
    REQUIRE(it != counts.end());
    return it == counts.begin() ? 0 : *(it - 1);
}

}  // namespace

TEST_CASE("power_of_two_counts: the powers of two and the 1.5x between")
{
    const std::vector<int> values = power_of_two_counts(4, 4096);
    CHECK(values.size() == 21);
    CHECK(values.front() == 4);
    CHECK(values[1] == 6);
    CHECK(values[2] == 8);
    CHECK(values[values.size() - 2] == 3072);
    CHECK(values.back() == 4096);
    const std::vector<int> sigmas = power_of_two_counts(2, 1024);
    CHECK(sigmas == std::vector<int>{2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 96, 128, 192, 256, 384, 512, 768, 1024});
}

TEST_CASE("nearest_rank_quantile: rank ceil(q n), p95 as summarize_errors, 1 is the max")
{
    std::vector<double> x(20000);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = static_cast<double>((i * 7919) % x.size());  // 0..19999 shuffled
    CHECK(nearest_rank_quantile(x, 0.999) == 19979.0);                                             // rank 19980
    CHECK(nearest_rank_quantile(x, 1.0) == 19999.0);
    CHECK(nearest_rank_quantile(x, 0.95) == summarize_errors(x).p95);
    CHECK(nearest_rank_quantile({}, 0.5) == 0.0);
    CHECK(nearest_rank_quantile({3.0}, 0.001) == 3.0);
    CHECK(quantile_name(0.999) == "p99.9");
    CHECK(quantile_name(1.0) == "max");
}

TEST_CASE("the chosen table meets the tolerance independently, and its smaller neighbours do not")
{
    struct Case {
        WrapMode wrap;
        double tolerance, quantile, sigma_max;
    };
    const Case cases[] = {{WrapMode::Clamp, 1.0, 0.95, 0.2},
                          {WrapMode::Clamp, 0.3, 0.95, 0.1},
                          {WrapMode::Repeat, 0.5, 0.95, 0.3},
                          {WrapMode::Clamp, 2.0, 0.999, 0.25}};
    for (const Case& c : cases) {
        const MapPair p = ramp_and_edge(24, c.wrap);
        TableSizeSearchOptions options;
        options.tolerance = c.tolerance;
        options.quantile = c.quantile;
        options.sigma_max = c.sigma_max;
        options.threads = 2;
        if (c.quantile < 0.99) {  // p95 is estimated well from fewer points (500 and 2000 above it)
            options.search_samples = 10000;
            options.verify_samples = 40000;
        }
        auto found = find_smallest_table(p.map, options);
        REQUIRE(found);
        const TableSize& chosen = found->size;
        const std::string wrap = to_string(c.wrap), spacing = to_string(chosen.spacing);
        CAPTURE(wrap);
        CAPTURE(c.tolerance);
        CAPTURE(chosen.values);
        CAPTURE(chosen.sigmas);
        CAPTURE(spacing);
        CHECK(found->table.axes().values == chosen.values);
        CHECK(found->table.axes().sigmas == chosen.sigmas);
        CHECK(found->table.axes().spacing == chosen.spacing);
        CHECK(found->sigma_max == c.sigma_max);
        CHECK(found->error <= c.tolerance);
        CHECK(found->search_error <= c.tolerance);

        // Independently: the chosen table meets the tolerance ...
        const double q = c.quantile;
        const int n = q < 0.99 ? 10000 : 20000;  // at least 20 points above the quantile
        CHECK(independent_error(found->table, p, q, n, 101) <= c.tolerance);
        // ... and the next smaller value count, and the next smaller sigma
        // count, of the same spacing do not.
        if (const int values = previous_count(options.value_counts, chosen.values)) {
            const TableSize smaller{values, chosen.sigmas, chosen.spacing};
            CAPTURE(values);
            CHECK(independent_error(bake(p, smaller, c.sigma_max), p, q, n, 102) > c.tolerance);
        }
        if (const int sigmas = previous_count(options.sigma_counts, chosen.sigmas)) {
            const TableSize smaller{chosen.values, sigmas, chosen.spacing};
            CAPTURE(sigmas);
            CHECK(independent_error(bake(p, smaller, c.sigma_max), p, q, n, 103) > c.tolerance);
        }

        // Minimal among what the search measured: every candidate of fewer
        // bytes failed at the search points or at the verification points,
        // and none of equal bytes that passed had a lower error.
        int rejected = 0;
        for (const TableSizeTrial& t : found->trials) {
            const bool passed = t.error <= c.tolerance && !(t.verified && t.verify_error > c.tolerance);
            rejected += t.verified && t.verify_error > c.tolerance;
            if (t.size.bytes() < chosen.bytes()) CHECK_FALSE(passed);
            if (t.size.bytes() == chosen.bytes() && passed) CHECK(t.error >= found->search_error);
        }
        CHECK(rejected == found->rejected);
    }
}

TEST_CASE("the search is deterministic and does not depend on the thread count")
{
    const MapPair p = ramp_and_edge(24, WrapMode::Clamp);
    TableSizeSearchOptions options;
    options.tolerance = 1.0;
    options.sigma_max = 0.2;
    options.threads = 1;
    auto a = find_smallest_table(p.map, options);
    options.threads = 3;
    auto b = find_smallest_table(p.map, options);
    REQUIRE(a);
    REQUIRE(b);
    CHECK(a->size.values == b->size.values);
    CHECK(a->size.sigmas == b->size.sigmas);
    CHECK(a->size.spacing == b->size.spacing);
    CHECK(a->error == b->error);
    CHECK(a->trials.size() == b->trials.size());
}

TEST_CASE("no table in the grid meets an impossible tolerance: the message names it and the best reached")
{
    const MapPair p = ramp_and_edge(24, WrapMode::Clamp);
    TableSizeSearchOptions options;
    options.tolerance = 1e-6;
    options.value_counts = {4, 8, 16};
    options.sigma_counts = {2, 3};
    options.search_samples = 2000;
    auto found = find_smallest_table(p.map, options);
    REQUIRE_FALSE(found);
    CHECK(found.error().kind == ErrorKind::BadInput);
    const std::string& m = found.error().message;
    CAPTURE(m);
    CHECK(contains(m, "no table up to 16 values x 3 sigmas meets the tolerance 1e-06"));
    CHECK(contains(m, "p99.9"));
    CHECK(contains(m, "the lowest p99.9 reached is "));
    CHECK(contains(m, "by 16 x "));
}

TEST_CASE("bad search options are refused, naming the value")
{
    const MapPair p = ramp_and_edge(8, WrapMode::Clamp);
    const auto message = [&](const TableSizeSearchOptions& o) {
        auto r = find_smallest_table(p.map, o);
        REQUIRE_FALSE(r);
        CHECK(r.error().kind == ErrorKind::BadInput);
        return r.error().message;
    };
    TableSizeSearchOptions o;
    o.tolerance = 0;
    CHECK(contains(message(o), "TableSizeSearchOptions::tolerance 0 is invalid"));
    o.tolerance = -2;
    CHECK(contains(message(o), "TableSizeSearchOptions::tolerance -2 is invalid"));
    o.tolerance = std::nan("");
    CHECK(contains(message(o), "is invalid (expected a CIEDE2000 difference > 0)"));
    o = {};
    o.quantile = 0;
    CHECK(contains(message(o), "quantile 0 is invalid"));
    o.quantile = 1.5;
    CHECK(contains(message(o), "quantile 1.5 is invalid"));
    o = {};
    o.value_counts = {8, 4};
    CHECK(contains(message(o), "value counts is not strictly ascending at 4"));
    o = {};
    o.sigma_counts = {1, 2};
    CHECK(contains(message(o), "sigma counts holds 1"));
    o = {};
    o.sigma_max = -1;
    CHECK(contains(message(o), "GaussianColorTableOptions::sigma_max -1 is invalid"));
    o = {};
    o.search_samples = 0;
    CHECK(contains(message(o), "sample counts must be >= 1"));
}

TEST_CASE("the tolerance record and sigma_max source round-trip through the table file")
{
    const MapPair p = ramp_and_edge(8, WrapMode::Clamp);
    auto table = GaussianColorTable::bake(p.map, {});
    REQUIRE(table);
    GaussianColorTableInfo info;
    info.sigma_max_source = "--for: the largest box sigma of 'x.exr'";
    info.tolerance = TableToleranceRecord{0.5, "p99.9", 0.4375, 100000, "values 4..4096 x sigmas 2..1024"};
    const std::string path = cmfilter_test::temp_dir("cmfilter-test-table-size-search") + "/t.exr";
    REQUIRE(write_gaussian_color_table(path, *table, info));
    auto back = read_gaussian_color_table(path);
    REQUIRE(back);
    CHECK(back->info.sigma_max_source == info.sigma_max_source);
    REQUIRE(back->info.tolerance);
    CHECK(back->info.tolerance->tolerance == 0.5);
    CHECK(back->info.tolerance->statistic == "p99.9");
    CHECK(back->info.tolerance->error == 0.4375);
    CHECK(back->info.tolerance->samples == 100000);
    CHECK(back->info.tolerance->search == info.tolerance->search);

    // A table baked at a given size records no tolerance.
    REQUIRE(write_gaussian_color_table(path, *table, {}));
    auto plain = read_gaussian_color_table(path);
    REQUIRE(plain);
    CHECK_FALSE(plain->info.tolerance);
    CHECK(plain->info.sigma_max_source.empty());
}
