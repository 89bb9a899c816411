// SPDX-License-Identifier: Apache-2.0
// Rendering through a coordinate map at full size and at a level of detail
// (coordinate_lookup.h), against loops written here: direct gathers, box
// means of the sample and of the output summed texel by texel, a 2 x 2 box
// pyramid built here, and per-footprint offset histograms counted in a
// std::map.
#include "cmfilter/synthesis/coordinate_lookup.h"

#include "patch_map_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

using namespace cmfilter;
using cmfilter_test::procedural_sample;

namespace {

float texel(const SampleImage& s, int x, int y, int c)
{
    return s.pixels[(static_cast<std::size_t>(y) * s.width + x) * s.channels + c];
}

// The sample's mean over [x0, x0 + w) x [y0, y0 + h), texel by texel,
// wrapping (periodic) or with the box moved inside the sample.
double brute_box(const SampleImage& s, long long x0, long long y0, int w, int h, int c)
{
    if (!s.periodic) {
        x0 = std::clamp<long long>(x0, 0, s.width - w);
        y0 = std::clamp<long long>(y0, 0, s.height - h);
    }
    double sum = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            sum += texel(s, cmfilter_test::wrap_index(x0 + x, s.width), cmfilter_test::wrap_index(y0 + y, s.height), c);
    return sum / (static_cast<double>(w) * h);
}

// The full-size output box-filtered over each footprint, from the map and
// the sample directly.
std::vector<double> brute_reference(const CoordinateMap& map, const SampleImage& s, int lod, int& ow, int& oh)
{
    const CoordinateLevel& f = map.full();
    const int step = 1 << lod;
    ow = (f.width + step - 1) / step;
    oh = (f.height + step - 1) / step;
    std::vector<double> out;
    for (int j = 0; j < oh; ++j)
        for (int i = 0; i < ow; ++i)
            for (int c = 0; c < s.channels; ++c) {
                double sum = 0;
                int n = 0;
                for (int y = j * step; y < std::min(f.height, (j + 1) * step); ++y)
                    for (int x = i * step; x < std::min(f.width, (i + 1) * step); ++x, ++n) {
                        const std::size_t t = static_cast<std::size_t>(y) * f.width + x;
                        sum += texel(s, f.x(t), f.y(t), c);
                    }
                out.push_back(sum / n);
            }
    return out;
}

OutputImage render(const CoordinateMap& map, const SampleImage& s, int lod, LodMethod method, int patches = 4,
                   int threads = 3)
{
    LodOptions o;
    o.lod = lod;
    o.method = method;
    o.patches = patches;
    o.threads = threads;
    auto out = render_at_lod(map, s, o);
    REQUIRE(out);
    return *out;
}

double max_difference(const OutputImage& image, const std::vector<double>& expected)
{
    REQUIRE(image.pixels.size() == expected.size());
    double worst = 0;
    for (std::size_t i = 0; i < expected.size(); ++i) worst = std::max(worst, std::abs(image.pixels[i] - expected[i]));
    return worst;
}

}  // namespace

TEST_CASE("coordinate lookup: the full-size output gathers the sample texel each coordinate names")
{
    const SampleImage sample = procedural_sample(23, 17, 3, false);
    const CoordinateMap map = cmfilter_test::random_patch_map(41, 37, 23, 17, 3, 9, false, 11);
    auto out = render_through_map(map, sample, 4);
    REQUIRE(out);
    CHECK(out->width == 41);
    CHECK(out->height == 37);
    CHECK(out->channels == 3);
    const CoordinateLevel& f = map.full();
    int mismatches = 0;
    for (int y = 0; y < 37; ++y)
        for (int x = 0; x < 41; ++x)
            for (int c = 0; c < 3; ++c) {
                const std::size_t t = static_cast<std::size_t>(y) * 41 + x;
                if (out->pixels[t * 3 + c] != texel(sample, f.x(t), f.y(t), c)) ++mismatches;
            }
    CHECK(mismatches == 0);
}

