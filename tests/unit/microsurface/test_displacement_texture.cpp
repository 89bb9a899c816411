// SPDX-License-Identifier: Apache-2.0
// DisplacementTexture against independent computations: its texel slopes and
// pyramid against `maketx --bumpslopes --filter box` read back with
// OpenImageIO, and against a Sobel gradient written out here; its footprint
// statistics against brute-force averages of height() and slope() over the
// parallelogram on a dense grid, from sub-texel footprints to several
// repeats, and the far limit against the texels' own moments; its
// heightfield's traced hits and slopes against height() and slope(); and the
// inputs it refuses.
#include "cmfilter/microsurface/displacement_texture.h"

#include "test_images.h"

#include <OpenImageIO/imageio.h>
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace cmfilter;
using cmfilter_test::temp_dir;
using cmfilter_test::write_image;

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string scratch(const std::string& name) { return temp_dir("cmfilter-test-displacement") + "/" + name; }

// Uniform texels in [0, 1) from a 64-bit LCG.
std::vector<float> random_texels(int n, std::uint64_t seed)
{
    std::vector<float> v(static_cast<std::size_t>(n) * n);
    for (float& x : v) {
        seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
        x = static_cast<float>((seed >> 11) * 0x1.0p-53);
    }
    return v;
}

// A smooth periodic relief sampled at the texel centres: three cosines.
std::vector<float> smooth_texels(int n)
{
    std::vector<float> v(static_cast<std::size_t>(n) * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double x = (i + 0.5) / n, y = (j + 0.5) / n;
            v[static_cast<std::size_t>(j) * n + i] = static_cast<float>(0.6 * std::cos(2 * kPi * (x + 2 * y) + 0.3) +
                                                                        0.3 * std::cos(2 * kPi * 3 * x - 1.1) +
                                                                        0.2 * std::sin(2 * kPi * (2 * x - 3 * y)));
        }
    return v;
}

DisplacementTexture make(std::vector<float> texels, int n, double scale, int probes = 8)
{
    DisplacementOptions o;
    o.path = "memory";
    o.height_scale = scale;
    o.max_probes = probes;
    auto t = DisplacementTexture::from_texels(std::move(texels), n, n, o);
    REQUIRE(t);
    return std::move(t.value());
}

// The Sobel gradient of texels f (value * scale) at (i, j), neighbours
// wrapping, per texture unit: maketx --bumpslopes's operator, written out.
void sobel(const std::vector<float>& f, int n, double scale, int i, int j, double& gx, double& gy)
{
    const auto at = [&](int x, int y) { return scale * f[static_cast<std::size_t>((y + n) % n) * n + (x + n) % n]; };
    static const int kx[3][3] = {{-1, 0, 1}, {-2, 0, 2}, {-1, 0, 1}};  // [row][column]
    gx = gy = 0;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            gx += kx[r][c] * at(i + c - 1, j + r - 1);
            gy += kx[c][r] * at(i + c - 1, j + r - 1);
        }
    gx *= n / 8.0;
    gy *= n / 8.0;
}

struct TxLevel {
    int w = 0, h = 0, channels = 0;
    std::vector<float> pixels;
};

std::vector<TxLevel> read_mip_levels(const std::string& path)
{
    auto in = OIIO::ImageInput::open(path);
    REQUIRE(in);
    std::vector<TxLevel> levels;
    for (int k = 0; in->seek_subimage(0, k); ++k) {
        const OIIO::ImageSpec& spec = in->spec();
        TxLevel L{spec.width, spec.height, spec.nchannels, {}};
        L.pixels.resize(static_cast<std::size_t>(L.w) * L.h * L.channels);
        REQUIRE(in->read_image(0, k, 0, L.channels, OIIO::TypeDesc::FLOAT, L.pixels.data()));
        levels.push_back(std::move(L));
    }
    return levels;
}

bool have_maketx()
{
    if (std::string(CMFILTER_MAKETX).empty()) MESSAGE("maketx not found; skipped");
    return !std::string(CMFILTER_MAKETX).empty();
}

// Runs maketx --bumpslopes (slopes per texture unit) on an n x n float image.
std::vector<TxLevel> maketx_bumpslopes(const std::vector<float>& texels, int n, const std::string& name)
{
    const std::string input = scratch(name + ".exr"), output = scratch(name + ".tx");
    write_image(input, n, n, 1, OIIO::TypeDesc::FLOAT, texels.data());
    const std::string command = "'" + std::string(CMFILTER_MAKETX) +
                                "' --bumpslopes --uvslopes_scale 1 --wrap periodic --filter box -d float '" + input +
                                "' -o '" + output + "' > /dev/null 2>&1";
    REQUIRE(std::system(command.c_str()) == 0);
    return read_mip_levels(output);
}

