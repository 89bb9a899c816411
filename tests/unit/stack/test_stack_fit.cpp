// SPDX-License-Identifier: Apache-2.0
// A fit of either kind (stack_fit.h): files told apart by kind, a
// Lafortune fit relit at other views against the paper's formula written in
// the test (lafortune_test_support.h), a linear fit's one view, and the
// error streamed from a stack's files against a brute-force RMSE.
#include "cmfilter/stack/fit_file.h"
#include "cmfilter/stack/lafortune_error.h"
#include "cmfilter/stack/lafortune_file.h"
#include "cmfilter/stack/stack_fit.h"

#include "lafortune_test_support.h"
#include "test_images.h"
#include "unit_test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

using namespace cmfilter;

namespace {

const std::string kDir = cmfilter_test::temp_dir("cmfilter-stack-fit");

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The fitted view: every component non-zero, so the paper's C is
// determined by the stored axes a = (Cx vx, Cy vy, Cz vz).
const Vec3 kFittedView = normalize(Vec3{0.3, -0.4, 0.866});

// Two texels of one luminance lobe each, in the paper's C, and their base
// colours.
struct PaperTexel {
    double rho;
    cmfilter_test::PaperLobe lobe;
    double colour[3];
};
const PaperTexel kTexels[] = {{0.2, {0.9, 1.1, 1.3, 6}, {0.8, 0.5, 0.3}},
                              {0.05, {-0.7, 0.6, 1.0, 20}, {0.4, 0.6, 0.9}}};

// The texels as a luminance LafortuneFit of 2 x 1 texels, one lobe slot,
// fitted at kFittedView: the stored axis is C times the view.
LafortuneFit paper_fit()
{
    LafortuneFit fit;
    fit.variant = LafortuneVariant::Luminance;
    fit.width = 2;
    fit.height = 1;
    fit.channels = 3;
    fit.lobes = 1;
    fit.view = kFittedView;
    fit.colorspace = "lin_rec709";
    for (const PaperTexel& t : kTexels) {
        const Vec3& v = kFittedView;
        for (double p : {t.rho, t.lobe.cx * v.x, t.lobe.cy * v.y, t.lobe.cz * v.z, t.lobe.n})
            fit.parameters.push_back(static_cast<float>(p));
        for (double c : t.colour) fit.parameters.push_back(static_cast<float>(c));
        fit.lobe_counts.push_back(1);
    }
    return fit;
}

// The paper's value of texel t at light u and view w: c uz f(u, w).
double paper_value(int t, int c, const Vec3& u, const Vec3& w)
{
    const PaperTexel& p = kTexels[t];
    return p.colour[c] * u.z * cmfilter_test::paper_reflectance(p.rho, {p.lobe}, u, w);
}

LinearFit small_linear_fit()
{
    LinearFit fit;
    fit.model = LinearModel::PtmRgb;
    fit.width = 2;
    fit.height = 1;
    fit.channels = 3;
    fit.colorspace = "lin_rec709";
    for (int i = 0; i < 2 * 18; ++i) fit.coefficients.push_back(0.01f * static_cast<float>(i % 7) + 0.02f);
    return fit;
}

const std::vector<Vec3> kLights = {normalize(Vec3{0.2, 0.1, 0.9}),   normalize(Vec3{-0.5, 0.3, 0.7}),
                                   normalize(Vec3{0.6, -0.6, 0.5}),  normalize(Vec3{0.0, 0.8, 0.6}),
                                   normalize(Vec3{-0.3, -0.7, 0.6}), normalize(Vec3{0.8, 0.1, 0.55}),
                                   normalize(Vec3{0.1, -0.2, 0.97})};

}  // namespace

