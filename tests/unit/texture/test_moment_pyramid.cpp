// SPDX-License-Identifier: Apache-2.0
// Moment pyramids (Heitz et al. 2013, sec. 4.2) against independent
// computations: every level of the written file, read back with OpenImageIO's
// ImageInput, against brute-force box means of the level-0 data in double
// precision (power-of-two and other sizes); against `maketx --filter box`;
// the offset driver [1000, 1000.01] where naive float moments fail; and
// TextureSystem lookups through MomentTexture at texel centres.
#include "cmfilter/texture/moment_pyramid.h"
#include "cmfilter/texture/moment_texture.h"
#include "cmfilter/texture/texture_lod.h"

#include "box_reference.h"

#include <OpenImageIO/imageio.h>
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

using namespace cmfilter;
namespace fs = std::filesystem;

namespace {

fs::path test_dir()
{
    const fs::path dir = fs::temp_directory_path() / "cmfilter-test-moment-pyramid";
    fs::create_directories(dir);
    return dir;
}

// A reproducible driver: uniform values in [lo, hi) from a 64-bit LCG.
std::vector<float> random_driver(int w, int h, double lo, double hi, std::uint64_t seed)
{
    std::vector<float> v(static_cast<std::size_t>(w) * h);
    for (float& x : v) {
        seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
        x = static_cast<float>(lo + (hi - lo) * static_cast<double>(seed >> 11) * 0x1.0p-53);
    }
    return v;
}

void write_image(const std::string& path, int w, int h, int channels, OIIO::TypeDesc type, const void* data)
{
    auto out = OIIO::ImageOutput::create(path);
    REQUIRE(out);
    REQUIRE(out->open(path, OIIO::ImageSpec(w, h, channels, type)));
    REQUIRE(out->write_image(type, data));
    REQUIRE(out->close());
}

struct Level {
    int w = 0, h = 0;
    std::vector<float> m;  // (m1, m2) per texel
};

// Every MIP level of a file of `channels` moments, read with ImageInput.
std::vector<Level> read_levels(const std::string& path, int channels = 2)
{
    auto in = OIIO::ImageInput::open(path);
    REQUIRE(in);
    std::vector<Level> levels;
    for (int k = 0; in->seek_subimage(0, k); ++k) {
        const OIIO::ImageSpec& spec = in->spec();
        REQUIRE(spec.nchannels == channels);
        Level L{spec.width, spec.height, std::vector<float>(std::size_t(spec.width) * spec.height * channels)};
        REQUIRE(in->read_image(0, k, 0, channels, OIIO::TypeDesc::FLOAT, L.m.data()));
        levels.push_back(std::move(L));
    }
    return levels;
}

MomentBakeResult bake(const std::string& driver, const std::string& output, int order = 2)
{
    MomentBakeOptions options;
    options.driver_path = driver;
    options.output_path = output;
    options.order = order;
    auto r = bake_moment_pyramid(options);
    if (!r) FAIL(r.error().message);
    return *r;
}

// Brute force (tests/support/box_reference.h): the box mean of
// g = (f - c)^power over texel (x, y) of a w x h level, summed in double.
double box_mean(const std::vector<float>& f, int W, int H, int w, int h, int x, int y, double c, int power)
{
    double sum = 0;
    for (const auto& b : cmfilter_test::box_weights(W, H, w, h, x, y)) {
        const double d = double(f[std::size_t(b.j) * W + b.i]) - c;
        sum += b.weight * std::pow(d, power);
    }
    return sum;
}

double level_extent(int e, int k) { return std::max(1, e >> k); }

}  // namespace

