// SPDX-License-Identifier: Apache-2.0
// .ptm files (ptm_file.h): hand-made files decode to the values they were
// made from; the writer's files, parsed by the test's own reader, hold the
// fit within half a quantisation step; bad files are refused with messages
// that say what is wrong.
#include "cmfilter/stack/ptm_file.h"
#include "cmfilter/stack/relit_difference.h"

#include "ptm_test_files.h"
#include "quantised_fit_test_support.h"
#include "test_images.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>

using namespace cmfilter;
using namespace cmfilter_test;

namespace {

std::string scratch(const std::string& name) { return temp_dir("cmfilter_test_ptm_file") + "/" + name; }

LinearFit random_fit(LinearModel model, int width, int height, std::mt19937_64& rng)
{
    LinearFit fit = display_encoded_fit(model, width, height);
    std::uniform_real_distribution<double> coefficient(-0.6, 1.2), color(0.05, 2.5);
    for (std::size_t t = 0; t < fit.texels(); ++t)
        for (int i = 0; i < fit.stride(); ++i)
            fit.coefficients[t * fit.stride() + i] = static_cast<float>(
                model == LinearModel::PtmLrgb && i >= 6 ? color(rng) : coefficient(rng) * (1 + i % 6) / 3.0);
    return fit;
}

// A fit written by write_ptm: the quantisation it states, the file parsed
// here and the fit read_ptm reads back from it.
struct WrittenPtm {
    PtmQuantisation quantisation;
    ParsedPtm parsed;
    LinearFit back;
};

// `fit` written to `path`; the parsed file checked to hold the documented
// header for the fit's format and size, integral biases within 0 .. 255,
// positive scales, and 18 (RGB) or 9 (LRGB) bytes a texel.
WrittenPtm write_and_read_back(const LinearFit& fit, const std::string& path)
{
    PtmQuantisation q;
    REQUIRE(write_ptm(path, fit, &q));
    const ParsedPtm p = parse_ptm_by_hand(read_bytes(path));
    const bool rgb = fit.model == LinearModel::PtmRgb;
    CHECK(p.version == "PTM_1.2");
    CHECK(p.format == (rgb ? "PTM_FORMAT_RGB" : "PTM_FORMAT_LRGB"));
    CHECK(p.width == fit.width);
    CHECK(p.height == fit.height);
    CHECK(p.biases_integral);
    for (int k = 0; k < 6; ++k) {
        CHECK(p.scales[k] > 0);
        CHECK(p.biases[k] >= 0);
        CHECK(p.biases[k] <= 255);
    }
    REQUIRE(p.data.size() == fit.texels() * (rgb ? 18 : 9));
    auto back = read_ptm(path);
    REQUIRE_MESSAGE(back, (back ? "" : back.error().message));
    return {q, p, *back};
}

int rgb_byte(int c, int x, int y, int k) { return (17 * c + 5 * x + 60 * y + 3 * k + 1) % 256; }
int lum_byte(int x, int y, int k) { return (11 * x + 70 * y + 29 * k + 7) % 256; }
int color_byte(int x, int y, int c) { return (40 * x + 90 * y + 13 * c + 2) % 256; }

const double kScales[6] = {0.5, 1.25, 2, 0.25, 4, 1};
const int kBiases[6] = {10, 20, 30, 40, 50, 0};

}  // namespace

TEST_CASE("ptm: a hand-made PTM_FORMAT_RGB file decodes to (byte - bias) * scale / 255, rows bottom to top")
{
    const int w = 3, h = 2;
    struct Layout {
        const char* name;
        std::string size_separator, newline, biases;
    };
    for (const Layout& layout :
         {Layout{"one line each, LF", "\n", "\n", "10 20 30 40 50 0"},
          Layout{"width and height on one line, CRLF, trailing space", " ", "\r\n", "10 20 30 40 50 0 "}}) {
        CAPTURE(layout.name);
        const std::string path = scratch("hand_rgb.ptm");
        write_bytes(path, ptm_header_text("PTM_FORMAT_RGB", w, h, "0.5 1.25 2.0 0.25 4 1", layout.biases,
                                          layout.size_separator, layout.newline) +
                              ptm_rgb_bytes(w, h, rgb_byte));
        auto fit = read_ptm(path);
        REQUIRE_MESSAGE(fit, (fit ? "" : fit.error().message));
        CHECK(fit->model == LinearModel::PtmRgb);
        CHECK(fit->width == w);
        CHECK(fit->height == h);
        CHECK(fit->channels == 3);
        CHECK(fit->encoding == StackEncoding::DisplayEncoded);
        REQUIRE(fit->coefficients.size() == std::size_t(w * h * 18));
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                for (int c = 0; c < 3; ++c)
                    for (int k = 0; k < 6; ++k) {
                        const double expected = (rgb_byte(c, x, y, k) - kBiases[k]) * kScales[k] / 255.0;
                        CHECK(fit->coefficients[(y * w + x) * 18 + c * 6 + k] ==
                              doctest::Approx(expected).epsilon(1e-6));
                    }
    }
}

