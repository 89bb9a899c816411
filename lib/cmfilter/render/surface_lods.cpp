// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/render/surface_lods.h"

#include <algorithm>
#include <string>

namespace cmfilter {

Expected<std::vector<SurfaceLodRange>> surface_lod_ranges(const RenderedImage& image, std::size_t surfaces)
{
    if (image.surface.size() != image.lod.size())
        return bad_input("RenderedImage::surface has " + std::to_string(image.surface.size()) + " entries for " +
                         std::to_string(image.lod.size()) +
                         " pixels (expected one a pixel: render with RenderOptions::surface_indices)");
    std::vector<SurfaceLodRange> ranges(surfaces);
    for (std::size_t p = 0; p < image.surface.size(); ++p) {
        const std::int32_t s = image.surface[p];
        if (s < 0) continue;
        if (static_cast<std::size_t>(s) >= surfaces)
            return bad_input("RenderedImage::surface holds surface " + std::to_string(s) + " (expected below " +
                             std::to_string(surfaces) + ")");
        SurfaceLodRange& r = ranges[static_cast<std::size_t>(s)];
        const double lod = image.lod[p];
        r.first = r.pixels == 0 ? lod : std::min(r.first, lod);
        r.last = r.pixels == 0 ? lod : std::max(r.last, lod);
        ++r.pixels;
    }
    return ranges;
}

Expected<std::vector<SurfaceLodRange>> survey_surface_lods(const Scene& scene, const std::vector<Material>& materials,
                                                           const RenderOptions& options)
{
    RenderOptions survey = options;
    survey.method = RenderMethod::Naive;
    survey.region.reset();
    survey.texture_methods.clear();
    survey.noise_sub_footprints.clear();
    survey.edge_coverage = false;
    survey.surface_indices = true;
    survey.progress = nullptr;
    auto image = render(scene, materials, survey);
    if (!image) return image.error();
    return surface_lod_ranges(*image, materials.size());
}

}  // namespace cmfilter
