// SPDX-License-Identifier: Apache-2.0
// Test-only inputs for apply_filter (ops/filtered_image.h) and the method
// choice built on it: an 8-texel map with its table, a driver with its
// moments, and the brute-force box mean of C0(f) over a level's texel.
#pragma once

#include "cmfilter/colormap/color_map_loading.h"
#include "cmfilter/ops/filtered_image.h"
#include "cmfilter/tables/gaussian_color_table_file.h"
#include "cmfilter/texture/moment_pyramid.h"

#include "box_reference.h"
#include "reference_convolution.h"
#include "test_images.h"
#include "unit_test_support.h"

#include <doctest/doctest.h>

#include <string>
#include <vector>

namespace cmfilter_test {

using namespace cmfilter;

// An 8-texel float (linear) map over [0, 1], clamp: the same texels as a
// ReferenceMap (float values widened to double on both sides).
inline const std::vector<float> kMap = {0.02f, 0.05f, 0.4f, 0.9f, 0.1f, 0.05f, 0.1f,  0.8f, 0.2f, 2.5f, 2.2f,  0.3f,
                                        0.0f,  0.0f,  0.0f, 0.6f, 0.6f, 0.6f,  0.05f, 0.9f, 0.3f, 1.0f, 0.95f, 0.9f};

inline ReferenceMap reference_map()
{
    ReferenceMap m;
    for (std::size_t i = 0; i < kMap.size(); i += 3) m.texels.push_back({kMap[i], kMap[i + 1], kMap[i + 2]});
    return m;
}

// Writes the map (kMap, or RGB `map_texels` over the same domain), bakes its
// table (options chosen per test) and a driver's moments; returns the apply
// options for them.
inline ApplyOptions apply_inputs(const std::string& dir, const std::string& name, const std::vector<float>& f, int W,
                                 int H, const GaussianColorTableOptions& table_options, int moment_order = 2,
                                 double vmin = 0, const std::vector<float>& map_texels = kMap)
{
    const ColorConfig config = builtin_color_config();
    const std::string map_path = dir + "/" + name + "-map.exr";
    write_image(map_path, static_cast<int>(map_texels.size() / 3), 1, 3, OIIO::TypeDesc::FLOAT, map_texels.data());
    ColorMapLoadOptions load;
    load.path = map_path;
    load.vmin = vmin;
    load.vmax = vmin + 1;
    auto map = load_color_map(load, config);
    REQUIRE(map);
    auto table = GaussianColorTable::bake(map->map, table_options);
    REQUIRE(table);
    GaussianColorTableInfo info;
    info.source = map->provenance;
    ApplyOptions options;
    options.table_path = dir + "/" + name + "-table.exr";
    REQUIRE(write_gaussian_color_table(options.table_path, *table, info));
    const std::string driver = dir + "/" + name + "-driver.exr";
    write_image(driver, W, H, 1, OIIO::TypeDesc::FLOAT, f.data());
    MomentBakeOptions bake;
    bake.driver_path = driver;
    bake.output_path = options.moments_path = dir + "/" + name + "-moments.exr";
    bake.order = moment_order;
    REQUIRE(bake_moment_pyramid(bake));
    return options;
}

// Brute force (tests/support/box_reference.h): the mean of C0(f) over
// texel (x, y) of a w x h level, area-weighted.
inline Rgb3 box_mean_color(const ReferenceMap& m, const std::vector<float>& f, int W, int H, int w, int h, int x, int y)
{
    Rgb3 sum{0, 0, 0};
    for (const auto& b : box_weights(W, H, w, h, x, y)) {
        const Rgb3 c = reference_map_value(m, f[std::size_t(b.j) * W + b.i]);
        for (int ch = 0; ch < 3; ++ch) sum[ch] += b.weight * c[ch];
    }
    return sum;
}

}  // namespace cmfilter_test
