// SPDX-License-Identifier: Apache-2.0
// HSH .rti files (rti_file.h): hand-made files decode to the values they
// were made from; the writer's files, parsed here, hold the fit within half
// a quantisation step; bad files are refused with messages that say what
// is wrong.
#include "cmfilter/stack/rti_file.h"

#include "ptm_test_files.h"
#include "test_images.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <random>

using namespace cmfilter;
using namespace cmfilter_test;

namespace {

std::string scratch(const std::string& name) { return temp_dir("cmfilter_test_rti_file") + "/" + name; }

LinearFit random_hsh_fit(LinearModel model, int width, int height, std::mt19937_64& rng)
{
    LinearFit fit;
    fit.model = model;
    fit.width = width;
    fit.height = height;
    fit.channels = 3;
    fit.encoding = StackEncoding::DisplayEncoded;
    fit.coefficients.resize(fit.texels() * fit.stride());
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (std::size_t i = 0; i < fit.coefficients.size(); ++i)
        fit.coefficients[i] = static_cast<float>(u(rng) * (i % fit.terms() == 0 ? 2.0 : 0.4 / (1 + i % fit.terms())));
    return fit;
}

double relit(const LinearFit& fit, std::size_t t, int c, const Vec3& l)
{
    const auto b = evaluate_basis(fit.model, l);
    double s = 0;
    for (int k = 0; k < fit.terms(); ++k) s += fit.coefficients[t * fit.stride() + c * fit.terms() + k] * b[k];
    return s;
}

int hsh_byte(int x, int y, int c, int k) { return (9 * x + 80 * y + 31 * c + 7 * k + 3) % 256; }

}  // namespace

TEST_CASE("rti: a hand-made HSH .rti decodes to byte / 255 * scale + bias, rows top to bottom, bands then terms")
{
    const int w = 3, h = 2;
    for (int terms : {4, 9}) {
        for (const std::string newline : {"\n", "\r\n"}) {
            CAPTURE(terms);
            std::vector<float> scales, biases;
            for (int k = 0; k < terms; ++k) {
                scales.push_back(0.25f * (k + 1));
                biases.push_back(-0.5f + 0.125f * k);
            }
            const std::string path = scratch("hand.rti");
            write_bytes(path, hsh_rti_bytes(w, h, terms, scales, biases, hsh_byte,
                                            {"#a comment line", "#another, as RTIBuilder writes"}, newline) +
                                  "trailing bytes are ignored");
            auto fit = read_rti(path);
            REQUIRE_MESSAGE(fit, (fit ? "" : fit.error().message));
            CHECK(fit->model == (terms == 4 ? LinearModel::Hsh2 : LinearModel::Hsh3));
            CHECK(fit->width == w);
            CHECK(fit->height == h);
            CHECK(fit->channels == 3);
            CHECK(fit->encoding == StackEncoding::DisplayEncoded);
            REQUIRE(fit->coefficients.size() == std::size_t(w * h * 3 * terms));
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x)
                    for (int c = 0; c < 3; ++c)
                        for (int k = 0; k < terms; ++k) {
                            const double expected = hsh_byte(x, y, c, k) / 255.0 * scales[k] + biases[k];
                            CHECK(fit->coefficients[(y * w + x) * 3 * terms + c * terms + k] ==
                                  doctest::Approx(expected).epsilon(1e-6));
                        }
        }
    }
}

