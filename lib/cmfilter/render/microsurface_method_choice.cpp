// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/render/microsurface_method_choice.h"

#include "cmfilter/render/view_pixels.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace cmfilter {

namespace {

Status check_options(const MicrosurfaceChoiceOptions& o)
{
    if (auto st = check_view_choice("MicrosurfaceChoiceOptions", o.tolerance, o.max_pixels); !st) return st;
    if (auto st = check_microsurface_methods(o.candidates); !st)
        return bad_input("MicrosurfaceChoiceOptions::candidates: " + st.error().message,
                         "MicrosurfaceChoiceOptions::candidates");
    return ok();
}

}  // namespace

Expected<std::vector<SurfaceMicrosurfaceChoice>> choose_microsurface_methods(const Scene& scene,
                                                                             const std::vector<Material>& materials,
                                                                             const MicrosurfaceChoiceOptions& options)
{
    if (auto st = check_options(options); !st) return st.error();
    if (materials.size() != scene.surfaces.size())
        return bad_input("choose_microsurface_methods: " + std::to_string(materials.size()) + " materials for " +
                         std::to_string(scene.surfaces.size()) + " surfaces");
    if (std::none_of(materials.begin(), materials.end(), is_microsurface))
        return std::vector<SurfaceMicrosurfaceChoice>{};
    if (auto st = check_render_probes(options.render.max_probes); !st) return st.error();
    auto sampled = sample_surface_pixels(scene, static_cast<std::size_t>(options.max_pixels), options.render.threads);
    if (!sampled) return sampled.error();
    auto table = HeightMomentTable::create();
    if (!table) return table.error();
    const std::vector<RenderMethod> candidates =
        options.candidates.empty() ? std::vector<RenderMethod>{RenderMethod::Naive, RenderMethod::Gaussian,
                                                               RenderMethod::GaussianExact, RenderMethod::Exact}
                                   : options.candidates;

    std::vector<SurfaceMicrosurfaceChoice> out;
    for (std::size_t s = 0; s < materials.size(); ++s) {
        const SurfacePixels& pixels = (*sampled)[s];
        if (!is_microsurface(materials[s]) || pixels.hits.empty()) continue;  // not one, or no pixel sees it
        const std::string where = scene.path + ": /surfaces/" + std::to_string(s) + ": ";
        // Each method alone on this surface (its base layer naive or gaussian).
        const auto colour_by = [&](RenderMethod method) {
            RenderOptions by = options.render;
            by.method = method;
            by.microsurface_methods.clear();
            return colour_surface_pixels(scene, materials[s], s, by, &*table, pixels.hits);
        };
        // The reference first: exact, and each pixel's LOD (geometry: the
        // same for every method).
        auto exact = colour_by(RenderMethod::Exact);
        if (!exact) return prefixed(where, exact.error());
        const LodBands bands = lod_bands(exact->lods);

        MicrosurfaceMethodChoice choice;
        static_cast<ViewMeasurement&>(choice) = view_measurement(options.tolerance, pixels, bands);
        for (RenderMethod method : candidates) {
            Expected<ColouredPixels> coloured = method == RenderMethod::Exact ? *exact : colour_by(method);
            if (!coloured) return prefixed(where, coloured.error());
            MicrosurfaceTrial t;
            static_cast<ViewTrial&>(t) = measure_trial(bands, *coloured, *exact, options.tolerance);
            t.method = method;
            if (t.meets && !choice.chosen) choice.chosen = choice.trials.size();
            choice.trials.push_back(std::move(t));
        }
        out.push_back({s, std::move(choice)});
    }
    return out;
}

}  // namespace cmfilter
