// SPDX-License-Identifier: Apache-2.0
// Linear fits of image stacks: coefficients against a per-texel QR solve,
// exact recovery of known models, the light set's conditioning against a
// closed form, the degenerate light sets named, relighting against direct
// evaluation, and the PTM-LRGB base colour against a brute-force minimum.
#include "cmfilter/stack/linear_fit.h"

#include <Eigen/Dense>
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace cmfilter;

namespace {

constexpr double kPi = 3.14159265358979323846;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

Vec3 direction(double elevation_deg, double azimuth_deg)
{
    const double e = elevation_deg * kPi / 180, a = azimuth_deg * kPi / 180;
    return {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
}

// n lights of random azimuth and elevation in [12, 85] degrees.
std::vector<Vec3> random_lights(std::mt19937_64& rng, int n)
{
    std::uniform_real_distribution<double> azimuth(0, 360), elevation(12, 85);
    std::vector<Vec3> lights;
    for (int k = 0; k < n; ++k) lights.push_back(direction(elevation(rng), azimuth(rng)));
    return lights;
}

ImageStack empty_stack(int width, int height, int channels, const std::vector<Vec3>& lights)
{
    ImageStack s;
    s.width = width;
    s.height = height;
    s.channels = channels;
    s.lights = lights;
    s.pixels.assign(lights.size() * s.texels() * static_cast<std::size_t>(channels), 0.0f);
    s.colorspace = "lin_rec709";
    return s;
}

// A stack of values uniform in [0.1, 0.9] plus Gaussian noise.
ImageStack random_stack(std::mt19937_64& rng, int width, int height, int channels, const std::vector<Vec3>& lights)
{
    ImageStack s = empty_stack(width, height, channels, lights);
    std::uniform_real_distribution<float> value(0.1f, 0.9f);
    std::normal_distribution<float> noise(0.0f, 0.05f);
    for (float& v : s.pixels) v = value(rng) + noise(rng);
    return s;
}

// The independent basis: the PTM monomials written out; HSH via
// evaluate_basis (checked against Gautron's definition in
// test_linear_model.cpp).
std::vector<double> basis_row(LinearModel model, const Vec3& l)
{
    if (model == LinearModel::PtmRgb || model == LinearModel::PtmLrgb)
        return {l.x * l.x, l.y * l.y, l.x * l.y, l.x, l.y, 1.0};
    const auto b = evaluate_basis(model, l);
    return std::vector<double>(b.begin(), b.begin() + basis_terms(model));
}

Eigen::MatrixXd design_matrix(LinearModel model, const std::vector<Vec3>& lights)
{
    const int terms = basis_terms(model);
    Eigen::MatrixXd a(static_cast<Eigen::Index>(lights.size()), terms);
    for (std::size_t k = 0; k < lights.size(); ++k) {
        const auto row = basis_row(model, lights[k]);
        for (int j = 0; j < terms; ++j) a(static_cast<Eigen::Index>(k), j) = row[static_cast<std::size_t>(j)];
    }
    return a;
}

// Texel t channel c's values under every light.
Eigen::VectorXd texel_values(const ImageStack& s, std::size_t t, int c)
{
    Eigen::VectorXd b(s.count());
    for (int k = 0; k < s.count(); ++k) b(k) = s.image(k)[t * s.channels + static_cast<std::size_t>(c)];
    return b;
}

std::string fit_error(const std::vector<Vec3>& lights, LinearModel model, std::string* field = nullptr)
{
    auto r = check_light_set(lights, model);
    if (r) return "(accepted)";
    CHECK(r.error().kind == ErrorKind::BadInput);
    if (field) *field = r.error().field;
    return r.error().message;
}

}  // namespace

TEST_CASE("linear fit: coefficients match a per-texel QR least-squares solve")
{
    std::mt19937_64 rng(17);
    const auto lights = random_lights(rng, 24);
    ImageStack stack = random_stack(rng, 7, 5, 3, lights);
    stack.encoding = StackEncoding::DisplayEncoded;
    const auto conditioning = check_light_set(lights, LinearModel::PtmRgb);
    REQUIRE(conditioning);
    for (LinearModel model : {LinearModel::PtmRgb, LinearModel::Hsh2, LinearModel::Hsh3, LinearModel::PtmLrgb}) {
        const std::string model_name = to_string(model);
        CAPTURE(model_name);
        LinearFitOptions options;
        options.model = model;
        options.threads = 2;
        auto fit = fit_linear(stack, options);
        REQUIRE(fit);
        CHECK(fit->width == 7);
        CHECK(fit->height == 5);
        CHECK(fit->channels == 3);
        CHECK(fit->colorspace == "lin_rec709");
        CHECK(fit->encoding == StackEncoding::DisplayEncoded);
        CHECK(fit->conditioning.lights == 24);
        CHECK(fit->conditioning.terms == basis_terms(model));
        if (model == LinearModel::PtmRgb) CHECK(fit->conditioning.condition_number == conditioning->condition_number);
        const int terms = basis_terms(model);
        REQUIRE(fit->coefficients.size() == stack.texels() * static_cast<std::size_t>(fit->stride()));
        const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(design_matrix(model, lights));
        for (std::size_t t = 0; t < stack.texels(); ++t) {
            if (model == LinearModel::PtmLrgb) {
                const Eigen::VectorXd y = 0.2126 * texel_values(stack, t, 0) + 0.7152 * texel_values(stack, t, 1) +
                                          0.0722 * texel_values(stack, t, 2);
                const Eigen::VectorXd x = qr.solve(y);
                for (int k = 0; k < terms; ++k) CHECK(fit->texel(t)[k] == doctest::Approx(x(k)).epsilon(1e-5));
                continue;
            }
            for (int c = 0; c < 3; ++c) {
                const Eigen::VectorXd x = qr.solve(texel_values(stack, t, c));
                for (int k = 0; k < terms; ++k)
                    CHECK(fit->texel(t)[c * terms + k] == doctest::Approx(x(k)).epsilon(1e-5));
            }
        }
    }
}

TEST_CASE("linear fit: a stack made from known PTM and HSH coefficients is recovered exactly")
{
    std::mt19937_64 rng(3);
    const auto lights = random_lights(rng, 30);
    std::uniform_real_distribution<double> coefficient(-1, 1);
    for (LinearModel model : {LinearModel::PtmRgb, LinearModel::Hsh2, LinearModel::Hsh3}) {
        const std::string model_name = to_string(model);
        CAPTURE(model_name);
        const int terms = basis_terms(model), channels = 3;
        ImageStack stack = empty_stack(6, 4, channels, lights);
        std::vector<double> truth(stack.texels() * channels * terms);
        for (double& v : truth) v = coefficient(rng);
        for (int k = 0; k < stack.count(); ++k) {
            const auto b = basis_row(model, lights[static_cast<std::size_t>(k)]);
            for (std::size_t i = 0; i < stack.texels() * channels; ++i) {
                double v = 0;
                for (int j = 0; j < terms; ++j) v += truth[i * terms + j] * b[static_cast<std::size_t>(j)];
                stack.image(k)[i] = static_cast<float>(v);
            }
        }
        LinearFitOptions options;
        options.model = model;
        auto fit = fit_linear(stack, options);
        REQUIRE(fit);
        for (std::size_t i = 0; i < truth.size(); ++i)
            CHECK(fit->coefficients[i] == doctest::Approx(truth[i]).epsilon(1e-5));
    }

    // PTM-LRGB: values c P(l) with a known colour c and polynomial P give
    // the luminance polynomial Y(c) P and the base colour c / Y(c).
    ImageStack stack = empty_stack(3, 3, 3, lights);
    std::uniform_real_distribution<double> colour(0.1, 1.0);
    std::vector<double> poly(stack.texels() * 6), base(stack.texels() * 3);
    for (double& v : poly) v = coefficient(rng);
    for (double& v : base) v = colour(rng);
    for (int k = 0; k < stack.count(); ++k) {
        const auto b = basis_row(LinearModel::PtmLrgb, lights[static_cast<std::size_t>(k)]);
        for (std::size_t t = 0; t < stack.texels(); ++t) {
            double p = 0;
            for (int j = 0; j < 6; ++j) p += poly[t * 6 + j] * b[static_cast<std::size_t>(j)];
            for (int c = 0; c < 3; ++c) stack.image(k)[t * 3 + c] = static_cast<float>(base[t * 3 + c] * p);
        }
    }
    LinearFitOptions options;
    options.model = LinearModel::PtmLrgb;
    auto fit = fit_linear(stack, options);
    REQUIRE(fit);
    for (std::size_t t = 0; t < stack.texels(); ++t) {
        const double y = 0.2126 * base[t * 3] + 0.7152 * base[t * 3 + 1] + 0.0722 * base[t * 3 + 2];
        for (int j = 0; j < 6; ++j) CHECK(fit->texel(t)[j] == doctest::Approx(y * poly[t * 6 + j]).epsilon(1e-5));
        for (int c = 0; c < 3; ++c) CHECK(fit->texel(t)[6 + c] == doctest::Approx(base[t * 3 + c] / y).epsilon(1e-5));
    }
}

TEST_CASE("linear fit: the conditioning of two rings of lights matches its closed form")
{
    // HSH 2 with n lights at azimuths 2 pi i / n on each of two rings,
    // cos(theta) = 1/2 + d and 1/2 - d: A^T A is diagonal with
    //   h0: 2n / (2 pi),   h2: (3 / (2 pi)) 2n (2d)^2,
    //   h1, h3: (6 / pi) (n / 2) 2 (1/4 - d^2),
    // and the singular values are their square roots.
    const int n = 8;
    const double d = 0.3;
    std::vector<Vec3> lights;
    for (double c : {0.5 + d, 0.5 - d})
        for (int i = 0; i < n; ++i) {
            const double phi = 2 * kPi * i / n, s = std::sqrt(1 - c * c);
            lights.push_back({s * std::cos(phi), s * std::sin(phi), c});
        }
    const double eig[3] = {n / kPi, 12 * n * d * d / kPi, 6 * n * (0.25 - d * d) / kPi};
    const double largest = std::sqrt(*std::max_element(eig, eig + 3));
    const double smallest = std::sqrt(*std::min_element(eig, eig + 3));
    auto c = check_light_set(lights, LinearModel::Hsh2);
    REQUIRE(c);
    CHECK(c->lights == 2 * n);
    CHECK(c->terms == 4);
    CHECK(c->clamped == 0);
    CHECK(c->largest_singular == doctest::Approx(largest).epsilon(1e-12));
    CHECK(c->smallest_singular == doctest::Approx(smallest).epsilon(1e-12));
    CHECK(c->condition_number == doctest::Approx(largest / smallest).epsilon(1e-12));
}

TEST_CASE("linear fit: degenerate light sets are refused naming the degeneracy")
{
    std::mt19937_64 rng(5);
    std::string field;

    // Fewer lights than terms: the model is the problem.
    const auto eight = random_lights(rng, 8);
    std::string e = fit_error(eight, LinearModel::Hsh3, &field);
    CHECK(contains(e, "fewer lights than terms"));
    CHECK(contains(e, "LinearFitOptions::model hsh3 has 9 terms"));
    CHECK(contains(e, "the 8 lights"));
    CHECK(field == "LinearFitOptions::model");
    CHECK(check_light_set(eight, LinearModel::PtmRgb));
    CHECK(contains(fit_error(random_lights(rng, 5), LinearModel::PtmRgb), "fewer lights than terms"));

    // Collinear: every (lu, lv) on the line at azimuth 30 degrees, on both
    // sides of the pole, at many elevations.
    std::vector<Vec3> line;
    for (double el : {20.0, 35.0, 50.0, 65.0, 80.0}) {
        line.push_back(direction(el, 30));
        line.push_back(direction(el, 210));
    }
    for (LinearModel m : {LinearModel::PtmRgb, LinearModel::PtmLrgb, LinearModel::Hsh2, LinearModel::Hsh3}) {
        e = fit_error(line, m, &field);
        CHECK(contains(e, "collinear"));
        CHECK(contains(e, "azimuth 30.0 degrees"));
        CHECK(field.empty());
    }
    // A jitter of 1e-7 in the directions is still collinear.
    for (std::size_t i = 0; i < line.size(); ++i) line[i].x += (i % 2 ? 1e-7 : -1e-7) * static_cast<double>(i);
    CHECK(contains(fit_error(line, LinearModel::PtmRgb), "collinear"));
    // A line off the pole (lu = 0.3, lv from -0.8 to 0.8): lu^2, lu and 1
    // are then proportional, so the PTM's rank falls by two; that is
    // collinear too, and the message gives the line's distance from the pole.
    std::vector<Vec3> off;
    for (int i = 0; i < 9; ++i) {
        const double v = -0.8 + 0.2 * i;
        off.push_back({0.3, v, std::sqrt(1 - 0.09 - v * v)});
    }
    e = fit_error(off, LinearModel::PtmRgb);
    CHECK(contains(e, "collinear"));
    CHECK(contains(e, "azimuth 90.0 degrees, 0.3 from the pole"));

    // All at one elevation: a ring at 45 degrees.
    std::vector<Vec3> ring;
    for (int i = 0; i < 12; ++i) ring.push_back(direction(45, 30.0 * i + 7));
    for (LinearModel m : {LinearModel::PtmRgb, LinearModel::Hsh2, LinearModel::Hsh3}) {
        e = fit_error(ring, m);
        CHECK(contains(e, "all at one elevation, 45.0 degrees"));
    }
    CHECK(contains(fit_error(ring, LinearModel::PtmRgb), "a0, a1 and a5"));
    CHECK(contains(fit_error(ring, LinearModel::Hsh3), "h0, h2 and h6"));

    // A rank deficiency of another kind: PTM lights whose (lu, lv) lie on
    // the ellipse lu^2 + 4 lv^2 = 1/2 (neither a line nor a circle, so at
    // many elevations) make a0 + 4 a1 - a5 / 2 dependent.
    std::vector<Vec3> ellipse;
    for (int i = 0; i < 10; ++i) {
        const double t = 2 * kPi * i / 10 + 0.1;
        const double u = std::sqrt(0.5) * std::cos(t), v = std::sqrt(0.5) / 2 * std::sin(t);
        ellipse.push_back({u, v, std::sqrt(1 - u * u - v * v)});
    }
    // It is not refused: the singular value is clamped, and the fit is the
    // minimum-norm least-squares solution (Eigen's complete orthogonal
    // decomposition gives it independently).
    auto clamped = check_light_set(ellipse, LinearModel::PtmRgb);
    REQUIRE(clamped);
    CHECK(clamped->clamped == 1);
    CHECK(std::isfinite(clamped->condition_number));
    {
        ImageStack s = empty_stack(1, 1, 1, ellipse);
        std::mt19937_64 rng(7);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        Eigen::MatrixXd a(ellipse.size(), 6);
        Eigen::VectorXd b(ellipse.size());
        for (std::size_t k = 0; k < ellipse.size(); ++k) {
            const auto basis = evaluate_basis(LinearModel::PtmRgb, ellipse[k]);
            for (int j = 0; j < 6; ++j) a(k, j) = basis[j];
            b(k) = unit(rng);
            s.image(static_cast<int>(k))[0] = static_cast<float>(b(k));
        }
        auto f = fit_linear(s, LinearFitOptions{});
        REQUIRE(f);
        CHECK(f->conditioning.clamped == 1);
        const Eigen::VectorXd x =
            a.completeOrthogonalDecomposition().solve(Eigen::VectorXd(b.cast<float>().cast<double>()));
        for (int j = 0; j < 6; ++j) CHECK(f->coefficients[j] == doctest::Approx(x(j)).epsilon(1e-4).scale(1));
    }
    // HSH 3 over the same lights is not degenerate in that way.
    CHECK(check_light_set(ellipse, LinearModel::Hsh2));

    // fit_linear names the stack's light file.
    ImageStack stack = empty_stack(2, 2, 3, ring);
    stack.light_file = "dome.lp";
    auto fit = fit_linear(stack, LinearFitOptions{});
    REQUIRE_FALSE(fit);
    CHECK(fit.error().kind == ErrorKind::BadInput);
    CHECK(contains(fit.error().message, "'dome.lp'"));
    CHECK(contains(fit.error().message, "all at one elevation, 45.0 degrees"));
}

TEST_CASE("linear fit: options and stacks that cannot be fitted are refused")
{
    std::mt19937_64 rng(9);
    const auto lights = random_lights(rng, 12);
    ImageStack stack = random_stack(rng, 3, 2, 3, lights);
    for (double bad : {-0.1, 1.0, 2.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
        LinearFitOptions options;
        options.singular_threshold = bad;
        auto fit = fit_linear(stack, options);
        REQUIRE_FALSE(fit);
        CHECK(fit.error().field == "LinearFitOptions::singular_threshold");
        CHECK(contains(fit.error().message, "LinearFitOptions::singular_threshold"));
        CHECK(contains(fit.error().message, "[0, 1)"));
    }
    // A threshold that clamps real singular values keeps the terms whose
    // singular values pass it: the fit is reported as clamped, and it fits
    // the values no better than the full one.
    LinearFitOptions strict;
    strict.singular_threshold = 0.999;
    auto clamped = fit_linear(stack, strict);
    REQUIRE(clamped);
    CHECK(clamped->conditioning.clamped >= 1);
    auto full = fit_linear(stack, LinearFitOptions{});
    REQUIRE(full);
    CHECK(full->conditioning.clamped == 0);
    double residual_clamped = 0, residual_full = 0;
    for (int k = 0; k < stack.count(); ++k) {
        const std::vector<float> a = relight(*clamped, stack.lights[k], 1), b = relight(*full, stack.lights[k], 1);
        for (std::size_t i = 0; i < a.size(); ++i) {
            residual_clamped += std::pow(a[i] - stack.image(k)[i], 2);
            residual_full += std::pow(b[i] - stack.image(k)[i], 2);
        }
    }
    CHECK(residual_clamped >= residual_full * (1 - 1e-9));

    ImageStack two = random_stack(rng, 3, 2, 2, lights);
    LinearFitOptions lrgb;
    lrgb.model = LinearModel::PtmLrgb;
    auto fit = fit_linear(two, lrgb);
    REQUIRE_FALSE(fit);
    CHECK(fit.error().field == "LinearFitOptions::model");
    CHECK(contains(fit.error().message, "1 or 3 channels"));
    lrgb.model = LinearModel::PtmRgb;
    CHECK(fit_linear(two, lrgb));

    stack.pixels.pop_back();
    CHECK_FALSE(fit_linear(stack, LinearFitOptions{}));
}

TEST_CASE("linear fit: results do not depend on the thread count")
{
    std::mt19937_64 rng(11);
    const auto lights = random_lights(rng, 20);
    const ImageStack stack = random_stack(rng, 64, 48, 3, lights);
    for (LinearModel model : {LinearModel::PtmRgb, LinearModel::PtmLrgb, LinearModel::Hsh3}) {
        LinearFitOptions options;
        options.model = model;
        options.threads = 1;
        auto one = fit_linear(stack, options);
        options.threads = 3;
        auto three = fit_linear(stack, options);
        REQUIRE(one);
        REQUIRE(three);
        CHECK(one->coefficients == three->coefficients);
        CHECK(relight(*one, lights[0], 1) == relight(*one, lights[0], 4));
    }
}

TEST_CASE("linear fit: relighting equals direct evaluation of the model")
{
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<float> coefficient(-1, 1);
    const Vec3 light = direction(40, 115);
    const double lu = light.x, lv = light.y;
    for (LinearModel model : {LinearModel::PtmRgb, LinearModel::PtmLrgb, LinearModel::Hsh3}) {
        const std::string model_name = to_string(model);
        CAPTURE(model_name);
        LinearFit fit;
        fit.model = model;
        fit.width = 5;
        fit.height = 3;
        fit.channels = 3;
        fit.coefficients.resize(fit.texels() * static_cast<std::size_t>(fit.stride()));
        for (float& v : fit.coefficients) v = coefficient(rng);
        const auto image = relight(fit, light, 2);
        REQUIRE(image.size() == fit.texels() * 3);
        for (std::size_t t = 0; t < fit.texels(); ++t) {
            const float* a = fit.texel(t);
            for (int c = 0; c < 3; ++c) {
                double expected = 0;
                if (model == LinearModel::PtmRgb) {
                    const float* p = a + 6 * c;
                    expected = p[0] * lu * lu + p[1] * lv * lv + p[2] * lu * lv + p[3] * lu + p[4] * lv + p[5];
                } else if (model == LinearModel::PtmLrgb) {
                    expected = a[6 + c] *
                               (a[0] * lu * lu + a[1] * lv * lv + a[2] * lu * lv + a[3] * lu + a[4] * lv + a[5]);
                } else {
                    const auto b = basis_row(model, light);
                    for (int k = 0; k < 9; ++k) expected += a[9 * c + k] * b[static_cast<std::size_t>(k)];
                }
                CHECK(image[t * 3 + c] == doctest::Approx(expected).epsilon(1e-6));
            }
        }
    }
}

TEST_CASE("linear fit: the PTM-LRGB base colour is the least-squares colour for the fitted luminance")
{
    std::mt19937_64 rng(21);
    const auto lights = random_lights(rng, 16);
    ImageStack stack = random_stack(rng, 4, 3, 3, lights);
    // Texel 0 black: the guard gives base colour 0.
    for (int k = 0; k < stack.count(); ++k)
        for (int c = 0; c < 3; ++c) stack.image(k)[c] = 0.0f;
    LinearFitOptions options;
    options.model = LinearModel::PtmLrgb;
    auto fit = fit_linear(stack, options);
    REQUIRE(fit);
    for (int c = 0; c < 3; ++c) CHECK(fit->texel(0)[6 + c] == 0.0f);
    for (std::size_t t = 1; t < stack.texels(); ++t) {
        const float* a = fit->texel(t);
        std::vector<double> fitted;
        for (const Vec3& l : lights)
            fitted.push_back(a[0] * l.x * l.x + a[1] * l.y * l.y + a[2] * l.x * l.y + a[3] * l.x + a[4] * l.y + a[5]);
        for (int c = 0; c < 3; ++c) {
            const Eigen::VectorXd values = texel_values(stack, t, c);
            const auto error = [&](double base) {
                double e = 0;
                for (int k = 0; k < stack.count(); ++k) e += std::pow(values(k) - base * fitted[k], 2);
                return e;
            };
            // Brute force: a scan of [0, 4] by 1e-3, then golden sections.
            double best = 0;
            for (double b = 0; b <= 4; b += 1e-3)
                if (error(b) < error(best)) best = b;
            double lo = best - 1e-3, hi = best + 1e-3;
            const double g = (std::sqrt(5.0) - 1) / 2;
            for (int i = 0; i < 60; ++i) {
                const double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
                if (error(x1) < error(x2)) hi = x2;
                else lo = x1;
            }
            CHECK(a[6 + c] == doctest::Approx(0.5 * (lo + hi)).epsilon(1e-5));
        }
        // Its Rec. 709 luminance is 1: the fitted luminance is the
        // projection of the luminance onto the polynomials.
        CHECK(0.2126 * a[6] + 0.7152 * a[7] + 0.0722 * a[8] == doctest::Approx(1.0).epsilon(1e-5));
    }

    // One channel: the luminance is the channel, and its base colour 1.
    const ImageStack grey = random_stack(rng, 4, 3, 1, lights);
    auto grey_fit = fit_linear(grey, options);
    REQUIRE(grey_fit);
    REQUIRE(grey_fit->stride() == 7);
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(design_matrix(LinearModel::PtmLrgb, lights));
    for (std::size_t t = 0; t < grey.texels(); ++t) {
        const Eigen::VectorXd x = qr.solve(texel_values(grey, t, 0));
        for (int k = 0; k < 6; ++k) CHECK(grey_fit->texel(t)[k] == doctest::Approx(x(k)).epsilon(1e-5));
        CHECK(grey_fit->texel(t)[6] == doctest::Approx(1.0).epsilon(1e-5));
    }
}