// Moments over the parallelogram c + a e1 + b e2, a, b in [-1/2, 1/2], by
// the midpoint rule on a g x g grid of height() and slope().
struct Brute {
    double h = 0, hh = 0, sx = 0, sy = 0, xx = 0, xy = 0, yy = 0;
};

Brute brute_force(const DisplacementTexture& t, double u, double v, double e1u, double e1v, double e2u, double e2v,
                  int g)
{
    Brute b;
    for (int p = 0; p < g; ++p)
        for (int q = 0; q < g; ++q) {
            const double a = (p + 0.5) / g - 0.5, c = (q + 0.5) / g - 0.5;
            const double x = u + a * e1u + c * e2u, y = v + a * e1v + c * e2v;
            const double h = t.height(x, y);
            double sx, sy;
            t.slope(x, y, sx, sy);
            b.h += h, b.hh += h * h, b.sx += sx, b.sy += sy, b.xx += sx * sx, b.xy += sx * sy, b.yy += sy * sy;
        }
    const double count = double(g) * g;
    b.h /= count, b.hh /= count, b.sx /= count, b.sy /= count, b.xx /= count, b.xy /= count, b.yy /= count;
    b.hh -= b.h * b.h, b.xx -= b.sx * b.sx, b.xy -= b.sx * b.sy, b.yy -= b.sy * b.sy;
    return b;
}

}  // namespace

TEST_CASE("displacement texel slopes are the Sobel gradient per texture unit, neighbours wrapping")
{
    const int n = 16;
    const double scale = 0.25;
    const auto f = random_texels(n, 17);
    const DisplacementTexture t = make(f, n, scale);
    double worst = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            double gx, gy;
            sobel(f, n, scale, i, j, gx, gy);
            const auto [sx, sy] = t.texel_slope(i, j);
            worst = std::max({worst, std::abs(sx - gx), std::abs(sy - gy)});
            // The surface passes through the texel centres, its slopes too.
            const double u = (i + 0.5) / n, v = (j + 0.5) / n;
            CHECK(t.height(u, v) == doctest::Approx(scale * f[std::size_t(j) * n + i]).epsilon(1e-12));
            double px, py;
            t.slope(u + 3, v - 2, px, py);  // whole repeats away
            CHECK(px == doctest::Approx(gx).epsilon(1e-9));
            CHECK(py == doctest::Approx(gy).epsilon(1e-9));
        }
    CHECK(worst <= 1e-12 * n * 8);
    // Halfway between two texel centres along u: the mean of the two.
    const double u = 3.0 / n, v = 5.5 / n;
    CHECK(t.height(u, v) == doctest::Approx(scale * 0.5 * (double(f[5 * n + 2]) + f[5 * n + 3])).epsilon(1e-12));
}