TEST_CASE("ptm: a hand-made PTM_FORMAT_LRGB file decodes to its polynomial (codes / 255) and colour bytes / 255")
{
    const int w = 4, h = 3;
    const std::string path = scratch("hand_lrgb.ptm");
    write_bytes(path, ptm_header_text("PTM_FORMAT_LRGB", w, h, "0.5 1.25 2 0.25 4 1", "10 20 30 40 50 0") +
                          ptm_lrgb_bytes(w, h, lum_byte, color_byte) + "trailing bytes are ignored");
    auto fit = read_ptm(path);
    REQUIRE_MESSAGE(fit, (fit ? "" : fit.error().message));
    CHECK(fit->model == LinearModel::PtmLrgb);
    REQUIRE(fit->stride() == 9);
    REQUIRE(fit->coefficients.size() == std::size_t(w * h * 9));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float* t = fit->coefficients.data() + (y * w + x) * 9;
            for (int k = 0; k < 6; ++k)
                CHECK(t[k] == doctest::Approx((lum_byte(x, y, k) - kBiases[k]) * kScales[k] / 255.0).epsilon(1e-6));
            for (int c = 0; c < 3; ++c) CHECK(t[6 + c] == doctest::Approx(color_byte(x, y, c) / 255.0).epsilon(1e-6));
        }
    // A viewer shows L / 255 * C codes (L the polynomial in codes, C the
    // colour byte); relighting the fit gives that / 255.
    const Vec3 l = normalize(Vec3{0.3, -0.4, 0.8});
    double lum_codes = 0;
    for (int k = 0; k < 6; ++k)
        lum_codes += (lum_byte(1, 2, k) - kBiases[k]) * kScales[k] * evaluate_basis(fit->model, l)[k];
    CHECK(relit_value(*fit, 2 * w + 1, 0, l) ==
          doctest::Approx(lum_codes / 255.0 * color_byte(1, 2, 0) / 255.0).epsilon(1e-5));
}

TEST_CASE("ptm: PTM_FORMAT_RGB written and read back is within half a quantisation step of the fit")
{
    std::mt19937_64 rng(17);
    const LinearFit fit = random_fit(LinearModel::PtmRgb, 7, 5, rng);
    const auto [q, p, back] = write_and_read_back(fit, scratch("round_trip_rgb.ptm"));
    // Three planes, rows bottom to top: each coefficient within scale / 2 (codes).
    std::size_t i = 0;
    for (int c = 0; c < 3; ++c)
        for (int y = 4; y >= 0; --y)
            for (int x = 0; x < 7; ++x)
                for (int k = 0; k < 6; ++k, ++i) {
                    const double codes = (static_cast<unsigned char>(p.data[i]) - p.biases[k]) * p.scales[k];
                    const double original = 255.0 * fit.coefficients[(y * 7 + x) * 18 + c * 6 + k];
                    CHECK(std::abs(codes - original) <= p.scales[k] / 2 * (1 + 1e-6) + 1e-4);
                }

    std::vector<double> max_error(6, 0.0);
    for (std::size_t t = 0; t < fit.texels(); ++t)
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 6; ++k) {
                const std::size_t j = t * 18 + c * 6 + k;
                max_error[k] = std::max(max_error[k], std::abs(double(back.coefficients[j]) - fit.coefficients[j]));
            }
    // Each term's scale is close to the smallest that covers its range (the
    // range widened to hold 0, in codes): 256 byte values hold at most 255
    // steps, and the best bias wastes less than one more.
    for (int k = 0; k < 6; ++k) {
        double lo = 0, hi = 0;
        for (std::size_t t = 0; t < fit.texels(); ++t)
            for (int c = 0; c < 3; ++c) {
                const double v = 255.0 * fit.coefficients[t * 18 + c * 6 + k];
                lo = std::min(lo, v);
                hi = std::max(hi, v);
            }
        CHECK(p.scales[k] >= (hi - lo) / 256.0);
        CHECK(p.scales[k] <= (hi - lo) / 254.0 * (1 + 1e-6));
    }
    double bound = 0;
    for (int k = 0; k < 6; ++k) {
        CHECK(max_error[k] <= p.scales[k] / 510.0 * (1 + 1e-5));
        CHECK(q.max_coefficient_error[k] == doctest::Approx(max_error[k]).epsilon(1e-6));
        CHECK(q.scales[k] == doctest::Approx(p.scales[k]).epsilon(1e-7));
        CHECK(q.biases[k] == p.biases[k]);
        bound += max_error[k];  // every PTM basis term is at most 1 in magnitude on the hemisphere
    }
    // Relit values: within sum_k e_k |B_k(l)| at any light; the stated error
    // at least the error at the pole (the first direction) and at most the bound.
    check_relit_within_term_errors(back, fit, max_error, random_hemisphere_directions(rng, 40));
    CHECK(q.max_value_error >= max_relit_difference_at_pole(back, fit) - 1e-7);
    CHECK(q.max_value_error <= bound + 1e-6);
    CHECK(q.max_value_error > 0);
}

