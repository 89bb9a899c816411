// SPDX-License-Identifier: Apache-2.0
// Streamed fits and errors (streamed_fit.h, relight_error.h): the
// coefficients of every model on RGB, grey and float stacks against the fit
// of the whole stack in memory and against a per-texel QR solve; the same
// for any thread count; the light set refused before any image is read; the
// image checks of load_image_stack; the error at a stack's lights against
// relight_error; and the streamed percentile against a sort.
#include "cmfilter/stack/image_stack.h"
#include "cmfilter/stack/linear_fit.h"
#include "cmfilter/stack/relight_error.h"
#include "cmfilter/stack/streamed_error_summary.h"
#include "cmfilter/stack/streamed_fit.h"

#include "test_images.h"
#include "unit_test_support.h"

#include <Eigen/Dense>
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace cmfilter;

namespace {

const std::string kDir = cmfilter_test::temp_dir("cmfilter-streamed-fit");

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

constexpr int kWidth = 80, kHeight = 60;  // 4800 texels: two blocks of the accumulation

// Light k of n: a spiral over elevations 15-80 degrees.
Vec3 spiral_light(int k, int n)
{
    const double e = (15 + 65.0 * k / (n - 1)) * 3.14159265358979323846 / 180;
    const double a = 2.39996323 * k;
    return {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
}

// n images of kWidth x kHeight with `channels` channels: a shaded relief
// times a colour, plus texel-dependent noise; the first row's first 5
// texels black under every light. 8-bit PNG, or float EXR (values to 3).
std::string write_stack(const std::string& name, int n, int channels, bool exr)
{
    std::mt19937_64 rng(std::hash<std::string>{}(name));
    std::uniform_real_distribution<double> noise(-0.04, 0.04);
    std::string lp = std::to_string(n) + "\n";
    const std::size_t texels = static_cast<std::size_t>(kWidth) * kHeight;
    for (int k = 0; k < n; ++k) {
        const Vec3 l = spiral_light(k, n);
        std::vector<float> value(texels * channels);
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const std::size_t t = static_cast<std::size_t>(y) * kWidth + x;
                const Vec3 normal = normalize(Vec3{0.5 * std::sin(0.21 * x), 0.4 * std::cos(0.17 * y), 1});
                const double shade = std::max(0.0, dot(normal, l));
                for (int c = 0; c < channels; ++c) {
                    const double colour = 0.3 + 0.6 * ((x * 7 + y * 3 + c * 11) % 17) / 16.0;
                    double v = colour * shade + noise(rng) + 0.05;
                    if (y == 0 && x < 5) v = 0;
                    value[t * channels + c] = static_cast<float>(exr ? 3 * v : std::clamp(v, 0.0, 1.0));
                }
            }
        const std::string file = name + "-" + std::to_string(k) + (exr ? ".exr" : ".png");
        if (exr)
            cmfilter_test::write_image(kDir + "/" + file, kWidth, kHeight, channels, OIIO::TypeDesc::FLOAT,
                                       value.data());
        else {
            std::vector<unsigned char> codes(value.size());
            for (std::size_t i = 0; i < value.size(); ++i)
                codes[i] = static_cast<unsigned char>(std::lround(255 * value[i]));
            cmfilter_test::write_image(kDir + "/" + file, kWidth, kHeight, channels, OIIO::TypeDesc::UINT8,
                                       codes.data());
        }
        char line[160];
        std::snprintf(line, sizeof line, "%s %.9f %.9f %.9f\n", file.c_str(), l.x, l.y, l.z);
        lp += line;
    }
    const std::string path = kDir + "/" + name + ".lp";
    std::ofstream(path) << lp;
    return path;
}

// The same coefficients to float rounding (a few units of the last place).
void check_same_fit(const LinearFit& streamed, const LinearFit& held)
{
    REQUIRE(streamed.coefficients.size() == held.coefficients.size());
    CHECK(streamed.width == held.width);
    CHECK(streamed.height == held.height);
    CHECK(streamed.channels == held.channels);
    CHECK(streamed.encoding == held.encoding);
    CHECK(streamed.colorspace == held.colorspace);
    CHECK(streamed.conditioning.condition_number == doctest::Approx(held.conditioning.condition_number));
    double worst = 0;
    for (std::size_t i = 0; i < held.coefficients.size(); ++i) {
        const double a = streamed.coefficients[i], b = held.coefficients[i];
        worst = std::max(worst, std::abs(a - b) / std::max(1.0, std::abs(b)));
    }
    CHECK(worst <= 1e-6);
}

const LinearModel kModels[] = {LinearModel::PtmRgb, LinearModel::PtmLrgb, LinearModel::Hsh2, LinearModel::Hsh3};

}  // namespace

