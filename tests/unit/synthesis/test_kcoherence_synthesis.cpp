// SPDX-License-Identifier: Apache-2.0
// k-coherence synthesis (kcoherence_synthesis.h), checked against the
// definition written out here from raw features: with one texton per texel
// the texton distance is the squared feature distance, so every texel of a
// one-level output must be the candidate (its causal neighbours' shifted
// coordinates and their k - 1 most similar texels) of least summed distance.
#include "cmfilter/synthesis/kcoherence_synthesis.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <set>

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

// A sample of smooth stripes plus noise: structure for synthesis to keep.
std::vector<float> striped_features(int w, int h, std::uint64_t seed)
{
    std::vector<float> f = random_features(w * h, 2, seed);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            f[2 * (y * w + x)] = 0.2f * f[2 * (y * w + x)] + ((x / 3) % 2 ? 1.0f : 0.0f);
            f[2 * (y * w + x) + 1] = 0.2f * f[2 * (y * w + x) + 1] + ((y / 4) % 2 ? 1.0f : 0.0f);
        }
    return f;
}

SampleAnalysis analyse(int w, int h, int dims, std::vector<float> features, int levels, bool periodic, int n)
{
    auto sample = sample_from_features(w, h, dims, std::move(features), levels, periodic);
    REQUIRE(sample);
    AnalysisOptions options;
    options.neighbourhood = n;
    options.candidates = 6;
    // One texton per texel at level 0 (coarser levels: the default).
    options.textons = levels == 1 ? w * h : 0;
    auto analysis = analyse_sample(*sample, options);
    REQUIRE(analysis);
    return std::move(*analysis);
}

double feature_distance(const std::vector<float>& f, int dims, int a, int b)
{
    double d = 0;
    for (int c = 0; c < dims; ++c) {
        const double e = f[static_cast<std::size_t>(a) * dims + c] - f[static_cast<std::size_t>(b) * dims + c];
        d += e * e;
    }
    return d;
}

}  // namespace

TEST_CASE("k-coherence synthesis: each texel is the best of its k-coherence candidates, by raw feature distance")
{
    const int w = 12, h = 10, dims = 2, n = 2;
    const std::vector<float> f = striped_features(w, h, 5);
    for (bool periodic : {false, true})
        for (int k : {1, 3}) {
            CAPTURE(periodic);
            CAPTURE(k);
            const SampleAnalysis analysis = analyse(w, h, dims, f, 1, periodic, n);
            SynthesisOptions options;
            options.width = 23;
            options.height = 17;
            options.k = k;
            options.neighbourhood = n;
            options.seed = 11;
            auto map = synthesise(analysis, options);
            REQUIRE(map);
            const CoordinateLevel& out = map->full();
            REQUIRE(out.width == 23);
            REQUIRE(out.height == 17);
            auto wrap = [&](int v, int size) {
                return periodic ? ((v % size) + size) % size : std::min(std::max(v, 0), size - 1);
            };
            auto coord = [&](int x, int y) { return out.y(y * out.width + x) * w + out.x(y * out.width + x); };
            int checked = 0;
            for (int y = 0; y < out.height; ++y)
                for (int x = 0; x < out.width; ++x) {
                    // The causal window's texels inside the output, as synthesised.
                    std::vector<std::pair<int, int>> offsets;
                    for (int dy = -n; dy <= 0; ++dy)
                        for (int dx = -n; dx <= n; ++dx) {
                            if (dy == 0 && dx >= 0) continue;
                            if (x + dx < 0 || x + dx >= out.width || y + dy < 0) continue;
                            offsets.push_back({dx, dy});
                        }
                    if (offsets.empty()) continue;
                    std::set<int> candidates;
                    for (auto [dx, dy] : offsets) {
                        const int s = coord(x + dx, y + dy);
                        // A copy that would leave a sample that does not tile ends.
                        const int sx = s % w - dx, sy = s / w - dy;
                        if (!periodic && (sx < 0 || sy < 0 || sx >= w || sy >= h)) continue;
                        const int c = wrap(sy, h) * w + wrap(sx, w);
                        candidates.insert(c);
                        const LevelAnalysis& level = analysis.levels[0];
                        for (int j = 0; j < k - 1; ++j) candidates.insert(level.similar[c * level.candidates + j]);
                    }
                    auto cost = [&](int c) {
                        double sum = 0;
                        for (auto [dx, dy] : offsets) {
                            const int s = wrap(c / w + dy, h) * w + wrap(c % w + dx, w);
                            sum += feature_distance(f, dims, coord(x + dx, y + dy), s);
                        }
                        return sum;
                    };
                    if (candidates.empty()) continue;  // a fresh copy from a random texel
                    double best = 1e300;
                    for (int c : candidates) best = std::min(best, cost(c));
                    const int chosen = coord(x, y);
                    REQUIRE(candidates.count(chosen) == 1);
                    CHECK(cost(chosen) <= best + 1e-4);
                    ++checked;
                }
            CHECK(checked > out.width * out.height * 9 / 10);
        }
}

