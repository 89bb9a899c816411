// SPDX-License-Identifier: Apache-2.0
// The Lafortune fit's artefacts under uneven light sampling (the second
// paper, sec. 5), measured: a training stack is fitted (luminance with 1, 2
// and 3 lobes and auto, RGB with 2; and HSH 3, the best linear model, for
// comparison) and every fit is relit at the training lights and at a
// held-out stack's lights (RMSE and CIEDE2000, lafortune_relight_error.h).
// Then, for the fit named by --detail: the error per held-out light with
// its azimuth, elevation and the training lights near it (how densely the
// training dome covers it), and the error by the true value's luminance
// (dark, shadowed texels against lit ones).
//   cmfilter-lafortune-artefacts TRAIN.lp HELD.lp [--density DEG] [--cap F]
//       [--penalty P] [--relative EPS] [--fits lum1,lum2,lum3,auto,rgb2,hsh3]
//       [--detail NAME] [--images DIR] [--threads N]
// --images DIR writes, for the fit with the largest held-out CIEDE2000 mean
// at the held-out light where it is largest: truth.png, model.png,
// model.exr, delta-e.png (heat map of that light's CIEDE2000, white at
// 10) and mean-delta-e.png (each texel's mean over the held-out lights).
#include "bench_timing.h"

#include "cmfilter/color/ciede2000.h"
#include "cmfilter/color/color_config.h"
#include "cmfilter/io/rgb_image_file.h"
#include "cmfilter/ops/error_heatmap.h"
#include "cmfilter/stack/image_stack.h"
#include "cmfilter/stack/lafortune_error.h"
#include "cmfilter/stack/lafortune_fit.h"
#include "cmfilter/stack/linear_fit.h"
#include "cmfilter/stack/relight_error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using namespace cmfilter;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kNearDegrees = 20;  // "training lights near a held-out light"

[[noreturn]] void fail(const std::string& message)
{
    std::fprintf(stderr, "cmfilter-lafortune-artefacts: %s\n", message.c_str());
    std::exit(3);
}

template <class T>
T take(Expected<T> value)
{
    if (!value) fail(value.error().message);
    return std::move(*value);
}

double degrees_between(const Vec3& a, const Vec3& b)
{
    return std::acos(std::clamp(dot(normalize(a), normalize(b)), -1.0, 1.0)) * 180 / kPi;
}

double luminance(const float* v, int channels)
{
    return channels >= 3 ? 0.2126 * v[0] + 0.7152 * v[1] + 0.0722 * v[2] : v[0];
}

Rgb colour_at(const float* v, int channels) { return channels >= 3 ? Rgb{v[0], v[1], v[2]} : Rgb{v[0], v[0], v[0]}; }

// One fitted model: its name, how it relights, its errors.
struct Model {
    std::string name;
    std::function<std::vector<float>(const Vec3&)> relight;
    double ms = 0;
    std::string notes;
    RelightError train, held;
    // Per held-out light and texel: CIEDE2000.
    std::vector<double> held_delta_e;
};