TEST_CASE("rti: HSH order 2 and 3 written and read back are within half a quantisation step of the fit")
{
    std::mt19937_64 rng(41);
    // The largest |H_k| over the hemisphere, by brute force on a fine grid.
    const double pi = 3.14159265358979323846;
    double largest[kMaxLinearTerms] = {};
    for (int i = 0; i <= 200; ++i)
        for (int j = 0; j < 400; ++j) {
            const double theta = 0.5 * pi * i / 200, phi = 2 * pi * j / 400;
            const auto b = evaluate_basis(
                LinearModel::Hsh3, {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)});
            for (int k = 0; k < 9; ++k) largest[k] = std::max(largest[k], std::abs(b[k]));
        }

    for (LinearModel model : {LinearModel::Hsh2, LinearModel::Hsh3}) {
        CAPTURE(to_string(model));
        const int w = 5, h = 4;
        const LinearFit fit = random_hsh_fit(model, w, h, rng);
        const int terms = fit.terms();
        const std::string path = scratch("round_trip.rti");
        RtiQuantisation q;
        REQUIRE(write_rti(path, fit, &q));
        CHECK(q.terms == terms);

        // The file, parsed here.
        const std::string bytes = read_bytes(path);
        const std::string header = "#HSH1.2\n3\n5 4 3\n" + std::to_string(terms) + " 2 1\n";
        REQUIRE(bytes.substr(0, header.size()) == header);
        std::vector<double> scale(terms), bias(terms);
        for (int k = 0; k < terms; ++k) {
            scale[k] = float_le_at(bytes, header.size() + 4 * k);
            bias[k] = float_le_at(bytes, header.size() + 4 * (terms + k));
            CHECK(scale[k] > 0);
            CHECK(q.scales[k] == float(scale[k]));
            CHECK(q.biases[k] == float(bias[k]));
        }
        const std::size_t data = header.size() + 8 * terms;
        REQUIRE(bytes.size() == data + std::size_t(w * h * 3 * terms));
        std::size_t i = data;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                for (int c = 0; c < 3; ++c)
                    for (int k = 0; k < terms; ++k, ++i) {
                        const double v = static_cast<unsigned char>(bytes[i]) / 255.0 * scale[k] + bias[k];
                        const double original = fit.coefficients[(y * w + x) * 3 * terms + c * terms + k];
                        CHECK(std::abs(v - original) <= scale[k] / 510 + 1e-6);
                    }

        auto back = read_rti(path);
        REQUIRE(back);
        CHECK(back->model == model);
        std::vector<double> e(terms, 0.0);
        for (std::size_t j = 0; j < fit.coefficients.size(); ++j) {
            const int k = static_cast<int>(j % terms);
            e[k] = std::max(e[k], std::abs(double(back->coefficients[j]) - fit.coefficients[j]));
        }
        double bound = 0;
        for (int k = 0; k < terms; ++k) {
            CHECK(e[k] <= scale[k] / 510 + 1e-6);
            CHECK(q.max_coefficient_error[k] == doctest::Approx(e[k]).epsilon(1e-6));
            bound += e[k] * largest[k] * 1.001;
        }
        std::uniform_real_distribution<double> u(0.0, 1.0);
        for (int n = 0; n < 40; ++n) {
            const double z = u(rng), phi = 2 * pi * u(rng), r = std::sqrt(1 - z * z);
            const Vec3 l{r * std::cos(phi), r * std::sin(phi), z};
            const auto b = evaluate_basis(model, l);
            double local = 0;
            for (int k = 0; k < terms; ++k) local += e[k] * std::abs(b[k]);
            for (std::size_t t = 0; t < fit.texels(); ++t)
                for (int c = 0; c < 3; ++c)
                    CHECK(std::abs(relit(*back, t, c, l) - relit(fit, t, c, l)) <= local + 1e-6);
        }
        double pole = 0;
        for (std::size_t t = 0; t < fit.texels(); ++t)
            for (int c = 0; c < 3; ++c)
                pole = std::max(pole, std::abs(relit(*back, t, c, {0, 0, 1}) - relit(fit, t, c, {0, 0, 1})));
        CHECK(q.max_value_error >= pole - 1e-7);
        CHECK(q.max_value_error <= bound + 1e-6);
    }
}

