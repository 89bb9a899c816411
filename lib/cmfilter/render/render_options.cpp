// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/render/render_options.h"

namespace cmfilter {

const char* to_string(RenderMethod method)
{
    switch (method) {
    case RenderMethod::Naive: return "naive";
    case RenderMethod::Gaussian: return "gaussian";
    case RenderMethod::GaussianExact: return "gaussian-exact";
    case RenderMethod::Exact: return "exact";
    case RenderMethod::Supersample: return "supersample";
    case RenderMethod::Reference: return "reference";
    case RenderMethod::Mixture: return "mixture";
    case RenderMethod::ColorPyramid: return "color-pyramid";
    case RenderMethod::Segments: return "segments";
    }
    return "gaussian";
}

Expected<RenderMethod> parse_render_method(const std::string& text)
{
    for (RenderMethod m : {RenderMethod::Naive, RenderMethod::Gaussian, RenderMethod::GaussianExact,
                           RenderMethod::Exact, RenderMethod::Supersample, RenderMethod::Reference,
                           RenderMethod::Mixture, RenderMethod::ColorPyramid, RenderMethod::Segments})
        if (text == to_string(m)) return m;
    return bad_input(
        "method '" + text +
        "' is unknown (expected naive, gaussian, gaussian-exact, mixture, color-pyramid, segments, exact, supersample or reference)");
}

Status check_render_samples(int samples)
{
    if (samples < 1 || samples > kMaxSamples)
        return bad_input("RenderOptions::samples " + std::to_string(samples) + " is out of range (expected 1 to " +
                             std::to_string(kMaxSamples) + ")",
                         "RenderOptions::samples");
    return ok();
}

Status check_microsurface_methods(const std::vector<RenderMethod>& methods)
{
    for (std::size_t i = 0; i < methods.size(); ++i) {
        const RenderMethod m = methods[i];
        if (m != RenderMethod::Naive && m != RenderMethod::Gaussian && m != RenderMethod::GaussianExact &&
            m != RenderMethod::Exact)
            return bad_input("RenderOptions::microsurface_methods holds " + std::string(to_string(m)) +
                                 " for surface " + std::to_string(i) +
                                 " (expected naive, gaussian, gaussian-exact or exact)",
                             "RenderOptions::microsurface_methods");
    }
    return ok();
}

Status check_render_probes(int probes)
{
    if (probes < 1 || probes > kMaxProbes)
        return bad_input("RenderOptions::max_probes " + std::to_string(probes) + " is out of range (expected 1 to " +
                             std::to_string(kMaxProbes) + ")",
                         "RenderOptions::max_probes");
    return ok();
}

Status check_surface_probes(const std::vector<int>& probes)
{
    for (std::size_t i = 0; i < probes.size(); ++i)
        if (probes[i] < 0 || probes[i] > kMaxProbes)
            return bad_input("RenderOptions::surface_probes holds " + std::to_string(probes[i]) + " for surface " +
                                 std::to_string(i) + " (expected 0 to " + std::to_string(kMaxProbes) + ")",
                             "RenderOptions::surface_probes");
    return ok();
}

int max_probes_of(const RenderOptions& options, std::size_t surface)
{
    return surface < options.surface_probes.size() && options.surface_probes[surface] > 0
               ? options.surface_probes[surface]
               : options.max_probes;
}

}  // namespace cmfilter