std::vector<std::string> split(const std::string& list)
{
    std::vector<std::string> out;
    std::stringstream s(list);
    for (std::string item; std::getline(s, item, ',');)
        if (!item.empty()) out.push_back(item);
    return out;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 3) fail("usage: TRAIN.lp HELD.lp [options] (see the source's header)");
    LafortuneFitOptions base;
    std::string fits = "lum1,lum2,lum3,auto,rgb2,hsh3", detail = "auto", images;
    int threads = 0;
    for (int i = 3; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) fail(a + " needs a value");
            return argv[++i];
        };
        if (a == "--density") base.density_radius = std::atof(next().c_str());
        else if (a == "--cap") base.spacing_cap = std::atof(next().c_str());
        else if (a == "--penalty") base.exponent_penalty = std::atof(next().c_str());
        else if (a == "--relative") base.relative_epsilon = std::atof(next().c_str());
        else if (a == "--fits") fits = next();
        else if (a == "--detail") detail = next();
        else if (a == "--images") images = next();
        else if (a == "--threads") threads = std::atoi(next().c_str());
        else fail("unknown option " + a);
    }
    base.threads = threads;
    const ColorConfig config = take(ColorConfig::load(""));
    StackLoadOptions load;
    load.light_file = argv[1];
    const ImageStack train = take(load_image_stack(load, config));
    load.light_file = argv[2];
    const ImageStack held = take(load_image_stack(load, config));
    if (train.encoding != StackEncoding::SceneLinear || held.encoding != StackEncoding::SceneLinear)
        fail("expected scene-linear stacks");
    const std::size_t texels = train.texels();
    const int ch = train.channels;

    std::printf("training: %s (%d lights), held out: %s (%d lights), %d x %d\n", argv[1], train.count(), argv[2],
                held.count(), train.width, train.height);
    std::printf("options: density_radius %g, spacing_cap %g (most exponent %.1f), exponent_penalty %g, "
                "relative_epsilon %g\n\n",
                base.density_radius, base.spacing_cap, lafortune_max_exponent(train.lights, base),
                base.exponent_penalty, base.relative_epsilon);

    std::vector<Model> models;
    for (const std::string& name : split(fits)) {
        Model m;
        m.name = name;
        if (name == "hsh3") {
            LinearFitOptions o;
            o.model = LinearModel::Hsh3;
            o.threads = threads;
            auto fit = std::make_shared<LinearFit>();
            m.ms = cmfilter_bench::fastest_ms(1, [&] { *fit = take(fit_linear(train, o)); });
            m.relight = [fit, threads](const Vec3& l) { return relight(*fit, l, threads); };
            m.train = take(relight_error(*fit, train, config, threads));
            m.held = take(relight_error(*fit, held, config, threads));
        } else {
            LafortuneFitOptions o = base;
            if (name == "rgb2") {
                o.variant = LafortuneVariant::Rgb;
                o.lobes = 2;
            } else if (name == "auto") {
                o.lobes = kLafortuneMaxLuminanceLobes;
                o.auto_lobes = true;
            } else if (name.rfind("lum", 0) == 0) {
                o.lobes = std::atoi(name.c_str() + 3);
            } else {
                fail("unknown fit " + name);
            }
            auto fit = std::make_shared<LafortuneFit>();
            m.ms = cmfilter_bench::fastest_ms(1, [&] { *fit = take(fit_lafortune(train, o)); });
            m.relight = [fit, threads](const Vec3& l) { return relight_lafortune(*fit, l, threads); };
            m.train = take(lafortune_relight_error(*fit, train, config, threads));
            m.held = take(lafortune_relight_error(*fit, held, config, threads));
            std::ostringstream notes;
            notes << "lobes";
            for (long long n : fit->lobe_histogram()) notes << " " << n;
            // The exponents in use: their median and largest.
            std::vector<float> exponents;
            const int scalars = fit->variant == LafortuneVariant::Rgb ? fit->channels : 1;
            for (std::size_t t = 0; t < fit->texels(); ++t)
                for (int c = 0; c < scalars; ++c) {
                    const float* s = fit->texel(t) + c * fit->scalar_stride();
                    for (int i = 0; i < fit->lobes; ++i)
                        if (s[1 + 4 * i] != 0 || s[2 + 4 * i] != 0 || s[3 + 4 * i] != 0)
                            exponents.push_back(s[4 + 4 * i]);
                }
            if (!exponents.empty()) {
                std::sort(exponents.begin(), exponents.end());
                notes << "; n median " << exponents[exponents.size() / 2] << ", p95 "
                      << exponents[exponents.size() * 95 / 100] << ", max " << exponents.back();
            }
            m.notes = notes.str();
        }
        // Per held-out light and texel CIEDE2000, for the detail and images.
        m.held_delta_e.resize(texels * held.count());
        for (int k = 0; k < held.count(); ++k) {
            const std::vector<float> relit = m.relight(held.lights[k]);
            for (std::size_t t = 0; t < texels; ++t)
                m.held_delta_e[k * texels + t] =
                    ciede2000_linear_rgb(colour_at(&relit[t * ch], ch), colour_at(held.image(k) + t * ch, ch));
        }
        models.push_back(std::move(m));
    }

    std::printf("| fit | training RMSE | training dE mean | held-out RMSE | held-out dE mean | held-out dE p95 | "
                "held-out dE max | fit ms | notes |\n|---|---|---|---|---|---|---|---|---|\n");
    for (const Model& m : models)
        std::printf("| %s | %.4f | %.2f | %.4f | %.2f | %.2f | %.1f | %.0f | %s |\n", m.name.c_str(), m.train.rmse,
                    m.train.delta_e.mean, m.held.rmse, m.held.delta_e.mean, m.held.delta_e.p95, m.held.delta_e.max,
                    m.ms, m.notes.c_str());

    const auto detailed = std::find_if(models.begin(), models.end(), [&](const Model& m) { return m.name == detail; });
    if (detailed != models.end()) {
        std::printf("\nper held-out light (%s; near: training lights within %g degrees):\n", detail.c_str(),
                    kNearDegrees);
        std::printf("| azimuth | elevation | nearest training light (deg) | near | RMSE | dE mean |");
        for (const Model& m : models)
            if (&m != &*detailed) std::printf(" %s dE |", m.name.c_str());
        std::printf("\n|---|---|---|---|---|---|");
        for (std::size_t i = 1; i < models.size(); ++i) std::printf("---|");
        std::printf("\n");
        for (int k = 0; k < held.count(); ++k) {
            const Vec3 l = held.lights[k];
            double nearest = 180;
            int near = 0;
            for (const Vec3& t : train.lights) {
                const double d = degrees_between(l, t);
                nearest = std::min(nearest, d);
                if (d <= kNearDegrees) ++near;
            }
            std::printf("| %.0f | %.0f | %.1f | %d | %.4f | %.2f |", std::atan2(l.y, l.x) * 180 / kPi,
                        std::asin(std::clamp(l.z, -1.0, 1.0)) * 180 / kPi, nearest, near, detailed->held.light_rmse[k],
                        detailed->held.light_delta_e[k]);
            for (const Model& m : models)
                if (&m != &*detailed) std::printf(" %.2f |", m.held.light_delta_e[k]);
            std::printf("\n");
        }
        // By the true value's luminance at the held-out light.
        const double edges[] = {0, 0.01, 0.03, 0.1, 0.3, 1e30};
        std::printf("\nheld-out dE mean by the true luminance (share of texel-lights):\n| luminance |");
        for (const Model& m : models) std::printf(" %s |", m.name.c_str());
        std::printf(" share |\n|---|");
        for (std::size_t i = 0; i < models.size(); ++i) std::printf("---|");
        std::printf("---|\n");
        for (int b = 0; b + 1 < 6; ++b) {
            std::vector<double> sum(models.size(), 0.0);
            long long count = 0;
            for (int k = 0; k < held.count(); ++k)
                for (std::size_t t = 0; t < texels; ++t) {
                    const double y = luminance(held.image(k) + t * ch, ch);
                    if (!(y >= edges[b] && y < edges[b + 1])) continue;
                    ++count;
                    for (std::size_t i = 0; i < models.size(); ++i) sum[i] += models[i].held_delta_e[k * texels + t];
                }
            if (edges[b + 1] > 1e29) std::printf("| >= %g |", edges[b]);
            else std::printf("| %g - %g |", edges[b], edges[b + 1]);
            for (double s : sum) std::printf(" %.2f |", count ? s / count : 0.0);
            std::printf(" %.1f%% |\n", 100.0 * count / (double(texels) * held.count()));
        }
    }

    if (!images.empty() && !models.empty()) {
        const Model* worst = &models[0];
        for (const Model& m : models)
            if (m.held.delta_e.mean > worst->held.delta_e.mean) worst = &m;
        const int k =
            static_cast<int>(std::max_element(worst->held.light_delta_e.begin(), worst->held.light_delta_e.end()) -
                             worst->held.light_delta_e.begin());
        const std::vector<float> relit = worst->relight(held.lights[k]);
        const std::vector<float> truth(held.image(k), held.image(k) + texels * ch);
        auto rgb = [&](const std::vector<float>& v) {
            std::vector<float> out(texels * 3);
            for (std::size_t t = 0; t < texels; ++t)
                for (int c = 0; c < 3; ++c) out[t * 3 + c] = v[t * ch + std::min(c, ch - 1)];
            return out;
        };
        const ImageAttributes none;
        for (auto [file, values] : {std::pair{"truth.png", &truth}, std::pair{"model.png", &relit}})
            if (auto st = write_rgb_image(images + "/" + file, train.width, train.height, 3, rgb(*values),
                                          train.colorspace, none, config);
                !st)
                fail(st.error().message);
        if (auto st = write_rgb_image(images + "/model.exr", train.width, train.height, ch, relit, train.colorspace,
                                      none, config);
            !st)
            fail(st.error().message);
        std::vector<double> at_light(worst->held_delta_e.begin() + k * texels,
                                     worst->held_delta_e.begin() + (k + 1) * texels);
        std::vector<double> mean(texels, 0.0);
        for (int j = 0; j < held.count(); ++j)
            for (std::size_t t = 0; t < texels; ++t) mean[t] += worst->held_delta_e[j * texels + t] / held.count();
        for (auto [file, values] : {std::pair{"delta-e.png", &at_light}, std::pair{"mean-delta-e.png", &mean}}) {
            HeatmapImage h;
            h.width = train.width;
            h.height = train.height;
            h.errors = values;
            h.max = 10;
            h.description = worst->name + " CIEDE2000";
            if (auto st = write_heatmap_png(images + "/" + file, h); !st) fail(st.error().message);
        }
        const Vec3 l = held.lights[k];
        std::printf("\nimages: %s at held-out light %d (azimuth %.0f, elevation %.0f; dE mean %.2f) in %s\n",
                    worst->name.c_str(), k, std::atan2(l.y, l.x) * 180 / kPi,
                    std::asin(std::clamp(l.z, -1.0, 1.0)) * 180 / kPi, worst->held.light_delta_e[k], images.c_str());
    }
    return 0;
}