TEST_CASE("rti: bad and truncated HSH files are refused naming what is wrong")
{
    const std::string path = scratch("bad.rti");
    const std::vector<float> s4 = {1, 1, 1, 1}, b4 = {0, 0, 0, 0};
    const std::string good = hsh_rti_bytes(3, 2, 4, s4, b4, hsh_byte);  // 3 * 2 * 3 * 4 = 72 coefficient bytes
    const std::size_t header = std::string("#HSH1.2\n3\n3 2 3\n4 2 1\n").size();
    auto replace = [&](const std::string& from, const std::string& to) {
        std::string b = good;
        b.replace(b.find(from), from.size(), to);
        return b;
    };
    struct Case {
        std::string bytes, message;
    };
    const std::vector<Case> cases = {
        {"PTM_1.2\nPTM_FORMAT_RGB\n", "is not an HSH .rti file: its first line is 'PTM_1.2', expected #HSH1.2"},
        {replace("\n3\n3 2 3\n", "\n1\n3 2 3\n"),
         "is of RTI type 1 (PTM), which cmfilter does not support; it reads HSH (3)"},
        {replace("\n3\n3 2 3\n", "\nx\n3 2 3\n"), "has RTI type line 'x', expected 3 (HSH)"},
        {replace("3 2 3\n", "3 two 3\n"), "has size line '3 two 3', expected three integers: width height bands"},
        {replace("3 2 3\n", "0 2 3\n"), "has width 0, expected an integer in 1 .. 65536"},
        {replace("3 2 3\n", "3 2 1\n"), "has 1 bands; cmfilter reads 3 (RGB)"},
        {replace("4 2 1\n", "16 2 1\n"), "has 16 terms; cmfilter reads HSH of order 2 (4 terms) and 3 (9 terms)"},
        {replace("4 2 1\n", "4 2 4\n"), "has element size 4; cmfilter reads 1-byte coefficients"},
        {good.substr(0, header + 20), "is truncated: expected 32 bytes of scales and biases, found 20"},
        {good.substr(0, good.size() - 5), "is truncated: expected 72 bytes of coefficients"},
        {"#HSH1.2\n#only comments\n", "ends before its RTI type line"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.message);
        write_bytes(path, c.bytes);
        auto fit = read_rti(path);
        REQUIRE_FALSE(fit);
        CHECK(fit.error().kind == ErrorKind::BadInput);
        CHECK(fit.error().message.find("'" + path + "'") != std::string::npos);
        CHECK(fit.error().message.find(c.message) != std::string::npos);
    }
    write_bytes(path, good.substr(0, good.size() - 5));
    auto fit = read_rti(path);
    REQUIRE_FALSE(fit);
    CHECK(fit.error().message.find("found 67") != std::string::npos);

    std::string nan_scale = good;
    const float nan = std::nanf("");
    std::memcpy(&nan_scale[header + 4], &nan, 4);
    write_bytes(path, nan_scale);
    fit = read_rti(path);
    REQUIRE_FALSE(fit);
    CHECK(fit.error().message.find("has a non-finite scale for term 1") != std::string::npos);

    auto missing = read_rti(scratch("no_such_file.rti"));
    REQUIRE_FALSE(missing);
    CHECK(missing.error().kind == ErrorKind::Io);
}

TEST_CASE("rti: write_rti refuses PTM fits, other channel counts and encodings, leaving no file")
{
    std::mt19937_64 rng(7);
    const std::string path = scratch("refused.rti");
    std::filesystem::remove(path);
    struct Case {
        LinearFit fit;
        std::string message;
    };
    std::vector<Case> cases;
    cases.push_back(
        {random_hsh_fit(LinearModel::PtmRgb, 2, 2, rng), "the fit's model is ptm-rgb; an HSH .rti holds hsh2 or hsh3"});
    LinearFit two = random_hsh_fit(LinearModel::Hsh3, 2, 2, rng);
    two.channels = 2;
    two.coefficients.resize(two.texels() * two.stride());
    cases.push_back({two, "the fit has 2 channel(s); an HSH .rti holds 3 (RGB)"});
    LinearFit linear = random_hsh_fit(LinearModel::Hsh2, 2, 2, rng);
    linear.encoding = StackEncoding::SceneLinear;
    cases.push_back({linear, "the fit is of scene-linear values; an .rti holds display-encoded ones"});
    LinearFit inf = random_hsh_fit(LinearModel::Hsh2, 2, 2, rng);
    inf.coefficients[2 * 12 + 5] = INFINITY;
    cases.push_back({inf, "texel (0, 1) has a non-finite coefficient"});
    for (const Case& c : cases) {
        CAPTURE(c.message);
        auto written = write_rti(path, c.fit);
        REQUIRE_FALSE(written);
        CHECK(written.error().kind == ErrorKind::BadInput);
        CHECK(written.error().message.find("cannot write '" + path + "' as .rti: " + c.message) != std::string::npos);
        CHECK_FALSE(std::filesystem::exists(path));
    }
}
