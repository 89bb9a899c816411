// SPDX-License-Identifier: Apache-2.0
// Which LODs a view reaches on each surface: the range of the footprint LODs
// (RenderedImage::lod: log2 of the footprint's width, or of each anisotropic
// probe's, over a noise's base period or in a texture's level-0 texels) over
// the pixels whose centre ray hits the surface. render --method auto
// measures each texture's methods and each noise's sub-footprints at these
// LODs only: the view's, not every level of its pyramid or sigma table.
#pragma once

#include "cmfilter/render/render.h"
#include "cmfilter/scene/scene.h"
#include "cmfilter/scene/scene_materials.h"
#include "cmfilter/util/error.h"

#include <cstddef>
#include <vector>

namespace cmfilter {

struct SurfaceLodRange {
    std::size_t pixels = 0;      // pixels whose centre ray hits the surface
    double first = 0, last = 0;  // the least and greatest LOD among them (0, 0 where none)
};

// One range per surface (`surfaces` of them) from an image rendered with
// RenderOptions::surface_indices. BadInput if the image has no surface
// indices or one is past `surfaces`.
Expected<std::vector<SurfaceLodRange>> surface_lod_ranges(const RenderedImage& image, std::size_t surfaces);

// The ranges of the whole frame as `options` would render it: its centre
// rays rendered by naive (the footprints and LODs of every one-ray method,
// without their colours' cost), whatever options' method, region and
// per-surface choices, and without edge coverage (the LODs are the centre
// rays' either way); no progress is reported.
Expected<std::vector<SurfaceLodRange>> survey_surface_lods(const Scene& scene, const std::vector<Material>& materials,
                                                           const RenderOptions& options);

}  // namespace cmfilter
