// SPDX-License-Identifier: Apache-2.0
// Synthesis quality measures (synthesis_quality.h) against what they must
// be for naive tiling (counted by hand), direct counts, and a brute-force
// computation from the sample's features on a tiny case.
#include "cmfilter/synthesis/synthesis_quality.h"

#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <set>
#include <utility>

using namespace cmfilter;

namespace {

std::vector<float> random_features(std::mt19937_64& rng, int texels, int dims)
{
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<float> f(static_cast<std::size_t>(texels) * dims);
    for (float& v : f) v = unit(rng);
    return f;
}

SampleAnalysis analyse(int w, int h, int dims, const std::vector<float>& features, bool periodic, int textons)
{
    auto sample = sample_from_features(w, h, dims, features, 1, periodic);
    REQUIRE(sample);
    AnalysisOptions options;
    options.textons = textons;
    options.candidates = 3;
    options.neighbourhood = 1;
    auto analysis = analyse_sample(*sample, options);
    REQUIRE_MESSAGE(analysis, (analysis ? std::string() : analysis.error().message));
    return *analysis;
}

CoordinateMap random_map(std::mt19937_64& rng, int w, int h, int sw, int sh, bool toroidal)
{
    CoordinateMap map;
    map.info.toroidal = toroidal;
    CoordinateLevel level;
    level.width = w;
    level.height = h;
    level.sample_width = sw;
    level.sample_height = sh;
    std::uniform_int_distribution<int> ux(0, sw - 1), uy(0, sh - 1);
    for (int t = 0; t < w * h; ++t) {
        level.coords.push_back(ux(rng));
        level.coords.push_back(uy(rng));
    }
    map.levels.push_back(level);
    return map;
}

SynthesisQuality measure(const CoordinateMap& map, const SampleAnalysis& analysis, int n, int texels = 0)
{
    QualityOptions options;
    options.neighbourhood = n;
    options.coherence_texels = texels;
    auto q = measure_synthesis(map, analysis, options);
    REQUIRE_MESSAGE(q, (q ? std::string() : q.error().message));
    return *q;
}

// Squared feature distance between sample texels (x0, y0) and (x1, y1).
double feature_distance(const std::vector<float>& f, int sw, int dims, int x0, int y0, int x1, int y1)
{
    double d = 0;
    for (int c = 0; c < dims; ++c) {
        const double a = f[(static_cast<std::size_t>(y0) * sw + x0) * dims + c];
        const double b = f[(static_cast<std::size_t>(y1) * sw + x1) * dims + c];
        d += (a - b) * (a - b);
    }
    return d;
}

// sqrt(min_q mean_o |f(c(p + o)) - f(q + o)|^2) for output texel (px, py),
// by brute force over every q, o, from the features.
double brute_force_root_distance(const CoordinateMap& map, const std::vector<float>& f, int sw, int sh, int dims,
                                 bool periodic, int n, int px, int py)
{
    const CoordinateLevel& m = map.full();
    auto sample_x = [&](int x) { return periodic ? (x % sw + sw) % sw : std::min(std::max(x, 0), sw - 1); };
    auto sample_y = [&](int y) { return periodic ? (y % sh + sh) % sh : std::min(std::max(y, 0), sh - 1); };
    double best = 1e300;
    for (int qy = 0; qy < sh; ++qy)
        for (int qx = 0; qx < sw; ++qx) {
            double sum = 0;
            int count = 0;
            for (int oy = -n; oy <= n; ++oy)
                for (int ox = -n; ox <= n; ++ox) {
                    int x = px + ox, y = py + oy;
                    if (map.info.toroidal) {
                        x = (x + m.width) % m.width;
                        y = (y + m.height) % m.height;
                    } else if (x < 0 || y < 0 || x >= m.width || y >= m.height) {
                        continue;
                    }
                    const std::size_t t = static_cast<std::size_t>(y) * m.width + x;
                    sum += feature_distance(f, sw, dims, m.x(t), m.y(t), sample_x(qx + ox), sample_y(qy + oy));
                    ++count;
                }
            best = std::min(best, sum / count);
        }
    return std::sqrt(best);
}

// The mean over every output texel of brute_force_root_distance.
double brute_force_coherence(const CoordinateMap& map, const std::vector<float>& f, int sw, int sh, int dims,
                             bool periodic, int n)
{
    const CoordinateLevel& m = map.full();
    double total = 0;
    for (int py = 0; py < m.height; ++py)
        for (int px = 0; px < m.width; ++px)
            total += brute_force_root_distance(map, f, sw, sh, dims, periodic, n, px, py);
    return total / static_cast<double>(m.texels());
}

// The largest (or smallest) brute_force_root_distance over the output.
double brute_force_extreme(const CoordinateMap& map, const std::vector<float>& f, int sw, int sh, int dims,
                           bool periodic, int n, bool largest)
{
    const CoordinateLevel& m = map.full();
    double extreme = largest ? 0.0 : 1e300;
    for (int py = 0; py < m.height; ++py)
        for (int px = 0; px < m.width; ++px) {
            const double d = brute_force_root_distance(map, f, sw, sh, dims, periodic, n, px, py);
            extreme = largest ? std::max(extreme, d) : std::min(extreme, d);
        }
    return extreme;
}

}  // namespace

