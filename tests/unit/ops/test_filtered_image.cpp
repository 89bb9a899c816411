// SPDX-License-Identifier: Apache-2.0
// apply_filter (filtered_image.h) against independent computations: the
// reference method against brute-force box means of C0(f) for a driver whose
// size is not a power of two; gaussian against the quadrature T(mean, sigma)
// of tests/support/reference_convolution.h where (mean, sigma) fall on table
// nodes (so bilinear interpolation adds nothing); gaussian at sigma = 0 and
// naive against C0 itself; and the PNG writer against the sRGB formula.
#include "cmfilter/colormap/color_map_loading.h"
#include "cmfilter/ops/filtered_image.h"
#include "cmfilter/ops/filtered_image_file.h"
#include "cmfilter/tables/gaussian_color_table_file.h"
#include "cmfilter/ops/table_color_pyramid.h"
#include "cmfilter/texture/histogram_pyramid.h"
#include "cmfilter/texture/moment_pyramid.h"

#include "apply_inputs.h"
#include "box_reference.h"
#include "reference_convolution.h"
#include "test_images.h"
#include "unit_test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace cmfilter;
using namespace cmfilter_test;

namespace {

const std::string kDir = temp_dir("cmfilter-test-filtered-image");

FilteredImage apply(ApplyOptions options, FilterMethod method, double lod)
{
    options.method = method;
    options.lod = lod;
    auto r = apply_filter(options, builtin_color_config());
    if (!r) FAIL(r.error().message);
    return *r;
}

// Largest |got - want| over the pixels, want given per pixel.
template <typename Want>
double worst_error(const FilteredImage& img, Want want)
{
    double worst = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const Rgb3 c = want(x, y);
            for (int ch = 0; ch < 3; ++ch)
                worst = std::max(worst, std::abs(img.rgb[(std::size_t(y) * img.width + x) * 3 + ch] - c[ch]));
        }
    return worst;
}

}  // namespace

TEST_CASE("apply reference equals brute-force box means of C0(f), 13 x 7 driver")
{
    const int W = 13, H = 7;
    std::vector<float> f(W * H);
    for (int i = 0; i < W * H; ++i) f[i] = static_cast<float>(0.5 + 0.6 * std::sin(1.3 * i + 0.2 * (i % 5)));
    const ApplyOptions options = apply_inputs(kDir, "box", f, W, H, {});
    const ReferenceMap m = reference_map();
    // Levels 13x7, 6x3, 3x1 are reachable (the smaller side reaches 1 at level 2).
    for (int k = 0; k <= 2; ++k) {
        CAPTURE(k);
        const FilteredImage img = apply(options, FilterMethod::Reference, k);
        REQUIRE(img.width == std::max(1, W >> k));
        REQUIRE(img.height == std::max(1, H >> k));
        // Values up to 2.5 stored as float32 (2^-24 relative, 1.5e-7) after
        // double sums; 1e-6 absolute leaves room for the level's own float
        // storage and the bilinear weights at texel centres (1 ulp off 0 or 1).
        CHECK(worst_error(img, [&](int x, int y) { return box_mean_color(m, f, W, H, img.width, img.height, x, y); }) <=
              1e-6);
    }
}