TEST_CASE("stack fit: a Lafortune EXR and a linear EXR told apart by kind, another kind refused")
{
    const std::string lafortune_path = kDir + "/lafortune.exr";
    const std::string linear_path = kDir + "/linear.exr";
    REQUIRE(write_lafortune_exr(lafortune_path, paper_fit()));
    REQUIRE(write_fit_exr(linear_path, small_linear_fit(), FitFileInfo{}));

    auto lafortune = load_stack_fit(lafortune_path);
    REQUIRE(lafortune);
    REQUIRE(std::holds_alternative<LafortuneFit>(*lafortune));
    CHECK(stack_fit_model_name(*lafortune) == "lafortune");
    CHECK(stack_fit_width(*lafortune) == 2);
    CHECK(stack_fit_height(*lafortune) == 1);
    CHECK(stack_fit_channels(*lafortune) == 3);
    CHECK(stack_fit_texels(*lafortune) == 2);
    CHECK(std::abs(stack_fit_view(*lafortune).x - kFittedView.x) < 1e-12);
    CHECK(std::abs(stack_fit_view(*lafortune).y - kFittedView.y) < 1e-12);

    auto linear = load_stack_fit(linear_path);
    REQUIRE(linear);
    REQUIRE(std::holds_alternative<LinearFit>(*linear));
    CHECK(stack_fit_model_name(*linear) == "ptm-rgb");
    CHECK(stack_fit_view(*linear).z == 1);

    // An EXR of another cmfilter kind, and an EXR with no kind.
    const std::string other_path = kDir + "/other.exr";
    {
        float pixel[3] = {0.1f, 0.2f, 0.3f};
        auto out = OIIO::ImageOutput::create(other_path);
        REQUIRE(out);
        OIIO::ImageSpec spec(1, 1, 3, OIIO::TypeDesc::FLOAT);
        spec.attribute("cmfilter:kind", "moment-pyramid");
        REQUIRE(out->open(other_path, spec));
        REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, pixel));
        REQUIRE(out->close());
    }
    auto other = load_stack_fit(other_path);
    REQUIRE_FALSE(other);
    CHECK(other.error().kind == ErrorKind::BadInput);
    CHECK(contains(other.error().message, "other.exr' is not a fit of an image stack (cmfilter:kind is "
                                          "'moment-pyramid', expected 'linear-fit' or 'lafortune-fit'"));
    auto missing = load_stack_fit(kDir + "/no-such-fit.exr");
    REQUIRE_FALSE(missing);
    CHECK(missing.error().kind == ErrorKind::Io);
}

TEST_CASE("stack fit: a Lafortune fit relit at its view and at others is the paper's formula, a PTM holds one view")
{
    const StackFit fit{paper_fit()};
    const Vec3 views[] = {kFittedView, normalize(Vec3{0, 0, 1}), normalize(Vec3{-0.5, 0.2, 0.6}),
                          normalize(Vec3{0.7, 0.7, 0.2})};
    for (const Vec3& w : views)
        for (const Vec3& u : kLights) {
            CAPTURE(w.x);
            CAPTURE(u.x);
            auto relit = relight_stack_fit(fit, u, w, 2);
            REQUIRE(relit);
            REQUIRE(relit->size() == 6);
            for (int t = 0; t < 2; ++t)
                for (int c = 0; c < 3; ++c) {
                    const double expected = paper_value(t, c, u, w);
                    CHECK(std::abs((*relit)[t * 3 + c] - expected) <= 2e-6 * std::abs(expected) + 1e-7);
                }
        }
    // No view: the fitted one.
    auto own = relight_stack_fit(fit, kLights[1]);
    REQUIRE(own);
    for (int t = 0; t < 2; ++t) CHECK(std::abs((*own)[t * 3] - paper_value(t, 0, kLights[1], kFittedView)) <= 1e-6);

    const LinearFit linear = small_linear_fit();
    const StackFit linear_fit{linear};
    auto other_view = relight_stack_fit(linear_fit, kLights[0], normalize(Vec3{0.5, 0, 0.866}));
    REQUIRE_FALSE(other_view);
    CHECK(other_view.error().kind == ErrorKind::BadInput);
    CHECK(contains(other_view.error().message, "a PTM/HSH holds one view"));
    // The zenith, or no view, is the PTM itself: a0 lu^2 + a1 lv^2 + a2 lu lv + a3 lu + a4 lv + a5.
    for (const std::optional<Vec3>& view : {std::optional<Vec3>{}, std::optional<Vec3>{Vec3{0, 0, 1}}}) {
        auto relit = relight_stack_fit(linear_fit, kLights[2], view);
        REQUIRE(relit);
        const Vec3& u = kLights[2];
        for (int t = 0; t < 2; ++t)
            for (int c = 0; c < 3; ++c) {
                const float* a = linear.coefficients.data() + t * 18 + c * 6;
                const double ptm = a[0] * u.x * u.x + a[1] * u.y * u.y + a[2] * u.x * u.y + a[3] * u.x + a[4] * u.y +
                                   a[5];
                CHECK(std::abs((*relit)[t * 3 + c] - ptm) <= 1e-6);
            }
    }
}