TEST_CASE("coordinate lookup: Reference is the box mean of the full-size output, edge footprints partial")
{
    const SampleImage sample = procedural_sample(20, 20, 2, true);
    const CoordinateMap map = cmfilter_test::random_patch_map(45, 38, 20, 20, 3, 10, true, 5);
    for (int lod : {0, 1, 2, 3, 6}) {
        CAPTURE(lod);
        int ow = 0, oh = 0;
        const std::vector<double> expected = brute_reference(map, sample, lod, ow, oh);
        const OutputImage out = render(map, sample, lod, LodMethod::Reference);
        CHECK(out.width == ow);
        CHECK(out.height == oh);
        CHECK(max_difference(out, expected) < 1e-6);
    }
}

TEST_CASE("coordinate lookup: Patches is exact for one shifted copy of the sample at every LOD")
{
    struct Case {
        int dx, dy;
        bool periodic;
    };
    // Offsets not multiples of 2^L; periodic ones wrap around the sample.
    for (const Case& k : {Case{3, 5, false}, Case{0, 0, false}, Case{7, 1, true}, Case{-13, 29, true}}) {
        CAPTURE(k.dx);
        CAPTURE(k.dy);
        const SampleImage sample = procedural_sample(k.periodic ? 32 : 64, k.periodic ? 24 : 60, 3, k.periodic);
        const int width = k.periodic ? 70 : 53, height = k.periodic ? 50 : 47;
        const CoordinateMap map =
            cmfilter_test::shifted_map(width, height, sample.width, sample.height, k.dx, k.dy, k.periodic);
        for (int lod = 0; lod <= 6; ++lod) {
            CAPTURE(lod);
            int ow = 0, oh = 0;
            const std::vector<double> expected = brute_reference(map, sample, lod, ow, oh);
            CHECK(max_difference(render(map, sample, lod, LodMethod::Patches, 1), expected) < 1e-6);
            CHECK(max_difference(render(map, sample, lod, LodMethod::Patches, 4), expected) < 1e-6);
        }
    }
}

TEST_CASE("coordinate lookup: at a seam Patches is the share-weighted mean of each piece's footprint box")
{
    const SampleImage sample = procedural_sample(40, 40, 3, false);
    // Columns [0, 6) copy from (20, 3) on, columns [6, 16) from (2, 30) on:
    // the LOD-2 footprints [4, 8) x .. hold two columns of each.
    CoordinateMap map = cmfilter_test::empty_map(16, 8, 40, 40, false);
    cmfilter_test::paste_patch(map, 0, 0, 6, 8, 20, 3);
    cmfilter_test::paste_patch(map, 6, 0, 16, 8, 2, 30);
    const int d1x = 20, d1y = 3, d2x = 2 - 6, d2y = 30;
    const OutputImage out = render(map, sample, 2, LodMethod::Patches, 4);
    REQUIRE(out.width == 4);
    REQUIRE(out.height == 2);
    for (int j = 0; j < 2; ++j)
        for (int c = 0; c < 3; ++c) {
            const int x0 = 4, y0 = 4 * j;
            const double expected = 0.5 * brute_box(sample, x0 + d1x, y0 + d1y, 4, 4, c) +
                                    0.5 * brute_box(sample, x0 + d2x, y0 + d2y, 4, 4, c);
            CHECK(std::abs(out.pixels[(static_cast<std::size_t>(j) * 4 + 1) * 3 + c] - expected) < 1e-6);
            // Footprint 0 lies in the first piece: its box alone.
            CHECK(std::abs(out.pixels[(static_cast<std::size_t>(j) * 4) * 3 + c] -
                           brute_box(sample, d1x, y0 + d1y, 4, 4, c)) < 1e-6);
        }
    auto level = build_patch_level(map, 2, 4, false, 1);
    REQUIRE(level);
    const float* first = level->entry(1, 0);
    const float* second = level->entry(1, 1);
    // Equal shares: the lower (dy, dx) first.
    CHECK(first[0] == doctest::Approx(d1x));
    CHECK(first[1] == doctest::Approx(d1y));
    CHECK(first[2] == doctest::Approx(0.5));
    CHECK(second[0] == doctest::Approx(d2x));
    CHECK(second[1] == doctest::Approx(d2y));
    CHECK(second[2] == doctest::Approx(0.5));
    CHECK(level->entry(1, 2)[2] == 0.0f);
}