TEST_CASE("synthesis quality: tiling a periodic sample is perfectly coherent, seamless and covers it")
{
    std::mt19937_64 rng(3);
    const std::vector<float> f = random_features(rng, 8 * 8, 3);
    const SampleAnalysis analysis = analyse(8, 8, 3, f, true, 16);
    const CoordinateMap tiled = tiled_coordinate_map(20, 20, 8, 8);
    const SynthesisQuality q = measure(tiled, analysis, 2);
    // Every output neighbourhood is the sample's (wrapped) neighbourhood there.
    CHECK(q.coherence == 0.0);
    CHECK(q.seam_share == 0.0);
    CHECK(q.seam_contrast == 0.0);
    CHECK(q.coverage == 1.0);
    CHECK(q.uniform_coverage == doctest::Approx(1.0 - std::pow(63.0 / 64.0, 400.0)));
}

TEST_CASE("synthesis quality: tiling a non-periodic sample has a seam at every tile border")
{
    std::mt19937_64 rng(4);
    const std::vector<float> f = random_features(rng, 8 * 6, 2);
    const SampleAnalysis analysis = analyse(8, 6, 2, f, false, 12);
    const CoordinateMap tiled = tiled_coordinate_map(20, 15, 8, 6);
    const SynthesisQuality q = measure(tiled, analysis, 1);
    // Horizontal pairs: 19 per row, 15 rows; borders after x = 7, 15: 2 per row.
    // Vertical pairs: 14 per column, 20 columns; borders after y = 5, 11: 2 per column.
    const double pairs = 19.0 * 15 + 14.0 * 20, seams = 2.0 * 15 + 2.0 * 20;
    CHECK(q.seam_share == doctest::Approx(seams / pairs));
    CHECK(q.seam_contrast > 0.0);
    CHECK(q.coverage == 1.0);
    // The borders' neighbourhoods do not occur in a clamped sample.
    CHECK(q.coherence > 0.0);

    // A toroidal tiling adds the wrapping pairs: 15 more horizontal, 20 more
    // vertical, each a seam unless the output is a multiple of the sample
    // (20 = 2.5 x 8: seams; 15 = 2.5 x 6: seams).
    CoordinateMap toroidal = tiled;
    toroidal.info.toroidal = true;
    const SynthesisQuality t = measure(toroidal, analysis, 1);
    CHECK(t.seam_share == doctest::Approx((seams + 15 + 20) / (pairs + 15 + 20)));
}