TEST_CASE("moment pyramid levels are exact box means of level 0, any size")
{
    // Float32 storage of a value computed in double rounds it by at most half
    // an ulp, 2^-24 relative; the tolerance allows 2^-23 |ref| plus 1e-12 for
    // the double sums on both sides.
    for (const auto& wh : std::vector<std::pair<int, int>>{{16, 16}, {32, 8}, {37, 23}, {5, 3}, {64, 1}, {1, 9}}) {
        const int W = wh.first, H = wh.second;
        CAPTURE(W);
        CAPTURE(H);
        const auto f = random_driver(W, H, -2.0, 3.0, 7 + W * 100 + H);
        const std::string driver =
            (test_dir() / ("box-" + std::to_string(W) + "x" + std::to_string(H) + ".exr")).string();
        const std::string output =
            (test_dir() / ("box-moments-" + std::to_string(W) + "x" + std::to_string(H) + ".exr")).string();
        write_image(driver, W, H, 1, OIIO::TypeDesc::FLOAT, f.data());
        const MomentBakeResult r = bake(driver, output);
        double mean = 0;
        for (float v : f) mean += v;
        mean /= f.size();
        CHECK(r.info.reference == doctest::Approx(mean).epsilon(1e-12));
        const double c = r.info.reference;

        const auto levels = read_levels(output);
        int expected_levels = 1;
        while ((std::max(W, H) >> expected_levels) > 0) ++expected_levels;
        REQUIRE(int(levels.size()) == expected_levels);
        REQUIRE(r.info.levels == expected_levels);
        for (int k = 0; k < int(levels.size()); ++k) {
            const Level& L = levels[k];
            REQUIRE(L.w == level_extent(W, k));
            REQUIRE(L.h == level_extent(H, k));
            double worst = 0;
            for (int y = 0; y < L.h; ++y)
                for (int x = 0; x < L.w; ++x)
                    for (int p = 1; p <= 2; ++p) {
                        const double ref = box_mean(f, W, H, L.w, L.h, x, y, c, p);
                        const double got = L.m[(std::size_t(y) * L.w + x) * 2 + p - 1];
                        const double err = std::abs(got - ref) - (0x1.0p-23 * std::abs(ref) + 1e-12);
                        worst = std::max(worst, err);
                    }
            CAPTURE(k);
            CHECK(worst <= 0);
        }
    }
}

TEST_CASE("a pyramid of order 4 holds the box means of (f - c)^3 and (f - c)^4 too, and lookups their central moments")
{
    for (const auto& wh : std::vector<std::pair<int, int>>{{16, 16}, {37, 23}}) {
        const int W = wh.first, H = wh.second;
        CAPTURE(W);
        const auto f = random_driver(W, H, 0.0, 1.0, 11 + W);
        const std::string driver = (test_dir() / ("order4-" + std::to_string(W) + ".exr")).string();
        const std::string output = (test_dir() / ("order4-moments-" + std::to_string(W) + ".exr")).string();
        write_image(driver, W, H, 1, OIIO::TypeDesc::FLOAT, f.data());
        const MomentBakeResult r = bake(driver, output, 4);
        CHECK(r.info.order == 4);
        const double c = r.info.reference;
        const auto levels = read_levels(output, 4);
        for (int k = 0; k < int(levels.size()); ++k) {
            const Level& L = levels[k];
            double worst = 0;
            for (int y = 0; y < L.h; ++y)
                for (int x = 0; x < L.w; ++x)
                    for (int p = 1; p <= 4; ++p) {
                        const double ref = box_mean(f, W, H, L.w, L.h, x, y, c, p);
                        const double got = L.m[(std::size_t(y) * L.w + x) * 4 + p - 1];
                        worst = std::max(worst, std::abs(got - ref) - (0x1.0p-23 * std::abs(ref) + 1e-12));
                    }
            CAPTURE(k);
            CHECK(worst <= 0);
        }
        // A lookup at a level-1 texel centre: the texel's own central moments,
        // brute force about its own mean (float32 moments: 1e-5 absolute on
        // moments of values in [0, 1]).
        auto tex = MomentTexture::open(output);
        REQUIRE(tex);
        const int w = std::max(1, W >> 1), h = std::max(1, H >> 1);
        for (const auto& xy : std::vector<std::pair<int, int>>{{0, 0}, {w / 2, h / 3}, {w - 1, h - 1}}) {
            const MomentSample m = tex->lookup((xy.first + 0.5f) / w, (xy.second + 0.5f) / h, 1.0f);
            REQUIRE(m.ok);
            const double mean = c + box_mean(f, W, H, w, h, xy.first, xy.second, c, 1);
            CHECK(m.mean == doctest::Approx(mean).epsilon(1e-6));
            CHECK(std::abs(m.mu3 - box_mean(f, W, H, w, h, xy.first, xy.second, mean, 3)) <= 1e-5);
            CHECK(std::abs(m.mu4 - box_mean(f, W, H, w, h, xy.first, xy.second, mean, 4)) <= 1e-5);
        }
    }
    MomentBakeOptions bad;
    bad.driver_path = "unused.exr";
    bad.output_path = (test_dir() / "order3.exr").string();
    bad.order = 3;
    auto refused = bake_moment_pyramid(bad);
    REQUIRE(!refused);
    CHECK(refused.error().field == "MomentBakeOptions::order");
}

