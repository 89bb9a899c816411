// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/render/surface_probe_choice.h"

#include "cmfilter/render/view_pixels.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace cmfilter {

namespace {

Status check_options(const ProbeChoiceOptions& o)
{
    if (auto st = check_view_choice("ProbeChoiceOptions", o.tolerance, o.max_pixels); !st) return st;
    if (auto st = check_render_probes(o.render.max_probes); !st) return st;
    for (std::size_t i = 0; i < o.candidates.size(); ++i)
        if (o.candidates[i] < 1 || o.candidates[i] > o.render.max_probes ||
            (i > 0 && o.candidates[i] <= o.candidates[i - 1]))
            return bad_input("ProbeChoiceOptions::candidates holds " + std::to_string(o.candidates[i]) +
                                 " (expected increasing counts from 1 to the ceiling, RenderOptions::max_probes " +
                                 std::to_string(o.render.max_probes) + ")",
                             "ProbeChoiceOptions::candidates");
    return ok();
}

}  // namespace

Expected<std::vector<SurfaceProbeChoice>>
choose_surface_probes(const Scene& scene, const std::vector<Material>& materials, const ProbeChoiceOptions& options)
{
    if (auto st = check_options(options); !st) return st.error();
    if (materials.size() != scene.surfaces.size())
        return bad_input("choose_surface_probes: " + std::to_string(materials.size()) + " materials for " +
                         std::to_string(scene.surfaces.size()) + " surfaces");
    if (auto st = check_microsurface_methods(options.render.microsurface_methods); !st) return st.error();
    const int ceiling = options.render.max_probes;
    std::vector<int> candidates = options.candidates;
    if (candidates.empty()) {
        for (int p = 1; p < ceiling; p *= 2) candidates.push_back(p);
        candidates.push_back(ceiling);
    }
    auto sampled = sample_surface_pixels(scene, static_cast<std::size_t>(options.max_pixels), options.render.threads);
    if (!sampled) return sampled.error();
    std::optional<HeightMomentTable> table;  // gaussian-exact's, on a microsurface
    if (std::any_of(materials.begin(), materials.end(), is_microsurface)) {
        auto made = HeightMomentTable::create();
        if (!made) return made.error();
        table.emplace(std::move(*made));
    }

    std::vector<SurfaceProbeChoice> out;
    for (std::size_t s = 0; s < materials.size(); ++s) {
        const SurfacePixels& pixels = (*sampled)[s];
        if (pixels.hits.empty()) continue;  // no pixel sees it
        const std::string where = scene.path + ": /surfaces/" + std::to_string(s) + ": ";
        const auto colour_with = [&](int probes) {
            RenderOptions with = options.render;
            with.surface_probes.clear();
            with.max_probes = probes;
            return colour_surface_pixels(scene, materials[s], s, with, table ? &*table : nullptr, pixels.hits);
        };
        auto reference = colour_with(ceiling);
        if (!reference) return prefixed(where, reference.error());
        const LodBands bands = lod_bands(reference->lods);

        ProbeChoice choice;
        static_cast<ViewMeasurement&>(choice) = view_measurement(options.tolerance, pixels, bands);
        choice.ceiling = ceiling;
        for (int probes : candidates) {
            Expected<ColouredPixels> coloured = probes == ceiling ? *reference : colour_with(probes);
            if (!coloured) return prefixed(where, coloured.error());
            ProbeTrial t;
            static_cast<ViewTrial&>(t) = measure_trial(bands, *coloured, *reference, options.tolerance);
            t.probes = probes;
            if (t.meets) choice.chosen = choice.trials.size();
            choice.trials.push_back(std::move(t));
            if (choice.chosen) break;  // more probes cost more: the first that meets is the choice
        }
        out.push_back({s, std::move(choice)});
    }
    return out;
}

}  // namespace cmfilter
