// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/colormap/color_map_loading.h"

#include "cmfilter/io/image_colorspace.h"
#include "cmfilter/io/image_reading.h"
#include "cmfilter/util/sha256.h"

#include <cmath>
#include <sstream>

namespace cmfilter {

Expected<std::vector<float>> image_rgb_texels(const ImageData& img, const std::string& path, int start_x, int start_y,
                                              int step_x, int step_y, int count)
{
    std::vector<float> rgb(static_cast<std::size_t>(count) * 3);
    for (int i = 0; i < count; ++i) {
        const int x = start_x + i * step_x, y = start_y + i * step_y;
        const ImageWindow& w = img.window;
        const float* p = img.pixels.data() + (static_cast<std::size_t>(y - w.y) * w.width + (x - w.x)) * img.channels;
        for (int ch = 0; ch < 3; ++ch) {
            const float v = img.channels >= 3 ? p[ch] : p[0];
            if (!std::isfinite(v)) {
                std::ostringstream msg;
                msg << "'" << path << "' has a non-finite texel at (" << x << ", " << y << ") channel " << ch << ": "
                    << v << "; expected finite colours";
                return bad_input(msg.str());
            }
            rgb[3 * i + ch] = v;
        }
    }
    return rgb;
}

Expected<ColorMapProvenance> image_map_provenance(const std::string& path, const ImageData& img,
                                                  const std::string& selection, const ImageColorSpace& space,
                                                  const ColorConfig& config)
{
    auto hash = sha256_file_hex(path);
    if (!hash) return hash.error();
    ColorMapProvenance prov;
    prov.path = path;
    prov.sha256 = *hash;
    prov.image_width = img.width;
    prov.image_height = img.height;
    prov.selection = selection;
    prov.colorspace = space.colorspace;
    prov.colorspace_rule = space.rule;
    prov.linear_space = config.scene_linear_name();
    prov.linear_interop_id = config.interop_id(prov.linear_space);
    prov.ocio_config = config.source();
    return prov;
}

Expected<LoadedColorMap> load_color_map(const ColorMapLoadOptions& options, const ColorConfig& config)
{
    if (!std::isfinite(options.vmin) || !std::isfinite(options.vmax) || !(options.vmin < options.vmax)) {
        std::ostringstream msg;
        msg << "ColorMapLoadOptions::vmin:vmax " << options.vmin << ":" << options.vmax
            << " is invalid (expected finite vmin < vmax)";
        return bad_input(msg.str(), "ColorMapLoadOptions::vmin");
    }
    if (options.row && options.column)
        return bad_input("ColorMapLoadOptions::row and ColorMapLoadOptions::column were both given; pick one gradient",
                         "ColorMapLoadOptions::row");

    // Which texels form the gradient, decided from the header: only they
    // are kept of the pixels.
    int start_x = 0, start_y = 0, step_x = 1, step_y = 0, count = 0;
    std::string selection = "row 0";
    auto choose = [&](const ImageData& img) -> Expected<ImageWindow> {
        if (options.column || (img.width == 1 && img.height > 1 && !options.row)) {
            const int c = options.column.value_or(0);
            if (c < 0 || c >= img.width) {
                std::ostringstream msg;
                msg << "ColorMapLoadOptions::column " << c << " is outside '" << options.path << "' (expected 0.."
                    << img.width - 1 << ")";
                return bad_input(msg.str(), "ColorMapLoadOptions::column");
            }
            start_x = c, step_x = 0, step_y = 1, count = img.height;
            selection = "column " + std::to_string(c);
            return ImageWindow{c, 0, 1, img.height};
        }
        if (options.row || img.height == 1) {
            const int r = options.row.value_or(0);
            if (r < 0 || r >= img.height) {
                std::ostringstream msg;
                msg << "ColorMapLoadOptions::row " << r << " is outside '" << options.path << "' (expected 0.."
                    << img.height - 1 << ")";
                return bad_input(msg.str(), "ColorMapLoadOptions::row");
            }
            start_y = r, count = img.width;
            selection = "row " + std::to_string(r);
            return ImageWindow{0, r, img.width, 1};
        }
        std::ostringstream msg;
        msg << "'" << options.path << "' is " << img.width << " x " << img.height
            << "; pass ColorMapLoadOptions::row N or ColorMapLoadOptions::column N to pick the gradient (or use a W x "
               "1 image)";
        return bad_input(msg.str(), "ColorMapLoadOptions::row");
    };
    auto image = read_image(options.path, choose);
    if (!image) return image.error();
    const ImageData& img = *image;

    auto texels = image_rgb_texels(img, options.path, start_x, start_y, step_x, step_y, count);
    if (!texels) return texels.error();
    std::vector<float>& rgb = *texels;

    auto space =
        decide_image_colorspace(img, options.path, options.colorspace, "ColorMapLoadOptions::colorspace", config);
    if (!space) return space.error();
    if (auto st = image_rgb_to_scene_linear(rgb, *space, config); !st) return st.error();

    LoadedColorMap out;
    out.map.vmin = options.vmin;
    out.map.vmax = options.vmax;
    out.map.wrap = options.wrap;
    out.map.texels.resize(count);
    for (int i = 0; i < count; ++i) out.map.texels[i] = {rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]};
    if (auto st = validate(out.map, "'" + options.path + "'"); !st) return st.error();

    auto provenance = image_map_provenance(options.path, img, selection, *space, config);
    if (!provenance) return provenance.error();
    out.provenance = std::move(*provenance);
    return out;
}

}  // namespace cmfilter
