// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/relight_error.h"

#include "cmfilter/color/ciede2000.h"
#include "cmfilter/stack/stack_encoding.h"
#include "cmfilter/stack/streamed_error_summary.h"
#include "cmfilter/util/parallel_for.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <optional>
#include <sstream>

namespace cmfilter {

namespace {

Rgb colour_at(const float* v, int channels) { return channels >= 3 ? Rgb{v[0], v[1], v[2]} : Rgb{v[0], v[0], v[0]}; }

// One light's error: the fit relit at `light` against `image` (texels x
// channels values in `encoding`), both in scene-linear; CIEDE2000 per texel
// into `delta_e`.
struct LightError {
    double squared = 0;  // sum of squared differences
    double rmse = 0;
    double delta_e_mean = 0;
};

Expected<LightError> light_error(const RelitModel& fit, const Vec3& light, const float* image, StackEncoding encoding,
                                 const ColorConfig& config, double* delta_e)
{
    const std::size_t texels = fit.texels();
    const int ch = fit.channels;
    std::vector<float> model = fit.relight(light);
    std::vector<float> truth(image, image + texels * ch);
    if (auto st = convert_stack_encoding(model, ch, fit.encoding, StackEncoding::SceneLinear, config); !st)
        return st.error();
    if (auto st = convert_stack_encoding(truth, ch, encoding, StackEncoding::SceneLinear, config); !st)
        return st.error();
    double sum = 0, de_sum = 0;
    for (std::size_t t = 0; t < texels; ++t) {
        for (int c = 0; c < ch; ++c) {
            const double d = double(model[t * ch + c]) - truth[t * ch + c];
            sum += d * d;
        }
        const double de = ciede2000_linear_rgb(colour_at(&model[t * ch], ch), colour_at(&truth[t * ch], ch));
        delta_e[t] = de;
        de_sum += de;
    }
    LightError out;
    out.squared = sum;
    out.rmse = std::sqrt(sum / (texels * ch));
    out.delta_e_mean = de_sum / texels;
    return out;
}

Status check_same_shape(const RelitModel& fit, const std::string& light_file, int width, int height, int channels)
{
    if (fit.width != width || fit.height != height || fit.channels != channels) {
        std::ostringstream msg;
        msg << fit.what << " is " << fit.width << "x" << fit.height << " with " << fit.channels
            << " channels but the stack '" << light_file << "' is " << width << "x" << height << " with " << channels
            << "; expected the same size and channels";
        return bad_input(msg.str());
    }
    return ok();
}

}  // namespace

RelitModel linear_relit_model(const LinearFit& fit)
{
    RelitModel model;
    model.width = fit.width;
    model.height = fit.height;
    model.channels = fit.channels;
    model.encoding = fit.encoding;
    model.relight = [&fit](const Vec3& light) { return relight(fit, light, 1); };
    return model;
}

Expected<RelightError> relight_error(const LinearFit& fit, const ImageStack& reference, const ColorConfig& config,
                                     int threads)
{
    return relit_model_error(linear_relit_model(fit), reference, config, threads);
}

Expected<RelightError> relight_error_from_files(const LinearFit& fit, const StackLoadOptions& reference,
                                                const ColorConfig& config, int threads)
{
    return relit_model_error_from_files(linear_relit_model(fit), reference, config, threads);
}

Expected<RelightError> relit_model_error(const RelitModel& fit, const ImageStack& reference, const ColorConfig& config,
                                         int threads)
{
    if (auto st = check_same_shape(fit, reference.light_file, reference.width, reference.height, reference.channels);
        !st)
        return st.error();
    const int n = reference.count();
    const std::size_t texels = reference.texels();
    const int ch = reference.channels;
    RelightError out;
    out.lights = n;
    out.light_rmse.assign(n, 0.0);
    out.light_delta_e.assign(n, 0.0);
    std::vector<double> delta_e(texels * n);
    std::vector<double> squared(n, 0.0);
    std::vector<std::optional<Error>> errors(n);
    // One light at a time per thread; each relights its image whole.
    parallel_for(n, threads, [&](int k) {
        auto e = light_error(fit, reference.lights[k], reference.image(k), reference.encoding, config,
                             delta_e.data() + k * texels);
        if (!e) {
            errors[k] = e.error();
            return;
        }
        squared[k] = e->squared;
        out.light_rmse[k] = e->rmse;
        out.light_delta_e[k] = e->delta_e_mean;
    });
    for (int k = 0; k < n; ++k)
        if (errors[k]) return *errors[k];
    double total = 0;
    for (double s : squared) total += s;
    out.rmse = std::sqrt(total / (double(texels) * ch * n));
    out.delta_e = summarize_errors(std::move(delta_e));
    return out;
}

Expected<RelightError> relit_model_error_from_files(const RelitModel& fit, const StackLoadOptions& reference,
                                                    const ColorConfig& config, int threads)
{
    auto light_file = read_light_file(reference.light_file);
    if (!light_file) return light_file.error();
    const LightFile& lp = *light_file;
    if (auto st = check_stack_light_count(lp); !st) return st.error();
    const int n = static_cast<int>(lp.lights.size());
    std::vector<std::string> images;
    for (int k = 0; k < n; ++k) images.push_back(lp.image_path(k));
    const std::size_t texels = fit.texels();
    const int ch = fit.channels;

    RelightError out;
    out.lights = n;
    out.light_rmse.assign(n, 0.0);
    out.light_delta_e.assign(n, 0.0);
    std::vector<double> squared(n, 0.0);
    StreamedErrorSummary summary;

    // One reading of the images, `in_flight` at a time, each relit and
    // compared on its own thread; their differences fed to the summary in
    // index order. The first failure by index is the one reported.
    const int in_flight = std::max(1, std::min(resolve_thread_count(threads), n));
    std::vector<std::vector<double>> delta_e(static_cast<std::size_t>(in_flight));
    auto read_pass = [&]() -> Status {
        for (int k0 = 0; k0 < n; k0 += in_flight) {
            const int count = std::min(in_flight, n - k0);
            std::mutex mutex;
            std::optional<std::pair<int, Error>> failure;
            auto fail = [&](int k, Error e) {
                std::lock_guard<std::mutex> lock(mutex);
                if (!failure || k < failure->first) failure.emplace(k, std::move(e));
            };
            parallel_for(count, in_flight, [&](int i) {
                const int k = k0 + i;
                auto img = load_stack_image(images[k], reference, config);
                if (!img) return fail(k, img.error());
                // The first image against the fit; the others against the
                // first (which matches the fit), as load_image_stack does.
                const Status shape =
                    k == 0
                        ? check_same_shape(fit, lp.path, img->data.width, img->data.height, img->data.channels)
                        : check_stack_image_shape(images[k], img->data, images[0], fit.width, fit.height, fit.channels);
                if (!shape) return fail(k, shape.error());
                std::vector<double>& de = delta_e[static_cast<std::size_t>(i)];
                de.resize(texels);
                auto e = light_error(fit, lp.lights[k].direction, img->data.pixels.data(), reference.encoding, config,
                                     de.data());
                if (!e) return fail(k, e.error());
                squared[k] = e->squared;
                out.light_rmse[k] = e->rmse;
                out.light_delta_e[k] = e->delta_e_mean;
            });
            if (failure) return failure->second;
            for (int i = 0; i < count; ++i) summary.add(delta_e[static_cast<std::size_t>(i)].data(), texels);
        }
        return ok();
    };
    do {
        if (auto st = read_pass(); !st) return st.error();
    } while (!summary.end_pass());
    double total = 0;
    for (double s : squared) total += s;
    out.rmse = std::sqrt(total / (double(texels) * ch * n));
    out.delta_e = summary.summary();
    return out;
}

}  // namespace cmfilter