TEST_CASE("streamed fit: every model of RGB, grey and float stacks equals the fit of the stack in memory")
{
    const auto config = cmfilter_test::builtin_color_config();
    struct Case {
        std::string lp;
        StackEncoding encoding;
    };
    const Case cases[] = {{write_stack("rgb", 14, 3, false), StackEncoding::SceneLinear},
                          {write_stack("rgb", 14, 3, false), StackEncoding::DisplayEncoded},
                          {write_stack("grey", 11, 1, false), StackEncoding::SceneLinear},
                          {write_stack("float", 9, 3, true), StackEncoding::SceneLinear}};
    for (const Case& c : cases)
        for (LinearModel model : kModels) {
            CAPTURE(c.lp);
            CAPTURE(to_string(model));
            StackLoadOptions load;
            load.light_file = c.lp;
            load.encoding = c.encoding;
            LinearFitOptions options;
            options.model = model;
            auto stack = load_image_stack(load, config);
            REQUIRE(stack);
            auto held = fit_linear(*stack, options);
            REQUIRE(held);
            auto streamed = fit_linear_from_files(load, options, config);
            REQUIRE(streamed);
            check_same_fit(*streamed, *held);
        }
}

TEST_CASE("streamed fit: HSH 3 coefficients equal a per-texel QR least-squares solve of the images")
{
    const auto config = cmfilter_test::builtin_color_config();
    StackLoadOptions load;
    load.light_file = write_stack("qr", 12, 3, true);
    auto stack = load_image_stack(load, config);
    REQUIRE(stack);
    LinearFitOptions options;
    options.model = LinearModel::Hsh3;
    auto fit = fit_linear_from_files(load, options, config);
    REQUIRE(fit);
    // The light matrix from the basis at each light, solved by Householder QR.
    Eigen::MatrixXd a(stack->count(), 9);
    for (int k = 0; k < stack->count(); ++k) {
        const auto b = evaluate_basis(LinearModel::Hsh3, stack->lights[k]);
        for (int j = 0; j < 9; ++j) a(k, j) = b[j];
    }
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(a);
    double worst = 0;
    for (std::size_t t : {std::size_t(7), std::size_t(1234), std::size_t(4799)})
        for (int c = 0; c < 3; ++c) {
            Eigen::VectorXd values(stack->count());
            for (int k = 0; k < stack->count(); ++k) values(k) = stack->image(k)[t * 3 + c];
            const Eigen::VectorXd x = qr.solve(values);
            for (int j = 0; j < 9; ++j)
                worst = std::max(worst, std::abs(fit->texel(t)[c * 9 + j] - x(j)) / std::max(1.0, std::abs(x(j))));
        }
    CHECK(worst <= 1e-5);
}

TEST_CASE("streamed fit: the same coefficients for any thread count, and progress to 1")
{
    const auto config = cmfilter_test::builtin_color_config();
    StackLoadOptions load;
    load.light_file = write_stack("threads", 13, 3, false);
    LinearFitOptions options;
    options.model = LinearModel::PtmLrgb;
    load.threads = 1;
    options.threads = 1;
    std::vector<double> fractions;
    auto one = fit_linear_from_files(load, options, config, [&](double f) { fractions.push_back(f); });
    REQUIRE(one);
    load.threads = 5;  // batches of 5 images: 1, then 5, 5, 2
    options.threads = 3;
    auto many = fit_linear_from_files(load, options, config);
    REQUIRE(many);
    CHECK(one->coefficients == many->coefficients);
    REQUIRE(fractions.size() == 13);
    CHECK(std::is_sorted(fractions.begin(), fractions.end()));
    CHECK(fractions.back() == 1.0);
}