TEST_CASE("ptm: PTM_FORMAT_LRGB moves the base colour's largest channel into the polynomial, relit values kept")
{
    std::mt19937_64 rng(29);
    const LinearFit fit = random_fit(LinearModel::PtmLrgb, 6, 4, rng);
    const auto [q, p, back] = write_and_read_back(fit, scratch("round_trip_lrgb.ptm"));

    // Expected, per texel: m the largest channel, colour c / m, polynomial P m.
    const int w = 6, h = 4;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float* v = fit.coefficients.data() + (y * w + x) * 9;
            const double m = std::max({v[6], v[7], v[8]});
            const std::size_t r = static_cast<std::size_t>(h - 1 - y);  // file row
            for (int k = 0; k < 6; ++k) {
                const unsigned char b = static_cast<unsigned char>(p.data[(r * w + x) * 6 + k]);
                const double codes = (b - p.biases[k]) * p.scales[k];
                CHECK(std::abs(codes - 255.0 * v[k] * m) <= p.scales[k] / 2 * (1 + 1e-6) + 1e-4);
            }
            int largest = 0;
            for (int c = 0; c < 3; ++c) {
                const unsigned char b = static_cast<unsigned char>(p.data[6 * w * h + (r * w + x) * 3 + c]);
                CHECK(std::abs(b / 255.0 - v[6 + c] / m) <= 0.5 / 255 + 1e-9);
                if (v[6 + c] == m) largest = c;
            }
            CHECK(static_cast<unsigned char>(p.data[6 * w * h + (r * w + x) * 3 + largest]) == 255);
        }

    double e[6] = {};
    for (std::size_t t = 0; t < fit.texels(); ++t) {
        const float* v = fit.coefficients.data() + t * 9;
        const double m = std::max({v[6], v[7], v[8]});
        for (int k = 0; k < 6; ++k) e[k] = std::max(e[k], std::abs(back.coefficients[t * 9 + k] - v[k] * m));
    }
    for (int k = 0; k < 6; ++k) {
        CHECK(e[k] <= p.scales[k] / 510.0 * (1 + 1e-5));
        CHECK(q.max_coefficient_error[k] == doctest::Approx(e[k]).epsilon(1e-5));
    }
    CHECK(q.max_color_error <= 0.5 / 255 + 1e-9);
    // Relit P' c' - P c = dP(l) c' + P'(l) dc + dP(l) dc, with c' <= 1, |dc| <= 1/510.
    for (const Vec3& l : random_hemisphere_directions(rng, 40)) {
        const auto b = evaluate_basis(LinearModel::PtmLrgb, l);
        double dp = 0;
        for (int k = 0; k < 6; ++k) dp += e[k] * std::abs(b[k]);
        for (std::size_t t = 0; t < fit.texels(); ++t) {
            const float* v = fit.coefficients.data() + t * 9;
            const double m = std::max({v[6], v[7], v[8]});
            double pl = 0;
            for (int k = 0; k < 6; ++k) pl += v[k] * m * b[k];
            const double bound = dp * (1 + 0.5 / 255) + std::abs(pl) * 0.5 / 255 + 1e-6;
            for (int c = 0; c < 3; ++c)
                CHECK(std::abs(relit_value(back, t, c, l) - relit_value(fit, t, c, l)) <= bound);
        }
    }
    CHECK(q.max_value_error > 0);
    CHECK(q.max_value_error < 0.05);
}

