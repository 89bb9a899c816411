// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/lafortune_error.h"

#include "cmfilter/color/ciede2000.h"
#include "cmfilter/stack/lafortune_fit.h"
#include "cmfilter/stack/stack_encoding.h"
#include "cmfilter/util/parallel_for.h"

#include <cmath>
#include <sstream>

namespace cmfilter {

namespace {

Rgb colour_at(const float* v, int channels) { return channels >= 3 ? Rgb{v[0], v[1], v[2]} : Rgb{v[0], v[0], v[0]}; }

}  // namespace

Expected<RelightError> lafortune_relight_error(const LafortuneFit& fit, const ImageStack& reference,
                                               const ColorConfig& config, int threads)
{
    if (fit.width != reference.width || fit.height != reference.height || fit.channels != reference.channels) {
        std::ostringstream msg;
        msg << "the Lafortune fit is " << fit.width << "x" << fit.height << " with " << fit.channels
            << " channels but the stack '" << reference.light_file << "' is " << reference.width << "x"
            << reference.height << " with " << reference.channels << "; expected the same size and channels";
        return bad_input(msg.str());
    }
    const int n = reference.count();
    const std::size_t texels = reference.texels();
    const int ch = reference.channels;
    RelightError out;
    out.lights = n;
    out.light_rmse.assign(n, 0.0);
    out.light_delta_e.assign(n, 0.0);
    std::vector<double> delta_e(texels * n);
    std::vector<double> squared(n, 0.0);
    std::vector<Error> errors(n);
    std::vector<char> failed(n, 0);
    parallel_for(n, threads, [&](int k) {
        std::vector<float> model = relight_lafortune(fit, reference.lights[k], 1);
        std::vector<float> truth(reference.image(k), reference.image(k) + texels * ch);
        for (auto [values, encoding] : {std::pair{&model, fit.encoding}, std::pair{&truth, reference.encoding}})
            if (auto st = convert_stack_encoding(*values, ch, encoding, StackEncoding::SceneLinear, config); !st) {
                errors[k] = st.error();
                failed[k] = 1;
                return;
            }
        double sum = 0, de_sum = 0;
        for (std::size_t t = 0; t < texels; ++t) {
            for (int c = 0; c < ch; ++c) {
                const double d = double(model[t * ch + c]) - truth[t * ch + c];
                sum += d * d;
            }
            const double de = ciede2000_linear_rgb(colour_at(&model[t * ch], ch), colour_at(&truth[t * ch], ch));
            delta_e[k * texels + t] = de;
            de_sum += de;
        }
        squared[k] = sum;
        out.light_rmse[k] = std::sqrt(sum / (texels * ch));
        out.light_delta_e[k] = de_sum / texels;
    });
    for (int k = 0; k < n; ++k)
        if (failed[k]) return errors[k];
    double total = 0;
    for (double s : squared) total += s;
    out.rmse = std::sqrt(total / (double(texels) * ch * n));
    out.delta_e = summarize_errors(std::move(delta_e));
    return out;
}

}  // namespace cmfilter
