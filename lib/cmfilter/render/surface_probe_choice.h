// SPDX-License-Identifier: Apache-2.0
// The fewest anisotropic probes (anisotropic_probes.h) each surface of a
// scene needs for a colour-difference tolerance, measured on the view:
// render --method auto's last choice, made after each surface's method.
//
// Probes cost in proportion to their count on every pixel whose footprint
// is longer than wide (on a ground plane, most of them towards the horizon);
// the render's max_probes is their ceiling, where the error against the
// ray-traced reference stops falling (16 by default, docs/render.md). Over
// the pixels view_pixels.h samples on each surface (up to max_pixels, spread
// evenly over the whole frame's pixels whose centre ray hits it), the
// surface is coloured as the render colours it (its own method and
// sub-footprints) with each candidate count and compared with the same at
// the ceiling: the mean CIEDE2000 per LOD band of the ceiling's pixels (the
// integer part of the LOD AOV), the worst band deciding. Candidates are
// tried fewest first (1, 2, 4, ... below the ceiling, then the ceiling,
// which meets by definition); the choice is the first that meets the
// tolerance. The error this bounds is the probes' alone, beside what the
// method's choice measured (its own tolerance, against its own reference).
#pragma once

#include "cmfilter/render/render_options.h"
#include "cmfilter/render/view_pixels.h"
#include "cmfilter/scene/scene.h"
#include "cmfilter/scene/scene_materials.h"
#include "cmfilter/util/error.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace cmfilter {

struct ProbeChoiceOptions {
    double tolerance = 1.0;  // mean CIEDE2000 in every LOD band; finite and > 0
    // Probe counts tried, in increasing order, each 1 .. render.max_probes;
    // empty: 1, 2, 4, ... below render.max_probes, then render.max_probes.
    std::vector<int> candidates;
    int max_pixels = 4096;  // per surface, >= 1
    // The render the choice is for: its method, per-surface choices,
    // footprint, masking, slope shading and threads are used, and its
    // max_probes is the ceiling measured against; its region and
    // surface_probes are not (the whole frame is measured).
    RenderOptions render;
};

struct ProbeTrial : ViewTrial {
    int probes = 1;
};

struct ProbeChoice : ViewMeasurement {
    int ceiling = 0;                    // the render's max_probes: the reference
    std::vector<ProbeTrial> trials;     // fewest probes first, up to the one chosen
    std::optional<std::size_t> chosen;  // the first that meets; none when none does

    const ProbeTrial* choice() const { return chosen ? &trials[*chosen] : nullptr; }
};

struct SurfaceProbeChoice {
    std::size_t surface = 0;
    ProbeChoice choice;
};

// One choice per surface some pixel's centre ray hits, in surface order.
// BadInput naming ProbeChoiceOptions' field for a tolerance, candidate or
// pixel count out of range, RenderOptions' for a ceiling or per-surface
// choice out of range, or for materials that do not match the scene.
Expected<std::vector<SurfaceProbeChoice>>
choose_surface_probes(const Scene& scene, const std::vector<Material>& materials, const ProbeChoiceOptions& options);

}  // namespace cmfilter