TEST_CASE("streamed fit: the light set is refused before any image is read, the images checked as loaded")
{
    const auto config = cmfilter_test::builtin_color_config();
    LinearFitOptions options;
    StackLoadOptions load;
    // Six lights at one elevation, none of whose images exist.
    std::string lp = "6\n";
    for (int k = 0; k < 6; ++k)
        lp += "absent-" + std::to_string(k) + ".png " + std::to_string(0.8 * std::cos(k)) + " " +
              std::to_string(0.8 * std::sin(k)) + " 0.6\n";
    std::ofstream(kDir + "/elevation.lp") << lp;
    load.light_file = kDir + "/elevation.lp";
    auto elevation = fit_linear_from_files(load, options, config);
    REQUIRE_FALSE(elevation);
    CHECK(elevation.error().kind == ErrorKind::BadInput);
    CHECK(contains(elevation.error().message, "elevation.lp': the 6 lights cannot determine a ptm-rgb fit"));
    CHECK(contains(elevation.error().message, "one elevation"));
    options.model = LinearModel::Hsh3;  // 9 terms, 6 lights
    auto few = fit_linear_from_files(load, options, config);
    REQUIRE_FALSE(few);
    CHECK(few.error().field == "LinearFitOptions::model");
    options.model = LinearModel::PtmRgb;
    options.singular_threshold = -1;
    auto threshold = fit_linear_from_files(load, options, config);
    REQUIRE_FALSE(threshold);
    CHECK(threshold.error().field == "LinearFitOptions::singular_threshold");
    CHECK(threshold.error().message.rfind("LinearFitOptions::singular_threshold -1 is invalid", 0) == 0);
    options.singular_threshold = 1e-6;

    // Each image error as load_image_stack gives it.
    auto same_error = [&](const std::string& expected_part) {
        auto held = load_image_stack(load, config);
        auto streamed = fit_linear_from_files(load, options, config);
        REQUIRE_FALSE(held);
        REQUIRE_FALSE(streamed);
        CHECK(streamed.error().kind == held.error().kind);
        CHECK(streamed.error().message == held.error().message);
        CHECK(contains(streamed.error().message, expected_part));
    };
    load.light_file = write_stack("five", 5, 3, false);
    same_error("has 5 lights; a stack needs at least 6");
    load.light_file = write_stack("size", 8, 3, false);
    std::vector<unsigned char> px(5 * 3 * 3, 9);
    cmfilter_test::write_image(kDir + "/size-6.png", 5, 3, 3, OIIO::TypeDesc::UINT8, px.data());
    same_error("size-6.png' is 5x3 but '" + kDir + "/size-0.png' is 80x60");
    load.light_file = write_stack("channels", 8, 3, false);
    std::vector<unsigned char> grey(kWidth * kHeight, 9);
    cmfilter_test::write_image(kDir + "/channels-3.png", kWidth, kHeight, 1, OIIO::TypeDesc::UINT8, grey.data());
    same_error("channels-3.png' has 1 channel but '" + kDir + "/channels-0.png' has 3");
    load.light_file = write_stack("missing", 8, 3, false);
    std::remove((kDir + "/missing-5.png").c_str());
    same_error("missing-5.png");
    load.light_file = write_stack("nan", 7, 3, true);
    std::vector<float> nan_image(kWidth * kHeight * 3, 0.5f);
    nan_image[(2 * kWidth + 3) * 3 + 1] = std::numeric_limits<float>::quiet_NaN();
    cmfilter_test::write_image(kDir + "/nan-4.exr", kWidth, kHeight, 3, OIIO::TypeDesc::FLOAT, nan_image.data());
    same_error("nan-4.exr' has a non-finite value at (3, 2) channel 1");

    // PTM-LRGB of four channels, as fit_linear refuses it.
    load.light_file = write_stack("rgba", 7, 4, false);
    options.model = LinearModel::PtmLrgb;
    auto stack = load_image_stack(load, config);
    REQUIRE(stack);
    auto held = fit_linear(*stack, options);
    auto streamed = fit_linear_from_files(load, options, config);
    REQUIRE_FALSE(held);
    REQUIRE_FALSE(streamed);
    CHECK(streamed.error().message == held.error().message);
    CHECK(streamed.error().field == "LinearFitOptions::model");
}

TEST_CASE("streamed relight error: equal to relight_error on the stack in memory")
{
    const auto config = cmfilter_test::builtin_color_config();
    for (int channels : {3, 1})
        for (StackEncoding encoding : {StackEncoding::SceneLinear, StackEncoding::DisplayEncoded}) {
            CAPTURE(channels);
            StackLoadOptions load;
            load.light_file = write_stack("error-" + std::to_string(channels), 10, channels, false);
            load.encoding = encoding;
            auto stack = load_image_stack(load, config);
            REQUIRE(stack);
            LinearFitOptions options;
            options.model = LinearModel::Hsh2;
            auto fit = fit_linear(*stack, options);
            REQUIRE(fit);
            // The error of this fit against a second stack (other noise) too.
            StackLoadOptions other = load;
            other.light_file = write_stack("error-other-" + std::to_string(channels), 7, channels, false);
            for (const StackLoadOptions* reference : {&load, &other}) {
                auto whole = load_image_stack(*reference, config);
                REQUIRE(whole);
                auto held = relight_error(*fit, *whole, config, 2);
                REQUIRE(held);
                for (int threads : {1, 3}) {
                    auto streamed = relight_error_from_files(*fit, *reference, config, threads);
                    REQUIRE(streamed);
                    auto near = [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::abs(b) + 1e-300; };
                    CHECK(streamed->lights == held->lights);
                    CHECK(near(streamed->rmse, held->rmse));
                    CHECK(near(streamed->delta_e.mean, held->delta_e.mean));
                    CHECK(streamed->delta_e.p95 == held->delta_e.p95);
                    CHECK(streamed->delta_e.max == held->delta_e.max);
                    CHECK(streamed->delta_e.count == held->delta_e.count);
                    REQUIRE(streamed->light_rmse.size() == held->light_rmse.size());
                    for (std::size_t k = 0; k < held->light_rmse.size(); ++k) {
                        CHECK(near(streamed->light_rmse[k], held->light_rmse[k]));
                        CHECK(near(streamed->light_delta_e[k], held->light_delta_e[k]));
                    }
                }
            }
        }
}