TEST_CASE("apply color-pyramid equals brute-force box means of C0(f), and the reference between levels")
{
    // 13 x 7 (not a power of two), values beyond the map's domain on both
    // sides (clamped by C0), baked through the table's map.
    const int W = 13, H = 7;
    std::vector<float> f(W * H);
    for (int i = 0; i < W * H; ++i) f[i] = static_cast<float>(0.5 + 0.7 * std::sin(0.9 * i + 0.3 * (i % 4)));
    ApplyOptions options = apply_inputs(kDir, "pyramid", f, W, H, {});
    TableColorPyramidOptions bake;
    bake.bake.driver_path = kDir + "/pyramid-driver.exr";
    bake.bake.output_path = kDir + "/pyramid-colors.exr";
    bake.table_path = options.table_path;
    auto baked = bake_table_color_pyramid(bake, builtin_color_config());
    REQUIRE(baked);
    ApplyOptions colors = options;
    colors.moments_path = bake.bake.output_path;
    const ReferenceMap m = reference_map();
    for (int k = 0; k <= 2; ++k) {
        CAPTURE(k);
        const FilteredImage img = apply(colors, FilterMethod::ColorPyramid, k);
        REQUIRE(img.width == std::max(1, W >> k));
        REQUIRE(img.height == std::max(1, H >> k));
        CHECK(worst_error(img, [&](int x, int y) { return box_mean_color(m, f, W, H, img.width, img.height, x, y); }) <=
              1e-6);
    }
    for (double lod : {0.5, 1.25}) {
        CAPTURE(lod);
        const FilteredImage got = apply(colors, FilterMethod::ColorPyramid, lod);
        const FilteredImage reference = apply(options, FilterMethod::Reference, lod);
        REQUIRE(got.rgb.size() == reference.rgb.size());
        double worst = 0;
        for (std::size_t i = 0; i < got.rgb.size(); ++i)
            worst = std::max(worst, double(std::abs(got.rgb[i] - reference.rgb[i])));
        CHECK(worst <= 1e-6);
    }

    // Through another table's map (one colour changed): refused, naming
    // the pyramid; a moment pyramid read as a colour pyramid: refused.
    std::vector<float> other = kMap;
    other[4] = 0.7f;
    ApplyOptions changed = apply_inputs(kDir, "pyramid-other", f, W, H, {}, 2, 0, other);
    changed.moments_path = colors.moments_path;
    changed.method = FilterMethod::ColorPyramid;
    auto refused = apply_filter(changed, builtin_color_config());
    REQUIRE_FALSE(refused);
    CHECK(refused.error().message.find("'" + colors.moments_path + "' was baked through another colour map") !=
          std::string::npos);
    ApplyOptions moments = options;
    moments.method = FilterMethod::ColorPyramid;
    auto wrong_kind = apply_filter(moments, builtin_color_config());
    REQUIRE_FALSE(wrong_kind);
    CHECK(wrong_kind.error().message.find("is a moment pyramid") != std::string::npos);
}

TEST_CASE("apply exact equals brute-force box means of C0(f) for a driver with few values")
{
    // Three distinct values, 11 x 6 (not a power of two), including one
    // outside the map's domain (clamped by C0): the histogram pyramid's inner
    // product with the map must give the box mean of C0(f) at every level
    // and, at a fractional lod, the same linear blend as the reference.
    const int W = 11, H = 6;
    const float values[3] = {0.125f, 0.7f, 1.25f};
    std::vector<float> f(W * H);
    for (int i = 0; i < W * H; ++i) f[i] = values[(i * 7 + i / W) % 3];
    ApplyOptions options = apply_inputs(kDir, "exact", f, W, H, {});
    HistogramBakeOptions bake;
    bake.driver_path = kDir + "/exact-driver.exr";
    bake.output_path = options.histograms_path = kDir + "/exact-histograms.exr";
    auto baked = bake_histogram_pyramid(bake);
    REQUIRE(baked);
    REQUIRE(baked->values.size() == 3);
    const ReferenceMap m = reference_map();
    for (int k = 0; k <= 2; ++k) {
        CAPTURE(k);
        const FilteredImage img = apply(options, FilterMethod::Exact, k);
        // Fractions stored as float32 (2^-24 relative) times colours up to
        // 2.5, summed over 3 values: below 1e-6.
        CHECK(worst_error(img, [&](int x, int y) { return box_mean_color(m, f, W, H, img.width, img.height, x, y); }) <=
              1e-6);
    }
    const FilteredImage exact = apply(options, FilterMethod::Exact, 0.5);
    const FilteredImage reference = apply(options, FilterMethod::Reference, 0.5);
    REQUIRE(exact.rgb.size() == reference.rgb.size());
    double worst = 0;
    for (std::size_t i = 0; i < exact.rgb.size(); ++i)
        worst = std::max(worst, double(std::abs(exact.rgb[i] - reference.rgb[i])));
    CHECK(worst <= 1e-6);
}