TEST_CASE("k-coherence synthesis: coordinates stay in the sample at every level, the same for any thread count")
{
    const int w = 16, h = 16;
    const SampleAnalysis analysis = analyse(w, h, 2, striped_features(w, h, 2), 3, false, 1);
    for (bool toroidal : {false, true}) {
        SynthesisOptions options;
        options.width = 37;
        options.height = 29;
        options.k = 3;
        options.neighbourhood = 1;
        options.levels = 3;
        options.toroidal = toroidal;
        options.threads = 1;
        auto one = synthesise(analysis, options);
        options.threads = 2;
        auto two = synthesise(analysis, options);
        REQUIRE(one);
        REQUIRE(two);
        REQUIRE(one->levels.size() == 3);
        for (int l = 0; l < 3; ++l) {
            const CoordinateLevel& level = one->levels[l];
            CHECK(level.width == (37 + (1 << l) - 1) / (1 << l));
            CHECK(level.height == (29 + (1 << l) - 1) / (1 << l));
            CHECK(level.sample_width == analysis.levels[l].width);
            for (std::size_t t = 0; t < level.texels(); ++t) {
                REQUIRE(level.x(t) >= 0);
                REQUIRE(level.x(t) < level.sample_width);
                REQUIRE(level.y(t) >= 0);
                REQUIRE(level.y(t) < level.sample_height);
            }
            CHECK(level.coords == two->levels[l].coords);
        }
        options.seed = 99;
        auto other = synthesise(analysis, options);
        REQUIRE(other);
        CHECK(other->full().coords != one->full().coords);
    }
}

TEST_CASE("k-coherence synthesis: an output the sample's size copied whole from a distinct sample is found again")
{
    // With k = 1 every texel after the first row and column continues its
    // neighbours' copy, so an output seeded at the sample's origin whose
    // first texel's neighbours all continue coherently: most adjacent
    // pairs in the output are adjacent in the sample.
    const int w = 20, h = 20;
    const SampleAnalysis analysis = analyse(w, h, 3, random_features(w * h, 3, 4), 1, true, 1);
    SynthesisOptions options;
    options.width = 64;
    options.height = 64;
    options.k = 1;
    options.neighbourhood = 1;
    auto map = synthesise(analysis, options);
    REQUIRE(map);
    const CoordinateLevel& out = map->full();
    int coherent = 0, pairs = 0;
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x + 1 < out.width; ++x) {
            const std::size_t p = static_cast<std::size_t>(y) * out.width + x;
            ++pairs;
            if (out.x(p + 1) == (out.x(p) + 1) % w && out.y(p + 1) == out.y(p)) ++coherent;
        }
    // Random texels would continue 1 time in 400.
    CHECK(coherent > pairs * 0.8);
}

TEST_CASE("k-coherence synthesis: bad options are refused, naming the field")
{
    const SampleAnalysis analysis = analyse(8, 8, 2, random_features(64, 2, 1), 1, false, 1);
    auto refused = [&](SynthesisOptions options, const char* field) {
        auto map = synthesise(analysis, options);
        REQUIRE_FALSE(map);
        CHECK(map.error().field == field);
        CHECK(map.error().message.find(field) != std::string::npos);
    };
    SynthesisOptions base;
    base.width = base.height = 16;
    base.neighbourhood = 1;
    SynthesisOptions o = base;
    o.width = 0;
    refused(o, "SynthesisOptions::width");
    o = base;
    o.height = kMaxSynthesisSize + 1;
    refused(o, "SynthesisOptions::height");
    o = base;
    o.k = 0;
    refused(o, "SynthesisOptions::k");
    o.k = 8;  // the analysis keeps 6 similar texels: k is at most 7
    refused(o, "SynthesisOptions::k");
    o = base;
    o.neighbourhood = 4;  // a 9 x 9 window in an 8 x 8 sample
    refused(o, "SynthesisOptions::neighbourhood");
    o = base;
    o.levels = 2;
    refused(o, "SynthesisOptions::levels");
}