TEST_CASE("8-bit drivers are data: codes / 255, no sRGB decoding")
{
    const int W = 7, H = 3;
    std::vector<unsigned char> codes(W * H);
    for (int i = 0; i < W * H; ++i) codes[i] = static_cast<unsigned char>(i * 12);
    const std::string driver = (test_dir() / "codes.png").string();
    const std::string output = (test_dir() / "codes-moments.exr").string();
    write_image(driver, W, H, 1, OIIO::TypeDesc::UINT8, codes.data());
    const MomentBakeResult r = bake(driver, output);
    const auto levels = read_levels(output);
    for (int i = 0; i < W * H; ++i)  // float32 storage of (code / 255 - c): 1e-6 absolute
        CHECK(std::abs(levels[0].m[2 * i] + r.info.reference - codes[i] / 255.0) <= 1e-6);
    CHECK(r.info.driver_max == doctest::Approx(240 / 255.0));
}

TEST_CASE("moment pyramid matches maketx --filter box on a power-of-two driver")
{
    const std::string maketx = CMFILTER_MAKETX;
    if (maketx.empty()) {
        MESSAGE("maketx not found; skipped");
        return;
    }
    const int W = 32, H = 16;
    const auto f = random_driver(W, H, 0.0, 1.0, 99);
    const std::string driver = (test_dir() / "pow2.exr").string();
    const std::string output = (test_dir() / "pow2-moments.exr").string();
    write_image(driver, W, H, 1, OIIO::TypeDesc::FLOAT, f.data());
    const MomentBakeResult r = bake(driver, output);
    // maketx averages whatever channels it is given: give it (f - c, (f - c)^2).
    std::vector<float> pair(std::size_t(W) * H * 2);
    for (std::size_t i = 0; i < f.size(); ++i) {
        const double d = double(f[i]) - r.info.reference;
        pair[2 * i] = float(d);
        pair[2 * i + 1] = float(d * d);
    }
    const std::string pair_path = (test_dir() / "pow2-pair.exr").string();
    const std::string made = (test_dir() / "pow2-maketx.exr").string();
    write_image(pair_path, W, H, 2, OIIO::TypeDesc::FLOAT, pair.data());
    const std::string command = "'" + maketx + "' --filter box -d float --tile 64 64 --compression zip '" + pair_path +
                                "' -o '" + made + "' > /dev/null 2>&1";
    REQUIRE(std::system(command.c_str()) == 0);
    const auto ours = read_levels(output);
    const auto theirs = read_levels(made);
    REQUIRE(ours.size() == theirs.size());
    // maketx filters in float from float inputs: 1e-6 absolute on values of
    // magnitude <= 1 covers its rounding and ours.
    for (std::size_t k = 0; k < ours.size(); ++k) {
        CAPTURE(k);
        REQUIRE(ours[k].w == theirs[k].w);
        REQUIRE(ours[k].h == theirs[k].h);
        double worst = 0;
        for (std::size_t i = 0; i < ours[k].m.size(); ++i)
            worst = std::max(worst, double(std::abs(ours[k].m[i] - theirs[k].m[i])));
        CHECK(worst <= 1e-6);
    }
}