TEST_CASE("coordinate lookup: patch levels hold each footprint's offset histogram, as shares of the footprint")
{
    const CoordinateMap map = cmfilter_test::random_patch_map(50, 44, 30, 26, 2, 7, true, 19);
    const CoordinateLevel& f = map.full();
    for (int lod : {1, 2, 3}) {
        for (int patches : {2, 64}) {
            CAPTURE(lod);
            CAPTURE(patches);
            auto level = build_patch_level(map, lod, patches, true, 3);
            REQUIRE(level);
            const int step = 1 << lod;
            int bad_sums = 0, bad_shares = 0;
            for (int j = 0; j < level->height; ++j)
                for (int i = 0; i < level->width; ++i) {
                    std::map<std::pair<int, int>, int> counts;
                    int n = 0;
                    for (int y = j * step; y < std::min(f.height, (j + 1) * step); ++y)
                        for (int x = i * step; x < std::min(f.width, (i + 1) * step); ++x, ++n) {
                            const std::size_t t = static_cast<std::size_t>(y) * f.width + x;
                            ++counts[{cmfilter_test::wrap_index(f.y(t) - y, 26),
                                      cmfilter_test::wrap_index(f.x(t) - x, 30)}];
                        }
                    const std::size_t texel = static_cast<std::size_t>(j) * level->width + i;
                    double sum = 0;
                    int kept = 0;
                    for (int k = 0; k < patches; ++k) sum += level->entry(texel, k)[2];
                    // The kept shares cover the footprint's `patches` most common pieces.
                    std::vector<int> sorted;
                    for (const auto& kv : counts) sorted.push_back(kv.second);
                    std::sort(sorted.rbegin(), sorted.rend());
                    double expected = 0;
                    for (std::size_t k = 0; k < sorted.size() && k < static_cast<std::size_t>(patches); ++k)
                        expected += static_cast<double>(sorted[k]) / n;
                    if (std::abs(sum - expected) > 1e-6) ++bad_sums;
                    // With room for every offset, each share is its count / n.
                    if (patches == 64) {
                        for (int k = 0; k < patches; ++k) {
                            const float* e = level->entry(texel, k);
                            if (e[2] == 0) continue;
                            ++kept;
                            const auto it = counts.find({static_cast<int>(e[1]), static_cast<int>(e[0])});
                            if (it == counts.end() || std::abs(e[2] - static_cast<double>(it->second) / n) > 1e-6)
                                ++bad_shares;
                        }
                        if (kept != static_cast<int>(counts.size())) ++bad_shares;
                    }
                }
            CHECK(bad_sums == 0);
            CHECK(bad_shares == 0);
        }
    }
}

TEST_CASE("coordinate lookup: aligned shifts make NaiveMip and Point the sample's own box pyramid")
{
    // A 2 x 2 box pyramid of the sample (odd edges repeat their last texel),
    // built here; with offsets multiples of 2^L every footprint is one texel
    // of level L.
    const SampleImage sample = procedural_sample(32, 32, 2, true);
    std::vector<SampleImage> pyramid{sample};
    while (pyramid.back().width > 1) {
        const SampleImage& a = pyramid.back();
        SampleImage b = a;
        b.width = (a.width + 1) / 2;
        b.height = (a.height + 1) / 2;
        b.pixels.clear();
        for (int y = 0; y < b.height; ++y)
            for (int x = 0; x < b.width; ++x)
                for (int c = 0; c < a.channels; ++c) {
                    const int x1 = std::min(2 * x + 1, a.width - 1), y1 = std::min(2 * y + 1, a.height - 1);
                    b.pixels.push_back(
                        static_cast<float>((static_cast<double>(texel(a, 2 * x, 2 * y, c)) + texel(a, x1, 2 * y, c) +
                                            texel(a, 2 * x, y1, c) + texel(a, x1, y1, c)) /
                                           4));
                }
        pyramid.push_back(b);
    }
    for (int lod = 1; lod <= 3; ++lod) {
        CAPTURE(lod);
        const int d = 3 << lod;
        const CoordinateMap map = cmfilter_test::shifted_map(64, 64, 32, 32, d, 2 * d, true);
        const SampleImage& level = pyramid[lod];
        std::vector<double> expected;
        const int n = 64 >> lod;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                for (int c = 0; c < 2; ++c)
                    expected.push_back(texel(level, cmfilter_test::wrap_index(i + (d >> lod), level.width),
                                             cmfilter_test::wrap_index(j + (2 * d >> lod), level.height), c));
        CHECK(max_difference(render(map, sample, lod, LodMethod::NaiveMip), expected) < 1e-5);
        CHECK(max_difference(render(map, sample, lod, LodMethod::Point), expected) < 1e-5);
        CHECK(max_difference(render(map, sample, lod, LodMethod::Reference), expected) < 1e-5);

        // The levels method: the synthesis's level-L map of the same shift,
        // into the sample's level L.
        CoordinateMap with_levels = map;
        for (int l = 1; l <= lod; ++l) {
            CoordinateMap coarse =
                cmfilter_test::shifted_map(64 >> l, 64 >> l, 32 >> l, 32 >> l, d >> l, (2 * d) >> l, true);
            with_levels.levels.push_back(coarse.levels[0]);
        }
        CHECK(max_difference(render(with_levels, sample, lod, LodMethod::Levels), expected) < 1e-6);
    }
}

