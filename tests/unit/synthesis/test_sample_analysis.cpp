// SPDX-License-Identifier: Apache-2.0
// The sample analysis (sample_analysis.h): with one texton per texel the
// texton distance is the feature distance, so the candidate sets must be
// those of a direct brute-force search over the raw features (computed
// here, with the sample's wrap or clamp), and M the features' dot products.
#include "cmfilter/synthesis/sample_analysis.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <numeric>
#include <random>

using namespace cmfilter;

namespace {

std::vector<float> random_features(int texels, int dims, std::uint64_t seed)
{
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<float> f(static_cast<std::size_t>(texels) * dims);
    for (float& v : f) v = unit(rng);
    return f;
}

// The neighbourhood distance from raw features.
double raw_distance(const std::vector<float>& f, int w, int h, int dims, int n, bool periodic, int p, int q)
{
    auto at = [&](int t, int dx, int dy) {
        int x = t % w + dx, y = t / w + dy;
        if (periodic) {
            x = (x + w) % w;
            y = (y + h) % h;
        } else {
            x = std::min(std::max(x, 0), w - 1);
            y = std::min(std::max(y, 0), h - 1);
        }
        return f.data() + (static_cast<std::size_t>(y) * w + x) * dims;
    };
    double sum = 0;
    for (int dy = -n; dy <= n; ++dy)
        for (int dx = -n; dx <= n; ++dx) {
            const float* a = at(p, dx, dy);
            const float* b = at(q, dx, dy);
            for (int d = 0; d < dims; ++d) sum += (double(a[d]) - b[d]) * (double(a[d]) - b[d]);
        }
    return sum;
}

void check_against_brute_force(bool periodic)
{
    const int w = 9, h = 7, dims = 3, n = 1, m = 5;
    const std::vector<float> f = random_features(w * h, dims, periodic ? 21 : 22);
    auto sample = sample_from_features(w, h, dims, f, 1, periodic);
    REQUIRE(sample);
    AnalysisOptions options;
    options.textons = w * h;
    options.candidates = m;
    options.neighbourhood = n;
    auto analysis = analyse_sample(*sample, options);
    REQUIRE(analysis);
    REQUIRE(analysis->levels.size() == 1);
    const LevelAnalysis& level = analysis->levels[0];
    REQUIRE(level.textons == w * h);
    REQUIRE(level.candidates == m);
    CHECK(analysis->periodic == periodic);
    CHECK(analysis->neighbourhood == n);
    for (int p = 0; p < w * h; ++p) {
        std::vector<int> order;
        for (int q = 0; q < w * h; ++q)
            if (q != p) order.push_back(q);
        std::vector<double> d(static_cast<std::size_t>(w * h));
        for (int q : order) d[static_cast<std::size_t>(q)] = raw_distance(f, w, h, dims, n, periodic, p, q);
        std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return d[a] < d[b]; });
        for (int j = 0; j < m; ++j) {
            const int got = level.similar[static_cast<std::size_t>(p) * m + j];
            CHECK(got != p);
            // Same distance, rank by rank; the same texel unless two are within rounding.
            CHECK(d[static_cast<std::size_t>(got)] ==
                  doctest::Approx(d[static_cast<std::size_t>(order[j])]).epsilon(1e-4));
            const bool separated = (j == 0 || d[order[j]] - d[order[j - 1]] > 1e-4) &&
                                   (d[order[j + 1]] - d[order[j]] > 1e-4);
            if (separated) CHECK(got == order[static_cast<std::size_t>(j)]);
        }
    }
    // M holds the features' dot products.
    for (int a = 0; a < w * h; a += 5)
        for (int b = 0; b < w * h; b += 3) {
            double dot = 0;
            for (int d = 0; d < dims; ++d) dot += double(f[a * dims + d]) * f[b * dims + d];
            const auto ta = level.texton[static_cast<std::size_t>(a)], tb = level.texton[static_cast<std::size_t>(b)];
            CHECK(level.dot[static_cast<std::size_t>(ta) * level.textons + tb] == doctest::Approx(dot).epsilon(1e-5));
        }
}

}  // namespace

TEST_CASE("sample analysis: candidate sets equal a brute-force search over the raw features (clamped sample)")
{
    check_against_brute_force(false);
}

TEST_CASE("sample analysis: candidate sets equal a brute-force search over the raw features (periodic sample)")
{
    check_against_brute_force(true);
}

TEST_CASE("sample analysis: default textons are min(2000, texels / 4) per level, each level its own size")
{
    const int w = 16, h = 12, dims = 2;
    auto sample = sample_from_features(w, h, dims, random_features(w * h, dims, 3), 2);
    REQUIRE(sample);
    AnalysisOptions options;
    options.candidates = 3;
    options.neighbourhood = 1;
    auto analysis = analyse_sample(*sample, options);
    REQUIRE(analysis);
    REQUIRE(analysis->levels.size() == 2);
    CHECK(analysis->levels[0].width == 16);
    CHECK(analysis->levels[0].height == 12);
    CHECK(analysis->levels[0].textons == 16 * 12 / 4);
    CHECK(analysis->levels[1].width == 8);
    CHECK(analysis->levels[1].height == 6);
    CHECK(analysis->levels[1].textons == 8 * 6 / 4);
    CHECK(analysis->seconds >= 0);
    for (const LevelAnalysis& level : analysis->levels) {
        CHECK(level.similar.size() == level.texels() * 3);
        for (auto t : level.texton) CHECK((t >= 0 && t < level.textons));
        CHECK(level.inertia > 0);
    }
}

TEST_CASE("sample analysis: bad options are refused, naming the field and the sample's size")
{
    auto sample = sample_from_features(6, 5, 1, random_features(30, 1, 4), 2);
    REQUIRE(sample);  // levels 6 x 5 and 3 x 3
    auto refused = [&](AnalysisOptions o, const char* field, const char* text) {
        auto r = analyse_sample(*sample, o);
        REQUIRE_FALSE(r);
        CHECK(r.error().kind == ErrorKind::BadInput);
        CHECK(r.error().field == field);
        CHECK_MESSAGE(r.error().message.find(text) != std::string::npos, r.error().message);
    };
    AnalysisOptions o;
    o.candidates = 2;
    o.neighbourhood = 1;
    o.textons = 10;  // more than the 9 texels of level 1
    refused(o, "AnalysisOptions::textons", "9 texels of level 1");
    o.textons = 0;
    o.candidates = 0;
    refused(o, "AnalysisOptions::candidates", "3 x 3");
    o.candidates = 9;
    refused(o, "AnalysisOptions::candidates", "between 1 and 8");
    o.candidates = 2;
    o.neighbourhood = 0;
    refused(o, "AnalysisOptions::neighbourhood", "0");
    o.neighbourhood = 2;  // a 5 x 5 window on a 3 x 3 level
    refused(o, "AnalysisOptions::neighbourhood", "3 x 3");
    o.neighbourhood = 1;
    CHECK(analyse_sample(*sample, o));
    SynthesisSample empty;
    auto r = analyse_sample(empty, o);
    REQUIRE_FALSE(r);
    CHECK(r.error().message.find("empty") != std::string::npos);
}