TEST_CASE("offset driver 1000..1000.01: sigma survives where naive float moments cancel")
{
    const int W = 48, H = 40;
    const auto f = random_driver(W, H, 1000.0, 1000.01, 5);
    const std::string driver = (test_dir() / "offset.exr").string();
    const std::string output = (test_dir() / "offset-moments.exr").string();
    write_image(driver, W, H, 1, OIIO::TypeDesc::FLOAT, f.data());
    const MomentBakeResult r = bake(driver, output);
    const double c = r.info.reference;
    const auto levels = read_levels(output);
    auto tex = MomentTexture::open(output);
    REQUIRE(tex);
    // Relative tolerance 1e-4 on sigma (plus 1e-7 absolute, 1e-5 of the range,
    // for near-constant footprints): float32 m1, m2 about c carry ~6e-8
    // relative error, so m2 - m1^2 loses at most a few ulps of m2.
    // Naive float moments of f itself (m2 ~ 1e6, ulp 0.0625) cannot resolve a
    // variance ~1e-5 at all.
    double worst_ours = 0, worst_lookup = 0, worst_naive = 0;
    for (std::size_t k = 1; k < levels.size(); ++k) {
        const Level& L = levels[k];
        for (int y = 0; y < L.h; ++y)
            for (int x = 0; x < L.w; ++x) {
                const double mean = box_mean(f, W, H, L.w, L.h, x, y, 0.0, 1);
                const double sigma_ref = std::sqrt(box_mean(f, W, H, L.w, L.h, x, y, mean, 2));
                const double tol = 1e-4 * sigma_ref + 1e-7;
                const float* m = &L.m[(std::size_t(y) * L.w + x) * 2];
                const double sigma = std::sqrt(std::max(0.0, double(m[1]) - double(m[0]) * m[0]));
                worst_ours = std::max(worst_ours, std::abs(sigma - sigma_ref) / tol);
                // The same footprint stored the naive way, each moment rounded to float.
                const float m1 = float(mean);
                const float m2 = float(box_mean(f, W, H, L.w, L.h, x, y, 0.0, 2));
                const double sigma_naive = std::sqrt(std::max(0.0, double(m2) - double(m1) * m1));
                worst_naive = std::max(worst_naive, std::abs(sigma_naive - sigma_ref) / tol);
                if (int(k) < tex->reachable_levels()) {
                    const MomentSample s = tex->lookup((x + 0.5f) / L.w, (y + 0.5f) / L.h, float(k));
                    worst_lookup = std::max(worst_lookup, std::abs(s.sigma - sigma_ref) / tol);
                    CHECK(s.mean == doctest::Approx(c + m[0]).epsilon(1e-9));
                }
            }
    }
    CHECK(worst_ours <= 1);
    CHECK(worst_lookup <= 1);
    CHECK(worst_naive > 100);  // the naive way misses by orders of magnitude
}

TEST_CASE("TextureSystem lookups at integer LOD and texel centres reproduce the level")
{
    for (const auto& wh : std::vector<std::pair<int, int>>{{32, 32}, {37, 23}, {64, 16}}) {
        const int W = wh.first, H = wh.second;
        CAPTURE(W);
        CAPTURE(H);
        const auto f = random_driver(W, H, 0.0, 1.0, 3 + W);
        const std::string size = std::to_string(W) + "x" + std::to_string(H);
        const std::string driver = (test_dir() / ("lookup-" + size + ".exr")).string();
        const std::string output = (test_dir() / ("lookup-moments-" + size + ".exr")).string();
        write_image(driver, W, H, 1, OIIO::TypeDesc::FLOAT, f.data());
        bake(driver, output);
        const auto levels = read_levels(output);
        auto tex = MomentTexture::open(output);
        REQUIRE(tex);
        // TextureSystem sizes filters by a level's smaller side, so it reaches
        // every level of a square texture, and for others the levels up to
        // the first whose smaller side is 1 texel.
        int reachable = 1;
        while (reachable < int(levels.size()) && std::min(levels[reachable - 1].w, levels[reachable - 1].h) > 1)
            ++reachable;
        CHECK(tex->reachable_levels() == reachable);
        if (W == H) CHECK(reachable == int(levels.size()));
        // Bilinear weights at a texel centre are (1, 0), up to the float
        // rounding of s = (x + 0.5) / w, which moves the sample by up to
        // 2^-24 w texels: on values in [0, 1], 2^-22 max(W, H) absolute.
        const double tol = 0x1.0p-22 * std::max(W, H);
        double worst = 0;
        for (int k = 0; k < reachable; ++k) {
            const Level& L = levels[k];
            for (int y = 0; y < L.h; ++y)
                for (int x = 0; x < L.w; ++x) {
                    const float* m = &L.m[(std::size_t(y) * L.w + x) * 2];
                    const MomentSample s = tex->lookup((x + 0.5f) / L.w, (y + 0.5f) / L.h, float(k));
                    REQUIRE(s.ok);
                    worst = std::max(worst, std::abs(s.mean - (tex->reference() + m[0])));
                    worst = std::max(worst, std::abs(s.variance - std::max(0.0, double(m[1]) - double(m[0]) * m[0])));
                }
        }
        CHECK(worst <= tol);
    }
}

