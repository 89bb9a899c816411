// SPDX-License-Identifier: Apache-2.0
// Histogram pyramids (sec. 4.1, exact solutions) against independent
// computations: every level of the written file, read back with OpenImageIO's
// ImageInput, against the fractions of the footprint at each value counted by
// brute force (tests/support/box_reference.h); lookups through
// HistogramTexture at texel centres; and the refusals.
#include "cmfilter/texture/histogram_pyramid.h"
#include "cmfilter/texture/moment_pyramid.h"

#include "box_reference.h"
#include "test_images.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

using namespace cmfilter;
using namespace cmfilter_test;

namespace {

const std::string kDir = temp_dir("cmfilter-test-histogram-pyramid");

std::vector<float> few_values(int W, int H, const std::vector<float>& values)
{
    std::vector<float> f(static_cast<std::size_t>(W) * H);
    for (std::size_t i = 0; i < f.size(); ++i) f[i] = values[(i * 5 + i / W + i * i % 7) % values.size()];
    return f;
}

HistogramPyramidInfo bake(const std::string& name, const std::vector<float>& f, int W, int H)
{
    const std::string driver = kDir + "/" + name + "-driver.exr";
    write_image(driver, W, H, 1, OIIO::TypeDesc::FLOAT, f.data());
    HistogramBakeOptions options;
    options.driver_path = driver;
    options.output_path = kDir + "/" + name + "-histograms.exr";
    auto r = bake_histogram_pyramid(options);
    if (!r) FAIL(r.error().message);
    return *r;
}

}  // namespace

TEST_CASE("histogram pyramid levels hold the fraction of each footprint at each value, any size")
{
    // Twelve values: more than ten bins, so that bin order must survive
    // OpenEXR's sorting of channels by name.
    const std::vector<float> values = {-0.5f, 0.25f, 0.3f, 7.0f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f, 8.0f, 9.0f};
    for (const auto& wh : std::vector<std::pair<int, int>>{{16, 16}, {5, 3}, {23, 9}, {1, 6}}) {
        const int W = wh.first, H = wh.second;
        CAPTURE(W);
        CAPTURE(H);
        const auto f = few_values(W, H, values);
        const std::string name = "levels-" + std::to_string(W) + "x" + std::to_string(H);
        const HistogramPyramidInfo info = bake(name, f, W, H);
        // The distinct values actually present, ascending.
        std::vector<float> present = f;
        std::sort(present.begin(), present.end());
        present.erase(std::unique(present.begin(), present.end()), present.end());
        REQUIRE(info.values.size() == present.size());
        for (std::size_t b = 0; b < present.size(); ++b) CHECK(info.values[b] == present[b]);

        auto in = OIIO::ImageInput::open(kDir + "/" + name + "-histograms.exr");
        REQUIRE(in);
        const int B = static_cast<int>(present.size());
        int levels = 0;
        for (int k = 0; in->seek_subimage(0, k); ++k, ++levels) {
            const OIIO::ImageSpec& spec = in->spec();
            REQUIRE(spec.nchannels == B);
            REQUIRE(spec.width == std::max(1, W >> k));
            REQUIRE(spec.height == std::max(1, H >> k));
            std::vector<float> h(std::size_t(spec.width) * spec.height * B);
            REQUIRE(in->read_image(0, k, 0, B, OIIO::TypeDesc::FLOAT, h.data()));
            double worst = 0, worst_sum = 0;
            for (int y = 0; y < spec.height; ++y)
                for (int x = 0; x < spec.width; ++x) {
                    std::vector<double> want(B, 0.0);
                    for (const auto& w : box_weights(W, H, spec.width, spec.height, x, y)) {
                        const float v = f[std::size_t(w.j) * W + w.i];
                        want[std::lower_bound(present.begin(), present.end(), v) - present.begin()] += w.weight;
                    }
                    double sum = 0;
                    for (int b = 0; b < B; ++b) {
                        const double got = h[(std::size_t(y) * spec.width + x) * B + b];
                        worst = std::max(worst, std::abs(got - want[b]));
                        sum += got;
                    }
                    worst_sum = std::max(worst_sum, std::abs(sum - 1.0));
                }
            CAPTURE(k);
            // Fractions in [0, 1] stored as float32: 2^-24 plus double sums.
            CHECK(worst <= 1e-7);
            CHECK(worst_sum <= 1e-6);
        }
        CHECK(levels == info.levels);
    }
}

TEST_CASE("histogram lookups at integer LOD and texel centres reproduce the level")
{
    const int W = 16, H = 16;
    const auto f = few_values(W, H, {0.0f, 0.5f, 1.0f});
    const HistogramPyramidInfo info = bake("lookup", f, W, H);
    auto tex = HistogramTexture::open(kDir + "/lookup-histograms.exr");
    REQUIRE(tex);
    REQUIRE(tex->bins() == 3);
    for (int k = 0; k < info.levels; ++k) {
        const int w = std::max(1, W >> k), h = std::max(1, H >> k);
        double worst = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                float got[3];
                REQUIRE(tex->lookup((x + 0.5f) / w, (y + 0.5f) / h, static_cast<float>(k), got));
                std::vector<double> want(3, 0.0);
                for (const auto& b : box_weights(W, H, w, h, x, y))
                    want[static_cast<int>(std::lround(2 * f[std::size_t(b.j) * W + b.i]))] += b.weight;
                for (int b = 0; b < 3; ++b) worst = std::max(worst, std::abs(got[b] - want[b]));
            }
        CAPTURE(k);
        // Float32 texels and the bilinear weights at texel centres (exact up to rounding).
        CHECK(worst <= 1e-6);
    }
}

TEST_CASE("more than 256 distinct values are refused and nothing is written")
{
    const int W = 20, H = 13;  // 260 distinct values
    std::vector<float> f(W * H);
    for (int i = 0; i < W * H; ++i) f[i] = static_cast<float>(i);
    const std::string driver = kDir + "/many-driver.exr";
    write_image(driver, W, H, 1, OIIO::TypeDesc::FLOAT, f.data());
    HistogramBakeOptions options;
    options.driver_path = driver;
    options.output_path = kDir + "/many-histograms.exr";
    std::filesystem::remove(options.output_path);
    auto r = bake_histogram_pyramid(options);
    REQUIRE_FALSE(r);
    CHECK(r.error().kind == ErrorKind::BadInput);
    CHECK(r.error().message.find("260 distinct values") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(options.output_path));
}

TEST_CASE("HistogramTexture refuses a moment pyramid")
{
    const int W = 8, H = 8;
    const auto f = few_values(W, H, {0.0f, 1.0f});
    const std::string driver = kDir + "/refuse-driver.exr";
    write_image(driver, W, H, 1, OIIO::TypeDesc::FLOAT, f.data());
    MomentBakeOptions options;
    options.driver_path = driver;
    options.output_path = kDir + "/refuse-moments.exr";
    REQUIRE(bake_moment_pyramid(options));
    auto tex = HistogramTexture::open(options.output_path);
    REQUIRE_FALSE(tex);
    CHECK(tex.error().kind == ErrorKind::BadInput);
    CHECK(tex.error().message.find("not a cmfilter histogram pyramid") != std::string::npos);
}