TEST_CASE("apply gaussian is T(mean, sigma) of eq. 10 and naive is C0(mean), on table nodes")
{
    // A 16 x 16 driver of values k / 8: in the left half each 2 x 2 block holds
    // two values a, b twice each, in the right half each 4 x 4 block is
    // constant. At lod 1 the left texels have mean (a + b) / 2 and sigma
    // |a - b| / 2, at lod 2 the right texels have sigma = 0: every mean and
    // sigma is a multiple of 1/16, exact in float32 (sigma <= 4/16).
    const int W = 16, H = 16;
    std::vector<float> f(W * H);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const int bx = x / 2, by = y / 2;
            const int a = (bx * 3 + by) % 9, b = (bx + by * 5) % 9;
            const int c = ((x / 4) * 5 + (y / 4) * 2) % 9;
            f[y * W + x] = x < 8 ? ((x + y) % 2 ? a : std::min(8, a + std::abs(a - b) % 5)) / 8.0f : c / 8.0f;
        }
    // Value nodes every 0.0125 over [-0.75, 1.75] and sigma nodes every
    // 0.0125 up to 0.25: multiples of 1/16 (and sigma <= 0.25) are nodes, so
    // bilinear lookups return node values, each T(v_i, sigma_j) stored as float32.
    GaussianColorTableOptions table;
    table.values = 201;
    table.sigmas = 21;
    table.sigma_max = 0.25;
    table.margin = 0.75;
    table.spacing = SigmaSpacing::Linear;
    const ApplyOptions options = apply_inputs(kDir, "nodes", f, W, H, table);
    const ReferenceMap m = reference_map();

    // Brute-force mean and sigma of a level-k texel (power of two: plain blocks).
    const auto moments = [&](int k, int x, int y) {
        const int n = 1 << k;
        double s1 = 0, s2 = 0;
        for (int j = y * n; j < (y + 1) * n; ++j)
            for (int i = x * n; i < (x + 1) * n; ++i) {
                s1 += f[j * W + i];
                s2 += double(f[j * W + i]) * f[j * W + i];
            }
        const double mean = s1 / (n * n);
        return std::pair<double, double>(mean, std::sqrt(std::max(0.0, s2 / (n * n) - mean * mean)));
    };
    {
        const int k = 1;  // every texel: two values twice (left) or constant (right)
        const FilteredImage gaussian = apply(options, FilterMethod::Gaussian, k);
        const FilteredImage naive = apply(options, FilterMethod::Naive, k);
        // Tolerance: the node's float32 storage (2^-24 relative of values up
        // to 2.5: 1.5e-7) plus the quadrature's error (< 1e-12); 1e-6 also
        // covers the output's own float32 rounding.
        const double g = worst_error(gaussian, [&](int x, int y) {
            const auto [mean, sigma] = moments(k, x, y);
            return reference_convolution(m, mean, sigma);  // sigma = 0: C0(mean) itself
        });
        CHECK(g <= 1e-6);
        CHECK(gaussian.table_counters.sigma_clamped == 0);
        // naive: C0 of the brute-force mean (float32 output: 1e-6 as above).
        CHECK(worst_error(naive, [&](int x, int y) { return reference_map_value(m, moments(k, x, y).first); }) <= 1e-6);
    }
    // At lod 2 the right half is constant per texel (the left half's means
    // and sigmas are no longer on nodes): gaussian = naive = reference = C0(v).
    const FilteredImage gaussian = apply(options, FilterMethod::Gaussian, 2);
    const FilteredImage reference = apply(options, FilterMethod::Reference, 2);
    for (int y = 0; y < 4; ++y)
        for (int x = 2; x < 4; ++x) {
            const Rgb3 c0 = reference_map_value(m, f[(4 * y) * W + 4 * x]);
            for (int ch = 0; ch < 3; ++ch) {
                const std::size_t i = (std::size_t(y) * 4 + x) * 3 + ch;
                // float32 of the same double value on every path: 2^-24 relative.
                CHECK(std::abs(gaussian.rgb[i] - c0[ch]) <= 1e-6);
                CHECK(std::abs(reference.rgb[i] - c0[ch]) <= 1e-6);
            }
        }
}