TEST_CASE("displacement slopes and pyramid match maketx --bumpslopes on a mirror-symmetric image")
{
    if (!have_maketx()) return;
    // maketx clamps the Sobel's neighbours at the edges whatever --wrap says;
    // an image whose first and last rows and columns mirror each other
    // (texel i equal to texel n - 1 - i) has the same slopes either way.
    const int n = 16;
    const auto r = random_texels(n, 5);
    std::vector<float> f(std::size_t(n) * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            f[std::size_t(j) * n + i] = r[std::size_t(std::min(j, n - 1 - j)) * n + std::min(i, n - 1 - i)];
    const double scale = 0.5;
    const DisplacementTexture t = make(f, n, scale);
    const auto levels = maketx_bumpslopes(f, n, "mirror");
    REQUIRE(static_cast<int>(levels.size()) == t.levels());
    // maketx's channels: h, dh/ds, dh/dt, their squares, their product.
    const double unit[6] = {scale, scale, scale, scale * scale, scale * scale, scale * scale};
    for (int k = 0; k < t.levels(); ++k) {
        CAPTURE(k);
        const TxLevel& L = levels[k];
        REQUIRE(L.channels == 6);
        REQUIRE(L.w == t.level_size(k));
        double worst = 0;
        for (int y = 0; y < L.h; ++y)
            for (int x = 0; x < L.w; ++x) {
                const auto ours = t.pyramid_texel(k, x, y);
                for (int c = 0; c < 6; ++c) {
                    const double theirs = unit[c] * L.pixels[(std::size_t(y) * L.w + x) * 6 + c];
                    // float rounding of values up to ~ (n / 2)^2 scale^2
                    worst = std::max(worst, std::abs(ours[c] - theirs) / (1 + std::abs(theirs)));
                }
            }
        CHECK(worst <= 1e-5);
    }
}

TEST_CASE("displacement slopes match maketx --bumpslopes away from the edges of any image")
{
    if (!have_maketx()) return;
    const int n = 16;
    const auto f = random_texels(n, 23);
    const DisplacementTexture t = make(f, n, 1.0);
    const auto levels = maketx_bumpslopes(f, n, "random");
    REQUIRE(!levels.empty());
    const TxLevel& L = levels[0];
    REQUIRE(L.channels == 6);
    double worst = 0;
    for (int y = 1; y < n - 1; ++y)
        for (int x = 1; x < n - 1; ++x) {
            const auto [sx, sy] = t.texel_slope(x, y);
            const float* p = &L.pixels[(std::size_t(y) * n + x) * 6];
            worst = std::max(
                {worst, std::abs(sx - p[1]), std::abs(sy - p[2]), std::abs(sx * sy - p[5]) / (1 + std::abs(p[5]))});
        }
    CHECK(worst <= 1e-5);
}

TEST_CASE("displacement pyramid carries the box means of h squared")
{
    const int n = 8;
    const auto f = random_texels(n, 41);
    const double scale = 3.0;
    const DisplacementTexture t = make(f, n, scale);
    for (int k = 1; k < t.levels(); ++k) {
        const int m = t.level_size(k), block = n / m;
        for (int y = 0; y < m; ++y)
            for (int x = 0; x < m; ++x) {
                double h = 0, hh = 0;
                for (int j = y * block; j < (y + 1) * block; ++j)
                    for (int i = x * block; i < (x + 1) * block; ++i) {
                        const double v = scale * f[std::size_t(j) * n + i];
                        h += v, hh += v * v;
                    }
                h /= block * block, hh /= block * block;
                const auto p = t.pyramid_texel(k, x, y);
                CHECK(p[kHeight] == doctest::Approx(h).epsilon(1e-6));
                CHECK(p[kHeightSquared] == doctest::Approx(hh).epsilon(1e-6));
            }
    }
}

TEST_CASE("displacement footprint of a point is the point's height and slope with no spread")
{
    const int n = 32;
    const DisplacementTexture t = make(smooth_texels(n), n, 0.05);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> uni(-2.0, 3.0);
    for (int trial = 0; trial < 50; ++trial) {
        const double u = uni(rng), v = uni(rng);
        const DisplacementFootprint fp = t.footprint(u, v, 0, 0, 0, 0);
        double sx, sy;
        t.slope(u, v, sx, sy);
        CHECK(fp.mean_height == doctest::Approx(t.height(u, v)).epsilon(1e-6));
        CHECK(fp.slope_x == doctest::Approx(sx).epsilon(1e-9));
        CHECK(fp.slope_y == doctest::Approx(sy).epsilon(1e-9));
        CHECK(fp.slope_xx == 0);
        CHECK(fp.slope_yy == 0);
        CHECK(fp.slope_xy == 0);
        CHECK(fp.sigma_h <= 1e-6);
        CHECK(std::isfinite(fp.lod));
    }
}

TEST_CASE("displacement footprint moments against brute force from sub-texel to several repeats")
{
    const int n = 32;
    const double scale = 0.05;
    const DisplacementTexture t = make(smooth_texels(n), n, scale);
    // The whole texture's spread, the scale errors are measured on.
    const Brute all = brute_force(t, 0.5, 0.5, 1, 0, 0, 1, 256);
    const double slope_var = all.xx + all.yy, height_var = all.hh;
    REQUIRE(slope_var > 0.01);
    // Tolerances: on the means, a share of the whole texture's deviation;
    // on the variances and covariances, of its variance. Below a texel the
    // fields are linear over the footprint; beyond, each probe reads a box
    // with the piece's second moments along u and v, not the parallelogram
    // itself, whose shape the content at the footprint's own scale sees.
    struct Case {
        double texels;  // |e1| in texels
        double aspect;  // |e2| / |e1|
        double angle;   // of e1
        double mean_tol, cov_tol;
        double rel_tol = 0;  // under a texel: of the footprint's own spread
    };
    const Case cases[] = {
        {0.05, 1, 0.3, 1e-3, 1e-3, 0.02}, {0.3, 0.5, 1.0, 2e-3, 1e-3, 0.02}, {1.0, 1, 0.2, 0.05, 0.015},
        {3.0, 1, 0.7, 0.06, 0.1},         {8.0, 0.125, 0.4, 0.03, 0.05},     {10.0, 1, 2.1, 0.1, 0.12},
        {32.0, 1, 0.1, 0.06, 0.04},       {100.0, 0.7, 0.9, 0.08, 0.02},     {400.0, 0.05, 1.3, 0.02, 0.006},
    };
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    for (const Case& c : cases) {
        for (int trial = 0; trial < 3; ++trial) {
            const double u = uni(rng), v = uni(rng);
            const double l1 = c.texels / n, l2 = l1 * c.aspect;
            const double e1u = l1 * std::cos(c.angle), e1v = l1 * std::sin(c.angle);
            const double e2u = -l2 * std::sin(c.angle + 0.2), e2v = l2 * std::cos(c.angle + 0.2);
            const int g = std::clamp(static_cast<int>(6 * c.texels), 16, 600);
            const Brute b = brute_force(t, u, v, e1u, e1v, e2u, e2v, g);
            const DisplacementFootprint fp = t.footprint(u, v, e1u, e1v, e2u, e2v);
            CAPTURE(c.texels);
            CAPTURE(c.aspect);
            const double slope_dev = std::sqrt(slope_var), height_dev = std::sqrt(height_var);
            CHECK(std::abs(fp.slope_x - b.sx) <= c.mean_tol * slope_dev);
            CHECK(std::abs(fp.slope_y - b.sy) <= c.mean_tol * slope_dev);
            CHECK(std::abs(fp.mean_height - b.h) <= c.mean_tol * height_dev);
            CHECK(std::abs(fp.slope_xx - b.xx) <= c.cov_tol * slope_var);
            CHECK(std::abs(fp.slope_xy - b.xy) <= c.cov_tol * slope_var);
            CHECK(std::abs(fp.slope_yy - b.yy) <= c.cov_tol * slope_var);
            CHECK(std::abs(fp.sigma_h * fp.sigma_h - b.hh) <= c.cov_tol * height_var);
            if (c.texels < 1) {
                // Under a texel the spread itself, not only its share of the
                // whole (the 16 x 16 midpoint grid's own variance is 1/256 low).
                CHECK(fp.slope_xx == doctest::Approx(b.xx).epsilon(c.rel_tol));
                CHECK(fp.slope_yy == doctest::Approx(b.yy).epsilon(c.rel_tol));
                CHECK(std::abs(fp.slope_xy - b.xy) <= c.rel_tol * std::sqrt(b.xx * b.yy));
                CHECK(fp.sigma_h * fp.sigma_h == doctest::Approx(b.hh).epsilon(c.rel_tol));
            }
        }
    }
}

TEST_CASE("displacement footprint far away is the whole surface's moments")
{
    const int n = 16;
    const auto f = random_texels(n, 29);
    const double scale = 0.02;
    const DisplacementTexture t = make(f, n, scale);
    // The bilinear surface's mean is the texels' mean; its slopes average to
    // 0 over a repeat (a periodic Sobel sums to 0); its spreads by the
    // midpoint rule, 64 x 64 points a texel.
    double texel_mean = 0;
    for (const float x : f) texel_mean += scale * x;
    texel_mean /= f.size();
    const Brute all = brute_force(t, 0.5, 0.5, 1, 0, 0, 1, 64 * n);
    CHECK(all.h == doctest::Approx(texel_mean).epsilon(1e-9));
    for (const double repeats : {64.0, 1e6}) {
        CAPTURE(repeats);
        // A box of a whole number of repeats but for a strip under 1 / repeats of it.
        const double strip = 1 / repeats;
        const DisplacementFootprint fp = t.footprint(0.3, 0.7, repeats, 0.1 * repeats, -0.2 * repeats, repeats);
        CHECK(std::abs(fp.mean_height - texel_mean) <= strip * std::sqrt(all.hh) + 1e-12);
        CHECK(std::abs(fp.slope_x) <= strip * std::sqrt(all.xx) + 1e-12);
        CHECK(std::abs(fp.slope_y) <= strip * std::sqrt(all.yy) + 1e-12);
        const double tol = 1e-3 + 2 * strip;
        CHECK(fp.slope_xx == doctest::Approx(all.xx).epsilon(tol));
        CHECK(std::abs(fp.slope_xy - all.xy) <= tol * all.xx);
        CHECK(fp.slope_yy == doctest::Approx(all.yy).epsilon(tol));
        CHECK(fp.sigma_h * fp.sigma_h == doctest::Approx(all.hh).epsilon(tol));
    }
    // Infinite edges: the whole repeat, finite.
    const double inf = std::numeric_limits<double>::infinity();
    const DisplacementFootprint fp = t.footprint(0.1, 0.2, inf, 0, 0, inf);
    CHECK(fp.mean_height == doctest::Approx(texel_mean).epsilon(1e-9));
    CHECK(fp.slope_xx == doctest::Approx(all.xx).epsilon(1e-3));
    CHECK(fp.slope_yy == doctest::Approx(all.yy).epsilon(1e-3));
    CHECK(std::isfinite(fp.lod));
    // The texels' own moments (maketx's top level) are not the surface's:
    // interpolation between texel centres smooths a random relief.
    const auto top = t.pyramid_texel(t.levels() - 1, 0, 0);
    CHECK(top[kSlopeXX] > 1.05 * all.xx);
}

TEST_CASE("displacement heightfield: traced hits lie on height(u, v), slopes are slope(u, v)")
{
    const int n = 32;
    const auto f = smooth_texels(n);
    const DisplacementTexture t = make(f, n, 0.04);
    auto field = t.heightfield(2);
    REQUIRE(field);
    CHECK(field->resolution() == n);
    CHECK(field->tile() == 1.0);
    for (int j = 0; j < n; j += 5)
        for (int i = 0; i < n; i += 3) CHECK(field->node_height(i, j) == t.texel_height(i, j));
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> uni(-1.5, 2.5), dir(-1.0, 1.0);
    int hits = 0;
    for (int trial = 0; trial < 200; ++trial) {
        const double x = uni(rng), y = uni(rng);
        const auto [u, v] = t.texture_uv(x, y);
        double sx, sy, fx = 0, fy = 0;
        t.slope(u, v, sx, sy);
        REQUIRE(field->slope(x, y, fx, fy));
        CHECK(fx == doctest::Approx(sx).epsilon(1e-9).scale(1));
        CHECK(fy == doctest::Approx(sy).epsilon(1e-9).scale(1));
        CHECK(field->height(x, y) == doctest::Approx(t.height(u, v)).epsilon(1e-12).scale(1));
        const Vec3 origin{x, y, 0.5};
        const Vec3 direction{dir(rng), dir(rng), -0.3 - 0.7 * (dir(rng) + 1) / 2};
        const auto hit = field->trace(origin, direction);
        if (!hit) continue;
        ++hits;
        const auto [hu, hv] = t.texture_uv(hit->point.x, hit->point.y);
        CHECK(hit->height == doctest::Approx(t.height(hu, hv)).epsilon(1e-9).scale(1));
    }
    CHECK(hits > 150);
    // The mapping and its inverse.
    const auto [x, y] = t.heightfield_xy(0.25, 0.75);
    CHECK(x == doctest::Approx(0.25 - 0.5 / n));
    CHECK(y == doctest::Approx(0.75 - 0.5 / n));
}

TEST_CASE("Heightfield::from_nodes refuses grids it cannot trace")
{
    CHECK(Heightfield::from_nodes(std::vector<double>(9, 0.0), 3, 1.0).error().kind == ErrorKind::BadInput);
    CHECK(Heightfield::from_nodes(std::vector<double>(15, 0.0), 4, 1.0).error().kind == ErrorKind::BadInput);
    CHECK(Heightfield::from_nodes(std::vector<double>(16, 0.0), 4, 0.0).error().kind == ErrorKind::BadInput);
    CHECK(Heightfield::from_nodes(std::vector<double>(16, 0.0), 4, 1.0, std::vector<double>(16, 0.0)).error().kind ==
          ErrorKind::BadInput);
    std::vector<double> nan(16, 0.0);
    nan[5] = std::nan("");
    const auto bad = Heightfield::from_nodes(nan, 4, 1.0);
    REQUIRE(!bad);
    CHECK(bad.error().message.find("(1, 1)") != std::string::npos);
    const auto flat = Heightfield::from_nodes(std::vector<double>(16, 0.25), 4, 2.0);
    REQUIRE(flat);
    const auto hit = flat->trace({0.3, 0.7, 1.0}, {0.1, 0.2, -1.0});
    REQUIRE(hit);
    CHECK(hit->height == doctest::Approx(0.25));
    CHECK(hit->t == doctest::Approx(0.75));
}

TEST_CASE("displacement refuses missing files, non-square, multi-channel and non-finite images, bad scales")
{
    DisplacementOptions o;
    o.path = scratch("missing.exr");
    auto missing = DisplacementTexture::load(o);
    REQUIRE(!missing);
    CHECK(missing.error().kind == ErrorKind::Io);
    CHECK(missing.error().message.find("missing.exr") != std::string::npos);

    const std::vector<float> wide(16 * 8, 0.5f);
    o.path = scratch("wide.exr");
    write_image(o.path, 16, 8, 1, OIIO::TypeDesc::FLOAT, wide.data());
    auto nonsquare = DisplacementTexture::load(o);
    REQUIRE(!nonsquare);
    CHECK(nonsquare.error().kind == ErrorKind::BadInput);
    CHECK(nonsquare.error().message.find("wide.exr") != std::string::npos);
    CHECK(nonsquare.error().message.find("16 x 8") != std::string::npos);

    const std::vector<float> rgb(8 * 8 * 3, 0.5f);
    o.path = scratch("rgb.exr");
    write_image(o.path, 8, 8, 3, OIIO::TypeDesc::FLOAT, rgb.data());
    auto multi = DisplacementTexture::load(o);
    REQUIRE(!multi);
    CHECK(multi.error().kind == ErrorKind::BadInput);
    CHECK(multi.error().message.find("rgb.exr") != std::string::npos);
    o.channel = "1";
    CHECK(DisplacementTexture::load(o));  // one channel chosen
    o.channel.clear();

    std::vector<float> nan(8 * 8, 0.5f);
    nan[8 * 3 + 2] = std::numeric_limits<float>::quiet_NaN();
    o.path = scratch("nan.exr");
    write_image(o.path, 8, 8, 1, OIIO::TypeDesc::FLOAT, nan.data());
    auto bad = DisplacementTexture::load(o);
    REQUIRE(!bad);
    CHECK(bad.error().kind == ErrorKind::BadInput);
    CHECK(bad.error().message.find("nan.exr") != std::string::npos);
    CHECK(bad.error().message.find("expected finite") != std::string::npos);
    auto in_memory = DisplacementTexture::from_texels(nan, 8, 8, o);
    REQUIRE(!in_memory);
    CHECK(in_memory.error().message.find("(2, 3)") != std::string::npos);

    o.path = scratch("wide.exr");
    write_image(o.path, 8, 8, 1, OIIO::TypeDesc::FLOAT, wide.data());
    for (const double scale : {-1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
        o.height_scale = scale;
        auto refused = DisplacementTexture::load(o);
        REQUIRE(!refused);
        CHECK(refused.error().kind == ErrorKind::BadInput);
        CHECK(refused.error().message.find("height_scale") != std::string::npos);
    }
    o.height_scale = 1;
    o.max_probes = 0;
    CHECK(!DisplacementTexture::load(o));
    o.max_probes = 8;
    auto odd = DisplacementTexture::from_texels(std::vector<float>(36, 0.0f), 6, 6, o);
    REQUIRE(odd);
    CHECK(odd->heightfield(1).error().kind == ErrorKind::BadInput);
}

TEST_CASE("the bundled snake-scales displacement loads, tiles, and spans slopes of 0 to about 60 degrees")
{
    DisplacementOptions o;
    o.path = std::string(CMFILTER_SOURCE_DIR) + "/examples/scenes/snake-scales.exr";
    auto t = DisplacementTexture::load(o);
    REQUIRE(t);
    const int n = t->size();
    CHECK(n == 256);
    double flattest = 90, steepest = 0, step_inside = 0, step_across = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const auto [sx, sy] = t->texel_slope(i, j);
            const double angle = std::atan(std::hypot(sx, sy)) * 180 / kPi;
            flattest = std::min(flattest, angle);
            steepest = std::max(steepest, angle);
            // Height steps between neighbours: across the wrap no larger than inside.
            const double step = std::max(std::abs(t->texel_height(i + 1, j) - t->texel_height(i, j)),
                                         std::abs(t->texel_height(i, j + 1) - t->texel_height(i, j)));
            double& worst = i == n - 1 || j == n - 1 ? step_across : step_inside;
            worst = std::max(worst, step);
        }
    CHECK(flattest < 2);
    CHECK(steepest > 55);
    CHECK(steepest < 65);
    CHECK(step_across <= step_inside);
}
