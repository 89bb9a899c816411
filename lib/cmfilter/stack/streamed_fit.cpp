// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/streamed_fit.h"

#include "cmfilter/stack/light_matrix.h"
#include "cmfilter/util/parallel_for.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <optional>

namespace cmfilter {

namespace {

// Texels per task of the accumulation (fixed, so the blocks do not depend
// on the thread count).
constexpr std::size_t kBlockTexels = 4096;

// The layout of a texel's accumulators: channel c's P I_c at
// [c * terms + j]; PtmLrgb adds sum_k I_{c,k} at [channels * terms + c] and
// sum_k Y_k^2 at [channels * (terms + 1)].
struct Accumulators {
    int terms = 0, channels = 0;
    bool lrgb = false;
    int stride() const { return channels * terms + (lrgb ? channels + 1 : 0); }
};

// Adds image `pixels` (light k's column `column` of P) to the accumulators
// of texels [first, last).
template <int Terms>
void accumulate_image(const Accumulators& layout, const float* pixels, const double* column,
                      const std::array<double, 3>& weights, std::size_t first, std::size_t last, double* acc)
{
    const int ch = layout.channels;
    const std::size_t stride = static_cast<std::size_t>(layout.stride());
    double p[Terms];
    for (int j = 0; j < Terms; ++j) p[j] = column[j];
    for (std::size_t t = first; t < last; ++t) {
        const float* v = pixels + t * ch;
        double* a = acc + t * stride;
        for (int c = 0; c < ch; ++c) {
            const double x = v[c];
            for (int j = 0; j < Terms; ++j) a[c * Terms + j] += p[j] * x;
        }
        if (layout.lrgb) {
            double y = weights[0] * double(v[0]);
            for (int c = 1; c < ch; ++c) y += weights[c] * double(v[c]);
            for (int c = 0; c < ch; ++c) a[ch * Terms + c] += v[c];
            a[ch * (Terms + 1)] += y * y;
        }
    }
}

void accumulate(const Accumulators& layout, const float* pixels, const double* column,
                const std::array<double, 3>& weights, std::size_t first, std::size_t last, double* acc)
{
    switch (layout.terms) {
    case 4: return accumulate_image<4>(layout, pixels, column, weights, first, last, acc);
    case 6: return accumulate_image<6>(layout, pixels, column, weights, first, last, acc);
    case 9: return accumulate_image<9>(layout, pixels, column, weights, first, last, acc);
    }
}

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

// A PtmLrgb texel's coefficients from its accumulators (streamed_fit.h):
// the luminance polynomial a = sum_c w_c G_c, then the base colour
// c = (W a) . (W G_c) / |W a|^2, or where |W a|^2 is negligible (below
// 1e-12 of sum_k Y_k^2, or 1e-30) the mean colour over the mean luminance,
// or 0 (linear_fit.h).
void lrgb_texel(const Accumulators& layout, const double* acc, const Matrix6d& w, const std::array<double, 3>& weights,
                int lights, float* out)
{
    constexpr int terms = 6;
    const int ch = layout.channels;
    Vector6d a = Vector6d::Zero();
    for (int c = 0; c < ch; ++c) a += weights[c] * Eigen::Map<const Vector6d>(acc + c * terms);
    const Vector6d wa = w * a;
    const double energy = wa.squaredNorm();
    const double own = acc[ch * (terms + 1)];
    const bool usable = energy > 1e-30 && energy > 1e-12 * own;
    double mean_luminance = 0;
    for (int c = 0; c < ch; ++c) mean_luminance += weights[c] * (acc[ch * terms + c] / lights);
    for (int k = 0; k < terms; ++k) out[k] = static_cast<float>(a(k));
    for (int c = 0; c < ch; ++c) {
        double base = 0;
        if (usable) base = wa.dot(w * Eigen::Map<const Vector6d>(acc + c * terms)) / energy;
        else if (std::abs(mean_luminance) > 1e-30) base = (acc[ch * terms + c] / lights) / mean_luminance;
        out[terms + c] = static_cast<float>(base);
    }
}

}  // namespace

Expected<LinearFit> fit_linear_from_files(const StackLoadOptions& load, const LinearFitOptions& options,
                                          const ColorConfig& config, const std::function<void(double)>& progress)
{
    auto light_file = read_light_file(load.light_file);
    if (!light_file) return light_file.error();
    const LightFile& lp = *light_file;
    if (auto st = check_stack_light_count(lp); !st) return st.error();
    const int n = static_cast<int>(lp.lights.size());
    std::vector<Vec3> lights;
    std::vector<std::string> images;
    for (int k = 0; k < n; ++k) {
        lights.push_back(lp.lights[k].direction);
        images.push_back(lp.image_path(k));
    }

    // The light set before any image (fit_linear's checks and messages).
    const std::string where = "image stack '" + lp.path + "': ";
    auto conditioning = check_light_set(lights, options.model, options.singular_threshold);
    if (!conditioning) {
        if (conditioning.error().field == "LinearFitOptions::singular_threshold") return conditioning.error();
        return prefixed(where, conditioning.error());
    }
    const LightPseudoInverse inverse = light_pseudo_inverse(lights, options.model, options.singular_threshold);
    // P's columns contiguous: light k's at p.data() + k * terms.
    const Eigen::MatrixXd& p = inverse.p;

    // The first image fixes the size and channels.
    auto first = load_stack_image(images[0], load, config);
    if (!first) return first.error();
    LinearFit fit;
    fit.model = options.model;
    fit.width = first->data.width;
    fit.height = first->data.height;
    fit.channels = first->data.channels;
    fit.encoding = load.encoding;
    fit.colorspace = stack_colorspace(first->space, load, config);
    fit.conditioning = *conditioning;
    if (options.model == LinearModel::PtmLrgb && fit.channels != 1 && fit.channels != 3)
        return bad_input("LinearFitOptions::model ptm-lrgb fits a luminance and a base colour of 1 or 3 channels; " +
                             where.substr(0, where.size() - 2) + " has " + std::to_string(fit.channels),
                         "LinearFitOptions::model");

    Accumulators layout;
    layout.terms = fit.terms();
    layout.channels = fit.channels;
    layout.lrgb = options.model == LinearModel::PtmLrgb;
    std::array<double, 3> weights = {1.0, 0.0, 0.0};
    if (layout.lrgb && fit.channels == 3) weights = {kRec709Luminance[0], kRec709Luminance[1], kRec709Luminance[2]};
    const std::size_t texels = fit.texels();
    const std::size_t acc_stride = static_cast<std::size_t>(layout.stride());
    std::vector<double> acc(texels * acc_stride, 0.0);
    const int blocks = static_cast<int>((texels + kBlockTexels - 1) / kBlockTexels);

    // Adds images [k0, k0 + batch.size()) to every texel, in index order.
    auto add = [&](int k0, const std::vector<std::optional<StackImage>>& batch) {
        parallel_for(blocks, options.threads, [&](int b) {
            const std::size_t lo = static_cast<std::size_t>(b) * kBlockTexels;
            const std::size_t hi = std::min(texels, lo + kBlockTexels);
            for (std::size_t i = 0; i < batch.size(); ++i)
                accumulate(layout, batch[i]->data.pixels.data(),
                           p.data() + static_cast<std::size_t>(k0 + static_cast<int>(i)) * layout.terms, weights, lo,
                           hi, acc.data());
        });
        if (progress) progress(double(k0 + static_cast<int>(batch.size())) / n);
    };
    {
        std::vector<std::optional<StackImage>> batch(1);
        batch[0].emplace(std::move(*first));
        add(0, batch);
    }

    // The rest, a bounded number in flight, read in parallel; the first
    // failure by index is the one reported, as load_image_stack does.
    const int in_flight = std::max(1, std::min(resolve_thread_count(load.threads), n - 1));
    for (int k0 = 1; k0 < n; k0 += in_flight) {
        const int count = std::min(in_flight, n - k0);
        std::vector<std::optional<StackImage>> batch(static_cast<std::size_t>(count));
        std::mutex mutex;
        std::optional<std::pair<int, Error>> failure;
        parallel_for(count, load.threads, [&](int i) {
            const int k = k0 + i;
            auto img = load_stack_image(images[k], load, config);
            Status st =
                img ? check_stack_image_shape(images[k], img->data, images[0], fit.width, fit.height, fit.channels)
                    : Status(img.error());
            if (!st) {
                std::lock_guard<std::mutex> lock(mutex);
                if (!failure || k < failure->first) failure.emplace(k, st.error());
                return;
            }
            batch[static_cast<std::size_t>(i)].emplace(std::move(*img));
        });
        if (failure) return failure->second;
        add(k0, batch);
    }

    // The coefficients from the accumulators.
    const int stride = fit.stride();
    Matrix6d w = Matrix6d::Zero();
    if (layout.lrgb) w = inverse.w;  // 6 x 6: PtmLrgb's polynomial
    fit.coefficients.assign(texels * static_cast<std::size_t>(stride), 0.0f);
    parallel_for(blocks, options.threads, [&](int b) {
        const std::size_t lo = static_cast<std::size_t>(b) * kBlockTexels;
        const std::size_t hi = std::min(texels, lo + kBlockTexels);
        for (std::size_t t = lo; t < hi; ++t) {
            const double* a = acc.data() + t * acc_stride;
            float* out = fit.coefficients.data() + t * stride;
            if (layout.lrgb) lrgb_texel(layout, a, w, weights, n, out);
            else
                for (int i = 0; i < stride; ++i) out[i] = static_cast<float>(a[i]);
        }
    });
    return fit;
}

}  // namespace cmfilter