TEST_CASE("ptm: truncated files are refused with the bytes expected and found")
{
    const std::string header = ptm_header_text("PTM_FORMAT_RGB", 3, 2, "0.5 1.25 2 0.25 4 1", "10 20 30 40 50 0");
    const std::string data = ptm_rgb_bytes(3, 2, rgb_byte);  // 3 * 2 * 18 = 108 bytes
    const std::string path = scratch("truncated.ptm");

    write_bytes(path, header + data.substr(0, 100));
    auto fit = read_ptm(path);
    REQUIRE_FALSE(fit);
    CHECK(fit.error().kind == ErrorKind::BadInput);
    CHECK(fit.error().message.find(path) != std::string::npos);
    CHECK(fit.error().message.find("expected 108 bytes of coefficients") != std::string::npos);
    CHECK(fit.error().message.find("found 100") != std::string::npos);

    const std::string lrgb = ptm_header_text("PTM_FORMAT_LRGB", 3, 2, "0.5 1.25 2 0.25 4 1", "10 20 30 40 50 0");
    write_bytes(path, lrgb + ptm_lrgb_bytes(3, 2, lum_byte, color_byte).substr(0, 50));
    fit = read_ptm(path);
    REQUIRE_FALSE(fit);
    CHECK(fit.error().message.find("expected 54 bytes of coefficients") != std::string::npos);
    CHECK(fit.error().message.find("found 50") != std::string::npos);

    write_bytes(path, "PTM_1.2\nPTM_FORMAT_RGB\n3\n2\n0.5 1.25 2");
    fit = read_ptm(path);
    REQUIRE_FALSE(fit);
    CHECK(fit.error().message.find("ends before its scale 3") != std::string::npos);
}

TEST_CASE("ptm: bad header lines are refused naming the line and what was expected")
{
    const std::string path = scratch("bad_header.ptm");
    const std::string data = ptm_rgb_bytes(3, 2, rgb_byte);
    const std::string good_scales = "0.5 1.25 2 0.25 4 1", good_biases = "10 20 30 40 50 0";
    const std::vector<RefusedFile> cases = {
        {"P6\n3 2\n255\n" + data, "is not a PTM 1.2 file: its first line is 'P6', expected PTM_1.2"},
        {"PTM_1.1\nPTM_FORMAT_RGB\n" + data, "is PTM version 'PTM_1.1'; cmfilter reads PTM_1.2"},
        {ptm_header_text("PTM_FORMAT_XYZ", 3, 2, good_scales, good_biases) + data,
         "unknown format line 'PTM_FORMAT_XYZ' (expected PTM_FORMAT_RGB or PTM_FORMAT_LRGB)"},
        {"PTM_1.2\nPTM_FORMAT_RGB\nabc\n2\n" + good_scales + "\n" + good_biases + "\n" + data,
         "has width 'abc', expected an integer in 1 .. 65536"},
        {ptm_header_text("PTM_FORMAT_RGB", 0, 2, good_scales, good_biases) + data, "has width '0'"},
        {ptm_header_text("PTM_FORMAT_RGB", 3, 100000, good_scales, good_biases) + data, "has height '100000'"},
        {ptm_header_text("PTM_FORMAT_RGB", 3, 2, "0.5 1.25 x 0.25 4 1", good_biases) + data,
         "has scale 2 'x', expected a finite number"},
        {ptm_header_text("PTM_FORMAT_RGB", 3, 2, "0.5 1.25 2 nan 4 1", good_biases) + data, "has scale 3 'nan'"},
        {ptm_header_text("PTM_FORMAT_RGB", 3, 2, good_scales, "10 20 30.5 40 50 0") + data,
         "has bias 2 '30.5', expected an integer"},
        {ptm_header_text("PTM_FORMAT_RGB", 3, 2, good_scales, "10 20 30 40 50 0 7") + data, "more than six biases"},
    };
    check_files_refused(read_ptm, path, cases, scratch("no_such_file.ptm"));
}