TEST_CASE("apply mixture gives a two-valued driver's box means, where gaussian cannot")
{
    // Values 0.25 and 0.75 in an irregular pattern, 16 x 16: every texel of
    // levels 1-3 holds one of them or both in some proportion p, and its
    // mixture is p C0(0.25) + (1 - p) C0(0.75) (moment_mixture.h: a two-point
    // footprint is its own mixture). Both values and the map's kinks are
    // value nodes of the table (every 0.0125), so the lookups at width s = 0
    // are C0 itself; the width left by float32 moments, s = sqrt(t var) for
    // t within about 1e-6 of 1, is at most a few 1e-4, a fiftieth of the
    // first sigma row: 5e-3 bounds what it blends in.
    const int W = 16, H = 16;
    std::vector<float> f(W * H);
    for (int i = 0; i < W * H; ++i) f[i] = ((i * 37 + i / 5) % 7) < 3 ? 0.25f : 0.75f;
    GaussianColorTableOptions table;
    table.values = 201;
    table.sigmas = 21;
    table.sigma_max = 0.25;
    table.margin = 0.75;
    table.spacing = SigmaSpacing::Linear;
    const ApplyOptions options = apply_inputs(kDir, "mixture", f, W, H, table, 4);
    const ReferenceMap m = reference_map();
    for (int k = 1; k <= 3; ++k) {
        CAPTURE(k);
        const FilteredImage mixture = apply(options, FilterMethod::Mixture, k);
        const FilteredImage gaussian = apply(options, FilterMethod::Gaussian, k);
        const auto box = [&](int x, int y) { return box_mean_color(m, f, W, H, mixture.width, mixture.height, x, y); };
        CHECK(worst_error(mixture, box) <= 5e-3);
        CHECK(worst_error(gaussian, box) >= 0.05);  // the Gaussian of the same two moments misses by far more
        for (float v : mixture.rgb) CHECK(std::isfinite(v));
    }
}

TEST_CASE("apply mixture stays finite and no worse than gaussian on constant and smooth drivers")
{
    const int W = 32, H = 32;
    const GaussianColorTableOptions table;
    // Constant: every footprint has variance 0; the mixture is the Gaussian.
    const ApplyOptions constant =
        apply_inputs(kDir, "mixture-constant", std::vector<float>(W * H, 0.4f), W, H, table, 4);
    for (double lod : {0.0, 2.5, 5.0}) {
        const FilteredImage mixture = apply(constant, FilterMethod::Mixture, lod);
        const FilteredImage gaussian = apply(constant, FilterMethod::Gaussian, lod);
        REQUIRE(mixture.rgb.size() == gaussian.rgb.size());
        for (std::size_t i = 0; i < mixture.rgb.size(); ++i) CHECK(mixture.rgb[i] == gaussian.rgb[i]);
    }
    // Smooth, skewed: the mixture's mean absolute error against the box
    // reference is at most the Gaussian's at every level.
    std::vector<float> f(W * H);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const double u = 0.5 + 0.45 * std::sin(0.7 * x + 0.2 * y) * std::cos(0.31 * y);
            f[y * W + x] = static_cast<float>(u * u);
        }
    // The same driver offset to [1000, 1001] (the map laid over that domain):
    // the moments about c keep the shape, so the same bound holds.
    std::vector<float> offset(f);
    for (float& v : offset) v += 1000.0f;
    const ApplyOptions smooth = apply_inputs(kDir, "mixture-smooth", f, W, H, table, 4);
    const ApplyOptions far = apply_inputs(kDir, "mixture-offset", offset, W, H, table, 4, 1000.0);
    for (const ApplyOptions* options : {&smooth, &far})
        for (int k = 1; k <= 5; ++k) {
            CAPTURE(k);
            CAPTURE(options->moments_path);
            const FilteredImage reference = apply(*options, FilterMethod::Reference, k);
            double mixture_error = 0, gaussian_error = 0;
            const FilteredImage mixture = apply(*options, FilterMethod::Mixture, k);
            const FilteredImage gaussian = apply(*options, FilterMethod::Gaussian, k);
            for (std::size_t i = 0; i < reference.rgb.size(); ++i) {
                REQUIRE(std::isfinite(mixture.rgb[i]));
                mixture_error += std::abs(mixture.rgb[i] - reference.rgb[i]);
                gaussian_error += std::abs(gaussian.rgb[i] - reference.rgb[i]);
            }
            CHECK(mixture_error <= gaussian_error * 1.001 + 1e-6);
        }
}

