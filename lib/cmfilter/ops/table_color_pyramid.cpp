// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/ops/table_color_pyramid.h"

#include "cmfilter/tables/gaussian_color_table_file.h"
#include "cmfilter/tables/table_color_map.h"

namespace cmfilter {

Expected<TableColorPyramid> bake_table_color_pyramid(const TableColorPyramidOptions& options, const ColorConfig& config)
{
    auto table = read_gaussian_color_table(options.table_path);
    if (!table) return table.error();
    TableColorMapOptions mo;
    mo.table_path = options.table_path;
    mo.map_override = options.map_path;
    auto map = load_table_color_map(*table, mo, config);
    if (!map) return map.error();
    ColorPyramidBakeOptions bake = options.bake;
    bake.map = &map->map.map;
    bake.map_source = map->map.provenance.path;
    bake.linear_space = config.scene_linear_name();
    bake.linear_interop_id = config.interop_id(bake.linear_space);
    auto baked = bake_color_pyramid(bake);
    if (!baked) return baked.error();
    TableColorPyramid out;
    out.result = std::move(*baked);
    out.map_path = map->map.provenance.path;
    out.warnings = std::move(map->warnings);
    return out;
}

}  // namespace cmfilter