TEST_CASE("coordinate lookup: on random patches Patches beats Point, which beats the naive mip of coordinates")
{
    // Pieces of 24 to 64 texels of a 128 x 128 sample: footprints of 4 to 16
    // texels lie inside one piece or across a few seams.
    const SampleImage sample = procedural_sample(128, 128, 3, false, 3);
    const CoordinateMap map = cmfilter_test::random_patch_map(256, 256, 128, 128, 24, 64, false, 23);
    for (int lod = 2; lod <= 4; ++lod) {
        CAPTURE(lod);
        int ow = 0, oh = 0;
        const std::vector<double> expected = brute_reference(map, sample, lod, ow, oh);
        const auto rmse = [&](const OutputImage& image) {
            double sum = 0;
            for (std::size_t i = 0; i < expected.size(); ++i) sum += std::pow(image.pixels[i] - expected[i], 2);
            return std::sqrt(sum / expected.size());
        };
        const double patches = rmse(render(map, sample, lod, LodMethod::Patches, 4));
        const double point = rmse(render(map, sample, lod, LodMethod::Point));
        const double naive = rmse(render(map, sample, lod, LodMethod::NaiveMip));
        MESSAGE("L=" << lod << " patches " << patches << " point " << point << " naive " << naive);
        CHECK(patches < 0.5 * point);
        CHECK(point < 0.8 * naive);
    }
}

TEST_CASE("coordinate lookup: bad options and maps outside the sample are named")
{
    const SampleImage sample = procedural_sample(16, 16, 1, false);
    const CoordinateMap map = cmfilter_test::shifted_map(20, 20, 16, 16, 0, 0, true);
    LodOptions o;
    o.lod = -1;
    auto r = render_at_lod(map, sample, o);
    REQUIRE_FALSE(r);
    CHECK(r.error().kind == ErrorKind::BadInput);
    CHECK(r.error().field == "LodOptions::lod");
    o.lod = 1;
    o.patches = 0;
    r = render_at_lod(map, sample, o);
    REQUIRE_FALSE(r);
    CHECK(r.error().field == "LodOptions::patches");
    o.patches = 4;
    o.method = LodMethod::Levels;
    r = render_at_lod(map, sample, o);
    REQUIRE_FALSE(r);
    CHECK(r.error().field == "LodOptions::lod");
    CHECK(r.error().message.find("1 (0 .. 0") != std::string::npos);

    const SampleImage small = procedural_sample(8, 16, 1, false);
    auto full = render_through_map(map, small);
    REQUIRE_FALSE(full);
    CHECK(full.error().kind == ErrorKind::BadInput);
    CHECK(full.error().message.find("16 x 16") != std::string::npos);
    CHECK(full.error().message.find("8 x 16") != std::string::npos);

    CoordinateMap outside = map;
    outside.levels[0].coords[2 * 5] = 16;
    full = render_through_map(outside, sample);
    REQUIRE_FALSE(full);
    CHECK(full.error().message.find("(16, 0)") != std::string::npos);

    CHECK(std::string(to_string(LodMethod::NaiveMip)) == "naive");
    auto parsed = parse_lod_method("patches");
    REQUIRE(parsed);
    CHECK(*parsed == LodMethod::Patches);
    auto unknown = parse_lod_method("mip");
    REQUIRE_FALSE(unknown);
    CHECK(unknown.error().field == "LodOptions::method");
}
