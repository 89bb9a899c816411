// SPDX-License-Identifier: Apache-2.0
// Helpers for the tests of render --method auto's choices measured on the
// view (microsurface_method_choice.h, surface_probe_choice.h): a scene from
// JSON text with its materials, one-ray render options without edge
// coverage (each pixel its centre ray's surface alone) and with surface
// indices, and the second computation the choices are checked against:
// whole renders compared pixel by pixel over one surface's pixels, banded
// by the reference render's LOD AOV.
#pragma once

#include "cmfilter/color/ciede2000.h"
#include "cmfilter/render/render.h"
#include "cmfilter/scene/scene_loading.h"

#include "slope_layer_test_support.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace cmfilter_test {

struct PreparedScene {
    cmfilter::Scene scene;
    std::vector<cmfilter::Material> materials;
};

inline PreparedScene prepare_scene(const nlohmann::json& text, const std::string& path)
{
    auto scene = cmfilter::parse_scene(text.dump(), path);
    REQUIRE_MESSAGE(scene, (scene ? "" : scene.error().message));
    std::vector<cmfilter::Material> materials = prepared_materials(*scene, 2);
    return {std::move(*scene), std::move(materials)};
}

inline cmfilter::RenderOptions one_ray_options(cmfilter::RenderMethod method)
{
    cmfilter::RenderOptions o;
    o.method = method;
    o.threads = 2;
    o.edge_coverage = false;  // each pixel its centre ray's surface alone
    o.surface_indices = true;
    return o;
}

inline cmfilter::RenderedImage render_scene(const PreparedScene& p, const cmfilter::RenderOptions& o)
{
    auto image = cmfilter::render(p.scene, p.materials, o);
    REQUIRE_MESSAGE(image, (image ? "" : image.error().message));
    return std::move(*image);
}

inline cmfilter::Rgb pixel_rgb(const cmfilter::RenderedImage& image, std::size_t p)
{
    return {image.rgb[3 * p], image.rgb[3 * p + 1], image.rgb[3 * p + 2]};
}

// Sums of CIEDE2000 from a reference render per floor(LOD) band, and the
// pixels per band, over one surface's pixels.
struct BandSums {
    std::map<int, double> sum;
    std::map<int, std::size_t> count;

    double mean(int band) const { return sum.at(band) / static_cast<double>(count.at(band)); }
    double worst() const
    {
        double w = 0;
        for (const auto& entry : sum) w = std::max(w, mean(entry.first));
        return w;
    }
};

inline BandSums band_sums(const cmfilter::RenderedImage& image, const cmfilter::RenderedImage& reference, int surface)
{
    BandSums b;
    for (std::size_t p = 0; p < image.surface.size(); ++p) {
        if (reference.surface[p] != surface) continue;
        const int band = static_cast<int>(std::floor(reference.lod[p]));
        b.sum[band] += cmfilter::ciede2000_linear_rgb(pixel_rgb(image, p), pixel_rgb(reference, p));
        ++b.count[band];
    }
    return b;
}

// render() stores its pixels as float, the choices keep doubles: their
// errors agree to about 1e-6 CIEDE2000.
inline constexpr double kFloatSlack = 1e-4;

}  // namespace cmfilter_test
