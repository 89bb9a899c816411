// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/colormap/slope_color_map_loading.h"

#include <cmath>
#include <sstream>

namespace cmfilter {

Expected<LoadedSlopeVectorColorMap> load_slope_vector_color_map(const SlopeVectorColorMapLoadOptions& options,
                                                                const ColorConfig& config)
{
    if (!std::isfinite(options.s_max) || !(options.s_max > 0)) {
        std::ostringstream msg;
        msg << "slope map s_max " << options.s_max << " is invalid (expected finite and > 0)";
        return bad_input(msg.str());
    }
    auto image = read_image(options.path);
    if (!image) return image.error();
    const ImageData& img = *image;
    std::vector<float> rgb;
    for (int y = 0; y < img.height; ++y) {
        auto row = image_rgb_texels(img, options.path, 0, y, 1, 0, img.width);
        if (!row) return row.error();
        rgb.insert(rgb.end(), row->begin(), row->end());
    }
    auto space = decide_image_colorspace(img, options.path, options.colorspace,
                                         "SlopeVectorColorMapLoadOptions::colorspace", config);
    if (!space) return space.error();
    if (auto st = image_rgb_to_scene_linear(rgb, *space, config); !st) return st.error();

    LoadedSlopeVectorColorMap out;
    out.map = {img.width, img.height, {}, options.s_max};
    for (std::size_t i = 0; i + 2 < rgb.size(); i += 3) out.map.texels.push_back({rgb[i], rgb[i + 1], rgb[i + 2]});
    if (auto st = validate(out.map, "'" + options.path + "'"); !st) return st.error();
    auto provenance = image_map_provenance(options.path, img, "whole image", *space, config);
    if (!provenance) return provenance.error();
    out.provenance = std::move(*provenance);
    return out;
}

}  // namespace cmfilter
