// SPDX-License-Identifier: Apache-2.0
// The cheapest one-ray method each microsurface material of a scene (a
// Gaussian microsurface or a textured displacement, secs. 5-6) needs for a
// colour-difference tolerance, measured on the view itself: render --method
// auto's choice for layered surfaces.
//
// The whole frame's centre rays are traced; of the pixels whose centre ray
// hits the surface, up to max_pixels spread evenly over them in scan order
// are coloured by each candidate as the renderer colours them (the surface's
// own renderer, layered_surface.h: the same probes, masking and slope
// shading, its base layer naive or gaussian), shaded, and compared with the
// same pixels by `exact` (V <C_h, D_h> and V <C_s, D_s> over each probe's
// unresolved footprint: eq. 14 and eqs. 19-20 without a Gaussian). The
// error is the mean CIEDE2000 over the pixels of each LOD band (the
// integer part of the pixel's LOD: log2 of its probes' width in texture
// units); a candidate meets the tolerance when every band's mean does.
// Candidates are tried cheapest first: naive (no filtering
// distribution), gaussian (the paper's fit of D_h, eqs. 17-18),
// gaussian-exact (D_h's exact moments), exact; the choice is the first that
// meets it. Exact is the reference, so it always meets; what no one-ray
// method renders (the shadows of resolved heights, which the ray-traced
// reference shows) is not part of the error (docs/microsurface.md measures
// it).
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

struct MicrosurfaceChoiceOptions {
    double tolerance = 1.0;  // mean CIEDE2000 in every LOD band; finite and > 0
    // Tried in this order (each naive, gaussian, gaussian-exact or exact);
    // empty: naive, gaussian, gaussian-exact, exact.
    std::vector<RenderMethod> candidates;
    int max_pixels = 4096;  // per surface, >= 1
    // The render the choice is for: its footprint, probes, masking, slope
    // shading and threads are used; its method, region and per-surface
    // choices are not (the whole frame is measured, so that every region of
    // a farm render makes the same choice).
    RenderOptions render;
};

struct MicrosurfaceTrial : ViewTrial {
    RenderMethod method = RenderMethod::Gaussian;
};

struct MicrosurfaceMethodChoice : ViewMeasurement {
    std::vector<MicrosurfaceTrial> trials;  // in the order tried
    std::optional<std::size_t> chosen;      // the first that meets; none when none does

    const MicrosurfaceTrial* choice() const { return chosen ? &trials[*chosen] : nullptr; }
};

struct SurfaceMicrosurfaceChoice {
    std::size_t surface = 0;
    MicrosurfaceMethodChoice choice;
};

// One choice per microsurface material whose surface some pixel's centre
// ray hits (a surface no pixel sees is left out), in surface order. BadInput
// naming MicrosurfaceChoiceOptions' field for a tolerance, candidate or
// pixel count out of range, or for materials that do not match the scene.
Expected<std::vector<SurfaceMicrosurfaceChoice>> choose_microsurface_methods(const Scene& scene,
                                                                             const std::vector<Material>& materials,
                                                                             const MicrosurfaceChoiceOptions& options);

}  // namespace cmfilter
