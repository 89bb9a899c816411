// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/ops/table_segment_pyramid.h"

#include "cmfilter/tables/gaussian_color_table_file.h"
#include "cmfilter/tables/table_color_map.h"
#include "cmfilter/texture/segment_pyramid_texture.h"

namespace cmfilter {

namespace {

// The colour map of the table at `path`, as its cmfilter:source records it.
Expected<TableColorMap> table_color_map(const std::string& path, const ColorConfig& config)
{
    auto table = read_gaussian_color_table(path);
    if (!table) return table.error();
    TableColorMapOptions mo;
    mo.table_path = path;
    return load_table_color_map(*table, mo, config);
}

}  // namespace

Expected<TableSegmentPyramid> bake_table_segment_pyramid(const TableSegmentPyramidOptions& options,
                                                         const ColorConfig& config)
{
    if (options.table_paths.empty())
        return bad_input("TableSegmentPyramidOptions::table_paths is empty (expected at least one colour table)",
                         "TableSegmentPyramidOptions::table_paths");
    TableSegmentPyramid out;
    std::vector<TableColorMap> maps;
    for (const std::string& path : options.table_paths) {
        auto map = table_color_map(path, config);
        if (!map) return map.error();
        out.map_paths.push_back(map->map.provenance.path);
        out.warnings.insert(out.warnings.end(), map->warnings.begin(), map->warnings.end());
        maps.push_back(std::move(*map));
    }
    SegmentPyramidBakeOptions bake = options.bake;
    bake.maps.clear();
    for (const TableColorMap& m : maps) bake.maps.push_back(&m.map.map);
    bake.map_sources = out.map_paths;
    auto baked = bake_segment_pyramid(bake);
    if (!baked) return baked.error();
    out.result = std::move(*baked);
    return out;
}

Expected<SegmentColors> segment_pyramid_colors(const std::string& pyramid_path, const std::string& table_path,
                                               const ColorConfig& config)
{
    auto pyramid = SegmentPyramidTexture::open(pyramid_path);
    if (!pyramid) return pyramid.error();
    const SegmentPyramidInfo& info = pyramid->info();
    auto map = table_color_map(table_path, config);
    if (!map) return map.error();
    const std::string map_name = "the map of table '" + table_path + "' ('" + map->map.provenance.path + "')";
    auto fit = check_segment_pyramid_map(info, pyramid_path, map->map.map, map_name);
    if (!fit) return fit.error();
    SegmentColors out;
    out.breakpoints = info.breakpoints;
    out.colors = breakpoint_colors(map->map.map, info.breakpoints, info.weights());
    out.fit_de = fit->max_de;
    out.mean_fit_de = fit->mean_de;
    out.warnings = map->warnings;
    if (auto w = segment_recolour_warning(info, pyramid_path, *fit, map_name)) out.warnings.push_back(*w);
    return out;
}

}  // namespace cmfilter