TEST_CASE("streamed relight error: a stack of another size than the fit, and a missing image")
{
    const auto config = cmfilter_test::builtin_color_config();
    StackLoadOptions load;
    load.light_file = write_stack("fit-shape", 8, 3, false);
    auto fit = fit_linear_from_files(load, LinearFitOptions{}, config);
    REQUIRE(fit);
    LinearFit smaller = *fit;
    smaller.width = 40;
    smaller.coefficients.resize(smaller.texels() * smaller.stride());
    auto shape = relight_error_from_files(smaller, load, config);
    REQUIRE_FALSE(shape);
    CHECK(contains(shape.error().message, "the fit is 40x60 with 3 channels but the stack '"));
    CHECK(contains(shape.error().message, "fit-shape.lp' is 80x60 with 3"));
    std::remove((kDir + "/fit-shape-6.png").c_str());
    auto missing = relight_error_from_files(*fit, load, config);
    REQUIRE_FALSE(missing);
    CHECK(missing.error().kind == ErrorKind::Io);
    CHECK(contains(missing.error().message, "fit-shape-6.png"));
}

TEST_CASE("streamed error summary: mean, exact p95 and max against a sort, in one pass or several")
{
    std::mt19937_64 rng(42);
    std::exponential_distribution<double> exponential(0.5);
    std::uniform_real_distribution<double> uniform(-2, 5);
    struct Sample {
        const char* name;
        std::vector<double> values;
    };
    std::vector<Sample> samples;
    std::vector<double> v;
    for (int i = 0; i < 60000; ++i) v.push_back(exponential(rng));
    samples.push_back({"exponential", v});
    std::sort(v.begin(), v.end());
    samples.push_back({"ascending", v});  // the estimate drifts upwards throughout
    std::reverse(v.begin(), v.end());
    samples.push_back({"descending", v});
    v.clear();
    for (int i = 0; i < 50000; ++i) v.push_back(i % 10 < 7 ? 0.0 : uniform(rng));  // many zeros, some negative
    samples.push_back({"zeros and negatives", v});
    v.assign(30000, 1.25);  // one value: every bit fixed in turn
    v[17] = 3;
    samples.push_back({"constant", v});
    v.clear();
    for (int i = 0; i < 40000; ++i) v.push_back(1 + i * 1e-15);  // distinct only in the lowest bits
    std::shuffle(v.begin(), v.end(), rng);
    samples.push_back({"narrow", v});
    samples.push_back({"small", {3, 1, 2}});
    for (const Sample& s : samples)
        for (std::size_t limit : {std::size_t(1) << 20, std::size_t(500)}) {
            CAPTURE(s.name);
            CAPTURE(limit);
            const ErrorSummary expected = summarize_errors(s.values);
            StreamedErrorSummary streamed(limit);
            int passes = 0;
            do {
                ++passes;
                for (std::size_t i = 0; i < s.values.size(); i += 997)
                    streamed.add(s.values.data() + i, std::min<std::size_t>(997, s.values.size() - i));
            } while (!streamed.end_pass() && passes < 10);
            CHECK(passes <= 4);
            if (limit > s.values.size()) CHECK(passes == 1);
            const ErrorSummary got = streamed.summary();
            CHECK(got.count == expected.count);
            CHECK(got.p95 == expected.p95);
            CHECK(got.max == expected.max);
            CHECK(got.mean == doctest::Approx(expected.mean).epsilon(1e-12));
        }
    StreamedErrorSummary empty;
    CHECK(empty.end_pass());
    CHECK(empty.summary().count == 0);
    CHECK(empty.summary().p95 == 0);
}
