// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/tables/table_color_map.h"

#include <filesystem>
#include <system_error>

namespace cmfilter {

Expected<TableColorMap> load_table_color_map(const LoadedGaussianColorTable& table, const TableColorMapOptions& options,
                                             const ColorConfig& config)
{
    const ColorMapProvenance& src = table.info.source;
    const TableAxes& axes = table.table.axes();
    const bool overridden = !options.map_override.empty();
    const std::string path = overridden ? options.map_override : src.path;
    const std::string where = "'" + options.table_path + "'";
    if (path.empty())
        return bad_input(where + " records no colour map source (cmfilter:source); pass "
                                 "TableColorMapOptions::map_override PATH",
                         "TableColorMapOptions::map_override");
    if (!overridden) {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(path, ec))
            return io_error(
                "cannot read colour map '" + path + "' recorded in " + where +
                    " (cmfilter:source): no such file; pass TableColorMapOptions::map_override PATH to give "
                    "its location",
                "TableColorMapOptions::map_override");
    }

    ColorMapLoadOptions load;
    load.path = path;
    load.colorspace = src.colorspace;  // the space the bake converted from, not a new guess
    load.vmin = axes.vmin;
    load.vmax = axes.vmax;
    load.wrap = axes.wrap;
    // "row N" or "column N", as load_color_map records it.
    const std::string& sel = src.selection;
    try {
        if (sel.rfind("row ", 0) == 0) load.row = std::stoi(sel.substr(4));
        else if (sel.rfind("column ", 0) == 0) load.column = std::stoi(sel.substr(7));
        else throw std::invalid_argument(sel);
    } catch (const std::exception&) {
        return bad_input(where + " has cmfilter:source_selection '" + sel + "' (expected 'row N' or 'column N')");
    }

    TableColorMap out;
    auto map = load_color_map(load, config);
    if (!map) return map.error();
    out.map = std::move(*map);
    if (out.map.provenance.sha256 != src.sha256) {
        const std::string what = "colour map '" + path + "' (sha256 " + out.map.provenance.sha256 +
                                 ") is not the file " + where + " was baked from (sha256 " + src.sha256 + ")";
        if (!overridden)
            return bad_input(
                what + "; re-bake the table, or pass TableColorMapOptions::map_override PATH to use it anyway",
                "TableColorMapOptions::map_override");
        out.warnings.push_back(what + "; using it as TableColorMapOptions::map_override asks");
    }
    // The same space under another name (another config) is the same space.
    const auto baked_in = src.linear_space.empty() ? Expected<std::string>(std::string())
                                                   : config.resolve(src.linear_space);
    if (!src.linear_space.empty() && (!baked_in || *baked_in != config.scene_linear_name()))
        out.warnings.push_back(where + " was baked in scene-linear '" + src.linear_space +
                               "' but the OpenColorIO config's scene_linear is '" + config.scene_linear_name() + "'");
    return out;
}

}  // namespace cmfilter