TEST_CASE("ptm: JPEG-compressed and other formats are refused as not supported")
{
    const std::string path = scratch("jpeg.ptm");
    for (const char* format :
         {"PTM_FORMAT_JPEG_RGB", "PTM_FORMAT_JPEG_LRGB", "PTM_FORMAT_JPEGLS_LRGB", "PTM_FORMAT_LUM"}) {
        CAPTURE(format);
        write_bytes(path, ptm_header_text(format, 3, 2, "0.5 1.25 2 0.25 4 1", "10 20 30 40 50 0") +
                              std::string(200, '\x7f'));
        auto fit = read_ptm(path);
        REQUIRE_FALSE(fit);
        CHECK(fit.error().kind == ErrorKind::BadInput);
        CHECK(fit.error().message.find(std::string("is in format ") + format +
                                       ", which cmfilter does not support; it reads PTM_FORMAT_RGB and "
                                       "PTM_FORMAT_LRGB") != std::string::npos);
    }
}

TEST_CASE("ptm: write_ptm refuses other models, channel counts, encodings and non-finite values, leaving no file")
{
    std::mt19937_64 rng(3);
    // In a braced list the fits are made, and rng drawn, in order.
    const std::vector<RefusedFit> cases = {
        {random_fit(LinearModel::Hsh2, 2, 2, rng), "the fit's model is hsh2; a .ptm holds ptm-rgb or ptm-lrgb"},
        {with_channels(random_fit(LinearModel::PtmRgb, 2, 2, rng), 1),
         "the fit has 1 channel(s); a .ptm holds 3 (RGB)"},
        {as_scene_linear(random_fit(LinearModel::PtmLrgb, 2, 2, rng)),
         "the fit is of scene-linear values; a .ptm holds display-encoded ones"},
        {with_coefficient(random_fit(LinearModel::PtmRgb, 2, 2, rng), 3 * 18 + 4, std::nanf("")),
         "texel (1, 1) has a non-finite coefficient"},
    };
    check_fits_refused([](const std::string& path, const LinearFit& fit) { return write_ptm(path, fit); },
                       scratch("refused.ptm"), ".ptm", cases);
}

TEST_CASE("relit difference: one coefficient changed by d differs by d times its basis function's largest value")
{
    std::mt19937_64 rng(5);
    // PTM a5 (the constant term): exactly d everywhere.
    LinearFit a = random_fit(LinearModel::PtmRgb, 3, 3, rng), b = a;
    b.coefficients[4 * 18 + 2 * 6 + 5] += 0.125f;
    const double d_ptm = double(b.coefficients[4 * 18 + 2 * 6 + 5]) - a.coefficients[4 * 18 + 2 * 6 + 5];
    CHECK(max_relit_difference(a, b, hemisphere_directions(), 1) == doctest::Approx(d_ptm).epsilon(1e-9));
    // HSH term 6, sqrt(5 / 2 pi) (1 - 6 c + 6 c^2), largest at the pole (c = 1):
    // sqrt(5 / 2 pi), the pole being the first direction.
    LinearFit h = random_fit(LinearModel::Hsh3, 2, 3, rng), g = h;
    g.coefficients[5 * 27 + 9 + 6] -= 0.25f;
    const double d_hsh = double(h.coefficients[5 * 27 + 9 + 6]) - g.coefficients[5 * 27 + 9 + 6];
    const double pi = 3.14159265358979323846;
    CHECK(max_relit_difference(h, g, hemisphere_directions(64), 2) ==
          doctest::Approx(d_hsh * std::sqrt(5 / (2 * pi))).epsilon(1e-9));
    // The directions: unit, upper hemisphere, the pole first.
    const auto dirs = hemisphere_directions(100);
    REQUIRE(dirs.size() == 101);
    CHECK(dirs[0].z == 1.0);
    for (const Vec3& l : dirs) {
        CHECK(length(l) == doctest::Approx(1.0).epsilon(1e-12));
        CHECK(l.z > 0);
    }
}