TEST_CASE("stack fit: the error streamed from a stack's files at a view, against a brute-force RMSE")
{
    // A stack of float EXRs at the lights: the paper's values at the view
    // `seen` plus a known offset per light, texel and channel.
    const Vec3 seen = normalize(Vec3{-0.4, 0.3, 0.8});
    const int n = static_cast<int>(kLights.size());
    std::string lp = std::to_string(n) + "\n";
    std::vector<float> images;
    for (int k = 0; k < n; ++k) {
        std::vector<float> image(6);
        for (int t = 0; t < 2; ++t)
            for (int c = 0; c < 3; ++c)
                image[t * 3 + c] =
                    static_cast<float>(paper_value(t, c, kLights[k], seen) + 0.01 * ((k + 2 * t + c) % 5));
        const std::string file = "err-" + std::to_string(k) + ".exr";
        cmfilter_test::write_image(kDir + "/" + file, 2, 1, 3, OIIO::TypeDesc::FLOAT, image.data());
        images.insert(images.end(), image.begin(), image.end());
        lp += file + " " + std::to_string(kLights[k].x) + " " + std::to_string(kLights[k].y) + " " +
              std::to_string(kLights[k].z) + "\n";
    }
    const std::string lp_path = kDir + "/err.lp";
    std::ofstream(lp_path) << lp;

    const auto config = cmfilter_test::builtin_color_config();
    StackLoadOptions load;
    load.light_file = lp_path;
    const StackFit fit{paper_fit()};
    // Brute force: the light file's directions as written (6 decimals), the
    // images' floats, the paper's model in double at `view`.
    auto brute_rmse = [&](const Vec3& view) {
        auto lights = read_light_file(lp_path);
        REQUIRE(lights);
        double sum = 0;
        for (int k = 0; k < n; ++k)
            for (int t = 0; t < 2; ++t)
                for (int c = 0; c < 3; ++c) {
                    const double d = paper_value(t, c, lights->lights[k].direction, view) - images[k * 6 + t * 3 + c];
                    sum += d * d;
                }
        return std::sqrt(sum / (n * 6));
    };
    for (const Vec3& view : {seen, kFittedView}) {
        auto e = stack_fit_error(fit, load, config, 2, view);
        REQUIRE(e);
        CHECK(e->lights == n);
        const double expected = brute_rmse(view);
        CHECK(std::abs(e->rmse - expected) <= 1e-5 * expected);
    }
    // No view: the fitted one, as lafortune_relight_error on the stack held.
    auto streamed = stack_fit_error(fit, load, config, 3);
    REQUIRE(streamed);
    auto held_stack = load_image_stack(load, config);
    REQUIRE(held_stack);
    auto held = lafortune_relight_error(std::get<LafortuneFit>(fit), *held_stack, config, 1);
    REQUIRE(held);
    CHECK(streamed->rmse == held->rmse);
    CHECK(streamed->delta_e.max == held->delta_e.max);
    CHECK(std::abs(streamed->rmse - brute_rmse(kFittedView)) <= 1e-5 * streamed->rmse);

    // A linear fit compared at another view is refused; at its own it is measured.
    const StackFit linear{small_linear_fit()};
    auto refused = stack_fit_error(linear, load, config, 1, seen);
    REQUIRE_FALSE(refused);
    CHECK(contains(refused.error().message, "a PTM/HSH holds one view"));
    CHECK(static_cast<bool>(stack_fit_error(linear, load, config, 1)));
}