TEST_CASE("synthesis quality: the coherence's texel grid sees the tile borders of a tiling whose period divides it")
{
    // 128 x 128 output of a 16 x 16 non-periodic sample, measured at 256 texels:
    // an 8 x 8-texel cell each, so cell centres would all sit 4 texels from a border.
    std::mt19937_64 rng(12);
    const std::vector<float> f = random_features(rng, 16 * 16, 3);
    const SampleAnalysis analysis = analyse(16, 16, 3, f, false, 64);
    const CoordinateMap tiled = tiled_coordinate_map(128, 128, 16, 16);
    const SynthesisQuality grid = measure(tiled, analysis, 2, 256);
    const SynthesisQuality all = measure(tiled, analysis, 2, 0);
    CHECK(all.coherence > 0.0);
    CHECK(grid.coherence > 0.0);
    // The grid's estimate within a factor of 2 of the full mean.
    CHECK(grid.coherence > 0.5 * all.coherence);
    CHECK(grid.coherence < 2.0 * all.coherence);
}

TEST_CASE("synthesis quality: a random map is incoherent and its coverage is the share of texels it copies")
{
    std::mt19937_64 rng(6);
    const std::vector<float> f = random_features(rng, 12 * 12, 3);
    const SampleAnalysis analysis = analyse(12, 12, 3, f, false, 36);
    const CoordinateMap map = random_map(rng, 10, 9, 12, 12, false);
    const SynthesisQuality q = measure(map, analysis, 1);
    CHECK(q.coherence > 0.3);
    std::set<std::pair<int, int>> used;
    for (std::size_t t = 0; t < map.full().texels(); ++t) used.insert({map.full().x(t), map.full().y(t)});
    CHECK(q.coverage == doctest::Approx(used.size() / 144.0));
    CHECK(q.uniform_coverage == doctest::Approx(1.0 - std::pow(1.0 - 1.0 / 144.0, 90.0)));
    // Almost every random neighbour pair is a seam.
    CHECK(q.seam_share > 0.9);
    // The same map measured on an even grid of texels, whatever the thread count.
    QualityOptions options;
    options.neighbourhood = 1;
    options.coherence_texels = 20;
    options.threads = 1;
    auto one = measure_synthesis(map, analysis, options);
    options.threads = 3;
    auto three = measure_synthesis(map, analysis, options);
    REQUIRE(one);
    REQUIRE(three);
    CHECK(one->coherence == three->coherence);
    CHECK(one->coherence > 0.3);
}

