// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/lafortune_error.h"

#include "cmfilter/stack/lafortune_fit.h"

namespace cmfilter {

RelitModel lafortune_relit_model(const LafortuneFit& fit, const Vec3& view)
{
    RelitModel model;
    model.width = fit.width;
    model.height = fit.height;
    model.channels = fit.channels;
    model.encoding = fit.encoding;
    model.relight = [&fit, view](const Vec3& light) { return relight_lafortune(fit, light, view, 1); };
    model.what = "the Lafortune fit";
    return model;
}

Expected<RelightError> lafortune_relight_error(const LafortuneFit& fit, const ImageStack& reference,
                                               const ColorConfig& config, int threads)
{
    return relit_model_error(lafortune_relit_model(fit, fit.view), reference, config, threads);
}

}  // namespace cmfilter