TEST_CASE("apply mixture stays finite and no worse than gaussian where sigma reaches 10 sigma_max")
{
    // Uniform-looking values over [0, 1] (sigma of a coarse footprint about
    // 0.29) through a table whose sigma axis ends at 0.029: from level 2 on,
    // footprints are up to 10 sigma_max wide and both methods clamp sigma
    // (LookupCounters::sigma_clamped); the mixture's components are no wider
    // than the footprint, so it never clamps more than the Gaussian.
    const int W = 32, H = 32;
    std::vector<float> f(W * H);
    for (int i = 0; i < W * H; ++i) f[i] = static_cast<float>((i * 0.6180339887) - std::floor(i * 0.6180339887));
    GaussianColorTableOptions table;
    table.sigma_max = 0.029;
    const ApplyOptions options = apply_inputs(kDir, "mixture-wide", f, W, H, table, 4);
    bool clamped = false;
    for (int k = 1; k <= 5; ++k) {
        CAPTURE(k);
        const FilteredImage reference = apply(options, FilterMethod::Reference, k);
        const FilteredImage mixture = apply(options, FilterMethod::Mixture, k);
        const FilteredImage gaussian = apply(options, FilterMethod::Gaussian, k);
        clamped |= gaussian.table_counters.sigma_clamped > 0;
        double mixture_error = 0, gaussian_error = 0;
        for (std::size_t i = 0; i < reference.rgb.size(); ++i) {
            REQUIRE(std::isfinite(mixture.rgb[i]));
            mixture_error += std::abs(mixture.rgb[i] - reference.rgb[i]);
            gaussian_error += std::abs(gaussian.rgb[i] - reference.rgb[i]);
        }
        MESSAGE("level " << k << ": mixture " << mixture_error << ", gaussian " << gaussian_error);
        CHECK(mixture_error <= gaussian_error * 1.001 + 1e-6);
    }
    CHECK(clamped);  // the sweep reached beyond the table
}

TEST_CASE("apply mixture refuses a pyramid of two moments, naming it")
{
    const std::vector<float> f(8 * 8, 0.5f);
    ApplyOptions options = apply_inputs(kDir, "mixture-order-2", f, 8, 8, {});
    options.method = FilterMethod::Mixture;
    auto r = apply_filter(options, builtin_color_config());
    REQUIRE(!r);
    CHECK(r.error().kind == ErrorKind::BadInput);
    CHECK(r.error().field == "ApplyOptions::moments_path");
    CHECK(r.error().message.find("holds 2 moments") != std::string::npos);
}

TEST_CASE("apply clamps the level of detail and reports it")
{
    std::vector<float> f(8 * 8, 0.5f);
    const ApplyOptions options = apply_inputs(kDir, "clamp", f, 8, 8, {});
    const FilteredImage above = apply(options, FilterMethod::Gaussian, 7.25);
    CHECK(above.lod_clamped);
    CHECK(above.lod == 3);
    CHECK(above.width == 1);
    const FilteredImage below = apply(options, FilterMethod::Gaussian, -0.5);
    CHECK(below.lod == 0);
    CHECK(below.width == 8);
    CHECK(below.warnings.size() == 1);
    const FilteredImage inside = apply(options, FilterMethod::Gaussian, 1.5);
    CHECK_FALSE(inside.lod_clamped);
    CHECK(inside.warnings.empty());
}

TEST_CASE("apply PNG output is the EXR output encoded to sRGB, clipped, 8-bit")
{
    FilteredImage img;
    img.width = 64;
    img.height = 1;
    img.linear_space = "Linear Rec.709";
    for (int i = 0; i < 64; ++i)  // -0.1 .. 1.2 (clipped at both ends), and a NaN
        for (int ch = 0; ch < 3; ++ch)
            img.rgb.push_back(i == 63 ? NAN : static_cast<float>(-0.1 + 1.3 * std::pow(i / 62.0, 2.0 + ch)));
    const ColorConfig config = builtin_color_config();
    const std::string png = kDir + "/encoded.png";
    REQUIRE(write_filtered_image(png, img, config));
    auto in = OIIO::ImageInput::open(png);
    REQUIRE(in);
    std::vector<unsigned char> codes(64 * 3);
    REQUIRE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, codes.data()));
    for (int i = 0; i < 64 * 3; ++i) {
        CAPTURE(i);
        const double v = std::isnan(img.rgb[i]) ? 0.0 : std::clamp<double>(img.rgb[i], 0.0, 1.0);
        // The code's quantisation interval, decoded with the IEC sRGB formula,
        // must hold the clipped value; 1e-6 allows for OpenColorIO's
        // C1-continuous sRGB toe (< 7.6e-7 from the formula) and float32.
        const double lo = srgb_to_linear(std::max(0.0, codes[i] - 0.5) / 255.0);
        const double hi = srgb_to_linear(std::min(255.0, codes[i] + 0.5) / 255.0);
        CHECK(v >= lo - 1e-6);
        CHECK(v <= hi + 1e-6);
    }
}