TEST_CASE("synthesis quality: coherence and seams of a hand-made map match a brute-force computation from the features")
{
    // 4 x 4 sample with a texton per texel, so texton distances are feature distances.
    std::mt19937_64 rng(8);
    const int sw = 4, sh = 4, dims = 3;
    const std::vector<float> f = random_features(rng, sw * sh, dims);
    for (bool periodic : {false, true}) {
        CAPTURE(periodic);
        const SampleAnalysis analysis = analyse(sw, sh, dims, f, periodic, sw * sh);
        REQUIRE(analysis.levels[0].textons == sw * sh);
        // A 6 x 6 map: the sample's top-left 3 x 3 corner copied at (0, 0),
        // the rest random; and a fully random one.
        CoordinateMap a = random_map(rng, 6, 6, sw, sh, false);
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 3; ++x) {
                a.levels[0].coords[2 * (y * 6 + x)] = x;
                a.levels[0].coords[2 * (y * 6 + x) + 1] = y;
            }
        CoordinateMap b = random_map(rng, 6, 6, sw, sh, true);
        const double ca = brute_force_coherence(a, f, sw, sh, dims, periodic, 1);
        const double cb = brute_force_coherence(b, f, sw, sh, dims, periodic, 1);
        const SynthesisQuality qa = measure(a, analysis, 1), qb = measure(b, analysis, 1);
        // The normaliser (random sample pairs) is common to both.
        REQUIRE(cb > 0);
        CHECK(qa.coherence / qb.coherence == doctest::Approx(ca / cb).epsilon(1e-4));
        // ... and close to the root of the mean over all sample pairs.
        double all_pairs = 0;
        for (int i = 0; i < sw * sh; ++i)
            for (int j = 0; j < sw * sh; ++j)
                all_pairs += feature_distance(f, sw, dims, i % sw, i / sw, j % sw, j / sw);
        all_pairs /= double(sw * sh) * (sw * sh);
        CHECK(qb.coherence == doctest::Approx(cb / std::sqrt(all_pairs)).epsilon(0.05));
        // Nine texels of a 6 x 6 output, one in each 2 x 2 cell: between the
        // best and the worst texel's root distance (brute force).
        const SynthesisQuality qa9 = measure(a, analysis, 1, 9);
        const double nine = qa9.coherence / qb.coherence * cb;
        CHECK(nine >= brute_force_extreme(a, f, sw, sh, dims, periodic, 1, false) - 1e-6);
        CHECK(nine <= brute_force_extreme(a, f, sw, sh, dims, periodic, 1, true) + 1e-6);

        // Seams of b (toroidal), counted directly.
        const CoordinateLevel& m = b.full();
        int seams = 0, pairs = 0;
        double seam_distance = 0;
        for (int y = 0; y < 6; ++y)
            for (int x = 0; x < 6; ++x)
                for (auto [ex, ey] : {std::pair<int, int>{1, 0}, std::pair<int, int>{0, 1}}) {
                    const int p = y * 6 + x, q = ((y + ey) % 6) * 6 + (x + ex) % 6;
                    int cx = m.x(p) + ex, cy = m.y(p) + ey;
                    if (periodic) {
                        cx %= sw;
                        cy %= sh;
                    }
                    ++pairs;
                    if (m.x(q) == cx && m.y(q) == cy) continue;
                    ++seams;
                    seam_distance += feature_distance(f, sw, dims, m.x(p), m.y(p), m.x(q), m.y(q));
                }
        double edge_distance = 0;
        int edges = 0;
        for (int y = 0; y < sh; ++y)
            for (int x = 0; x < sw; ++x) {
                if (periodic || x + 1 < sw) {
                    edge_distance += feature_distance(f, sw, dims, x, y, (x + 1) % sw, y);
                    ++edges;
                }
                if (periodic || y + 1 < sh) {
                    edge_distance += feature_distance(f, sw, dims, x, y, x, (y + 1) % sh);
                    ++edges;
                }
            }
        REQUIRE(seams > 0);
        CHECK(pairs == 72);
        CHECK(qb.seam_share == doctest::Approx(double(seams) / pairs));
        CHECK(qb.seam_contrast == doctest::Approx((seam_distance / seams) / (edge_distance / edges)).epsilon(1e-4));
    }
}

TEST_CASE("synthesis quality: a map into another sample and a bad neighbourhood are refused")
{
    std::mt19937_64 rng(10);
    const SampleAnalysis analysis = analyse(6, 6, 2, random_features(rng, 36, 2), false, 9);
    QualityOptions options;
    auto other = measure_synthesis(tiled_coordinate_map(8, 8, 7, 6), analysis, options);
    REQUIRE_FALSE(other);
    CHECK(other.error().kind == ErrorKind::BadInput);
    CHECK_MESSAGE(other.error().message.find("7 x 6") != std::string::npos, other.error().message);
    options.neighbourhood = 3;
    auto wide = measure_synthesis(tiled_coordinate_map(8, 8, 6, 6), analysis, options);
    REQUIRE_FALSE(wide);
    CHECK(wide.error().field == "QualityOptions::neighbourhood");
    CoordinateMap outside = tiled_coordinate_map(8, 8, 6, 6);
    outside.levels[0].coords[2 * 9 + 1] = 6;
    options.neighbourhood = 1;
    auto out = measure_synthesis(outside, analysis, options);
    REQUIRE_FALSE(out);
    CHECK_MESSAGE(out.error().message.find("texel (1, 1)") != std::string::npos, out.error().message);
}