TEST_CASE("MomentTexture refuses files that are not moment pyramids")
{
    const std::string plain = (test_dir() / "plain.exr").string();
    const std::vector<float> v(8, 0.5f);
    write_image(plain, 4, 2, 1, OIIO::TypeDesc::FLOAT, v.data());
    auto tex = MomentTexture::open(plain);
    REQUIRE_FALSE(tex);
    CHECK(tex.error().kind == ErrorKind::BadInput);
    CHECK(tex.error().message.find("plain.exr' is not a cmfilter moment pyramid") != std::string::npos);
    auto missing = MomentTexture::open((test_dir() / "no-such.exr").string());
    REQUIRE_FALSE(missing);
    CHECK(missing.error().kind == ErrorKind::Io);
}

TEST_CASE("a pyramid level with more tiles than the image cache can count is refused")
{
    // OpenImageIO's image cache counts a level's tiles in an int: a header
    // claiming 167772159 x 385875968 pixels in 64 x 64 tiles overflows it
    // (and made the cache abort, found by fuzz.moment_pyramid).
    OIIO::ImageSpec huge(167772159, 385875968, 2, OIIO::TypeDesc::FLOAT);
    huge.tile_width = huge.tile_height = 64;
    const std::int64_t tiles = ((huge.width + 63LL) / 64) * ((huge.height + 63LL) / 64);
    REQUIRE(tiles > std::int64_t(2147483647));
    const Status refused = check_texture_level(huge, 0, "huge.exr");
    REQUIRE_FALSE(refused);
    CHECK(refused.error().kind == ErrorKind::BadInput);
    CHECK(refused.error().message.find("level 0 of 'huge.exr' has " + std::to_string(tiles) + " tiles") !=
          std::string::npos);
    OIIO::ImageSpec untiled(64, 64, 2, OIIO::TypeDesc::FLOAT);
    CHECK_FALSE(check_texture_level(untiled, 0, "untiled.exr"));
    OIIO::ImageSpec empty(0, 64, 2, OIIO::TypeDesc::FLOAT);
    empty.tile_width = empty.tile_height = 64;
    CHECK_FALSE(check_texture_level(empty, 0, "empty.exr"));
    OIIO::ImageSpec fine(4096, 1, 2, OIIO::TypeDesc::FLOAT);
    fine.tile_width = fine.tile_height = 64;
    CHECK(check_texture_level(fine, 3, "fine.exr"));
}

TEST_CASE("--nan zero replaces and counts non-finite texels")
{
    const std::vector<float> v = {1.0f, NAN, 3.0f, INFINITY, 5.0f, 6.0f};
    const std::string driver = (test_dir() / "nan.exr").string();
    write_image(driver, 3, 2, 1, OIIO::TypeDesc::FLOAT, v.data());
    MomentBakeOptions options;
    options.driver_path = driver;
    options.output_path = (test_dir() / "nan-moments.exr").string();
    fs::remove(options.output_path);
    auto refused = bake_moment_pyramid(options);
    REQUIRE_FALSE(refused);
    CHECK(refused.error().kind == ErrorKind::BadInput);
    CHECK(refused.error().message.find("has 2 non-finite texels") != std::string::npos);
    CHECK_FALSE(fs::exists(options.output_path));
    options.nonfinite = NonFinitePolicy::Zero;
    auto r = bake_moment_pyramid(options);
    REQUIRE(r);
    CHECK(r->info.nonfinite_replaced == 2);
    CHECK(r->info.reference == doctest::Approx((1 + 3 + 5 + 6) / 6.0));
    auto tex = MomentTexture::open(options.output_path);
    REQUIRE(tex);
    CHECK(tex->info().nonfinite_replaced == 2);
}
