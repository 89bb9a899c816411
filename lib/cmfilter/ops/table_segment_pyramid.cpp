// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/ops/table_segment_pyramid.h"

#include "cmfilter/tables/gaussian_color_table_file.h"
#include "cmfilter/tables/table_color_map.h"

namespace cmfilter {

Expected<TableSegmentPyramid> bake_table_segment_pyramid(const TableSegmentPyramidOptions& options,
                                                         const ColorConfig& config)
{
    if (options.table_paths.empty())
        return bad_input("TableSegmentPyramidOptions::table_paths is empty (expected at least one colour table)",
                         "TableSegmentPyramidOptions::table_paths");
    TableSegmentPyramid out;
    std::vector<TableColorMap> maps;
    for (const std::string& path : options.table_paths) {
        auto table = read_gaussian_color_table(path);
        if (!table) return table.error();
        TableColorMapOptions mo;
        mo.table_path = path;
        auto map = load_table_color_map(*table, mo, config);
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

}  // namespace cmfilter
