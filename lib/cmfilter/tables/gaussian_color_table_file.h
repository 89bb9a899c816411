// SPDX-License-Identifier: Apache-2.0
// The on-disk form of a GaussianColorTable: a scanline float32 RGB OpenEXR,
// width = value nodes, height = sigma nodes (row 0 = sigma 0), carrying every
// baking parameter as cmfilter:* metadata (docs/table-format.md). Written
// atomically; read back with the geometry checked against the pixels.
#pragma once

#include "cmfilter/colormap/color_map_loading.h"
#include "cmfilter/io/exr_output_options.h"
#include "cmfilter/util/error.h"
#include "cmfilter/color/error_summary.h"
#include "cmfilter/tables/gaussian_color_table.h"

#include <optional>
#include <string>

namespace cmfilter {

inline constexpr const char* kGaussianColorTableKind = "gaussian-color-table";

// How a table's size was chosen for a tolerance (bake-colormap --tolerance,
// table_size_search.h).
struct TableToleranceRecord {
    double tolerance = 0;   // CIEDE2000
    std::string statistic;  // quantile_name: "p99.9", "max"
    double error = 0;       // the statistic the table reaches at the verification points
    int samples = 0;        // verification points
    std::string search;     // the grid searched and what was measured
};

// What a table file says about itself beyond its axes.
struct GaussianColorTableInfo {
    ColorMapProvenance source;
    std::optional<ErrorSummary> lookup_error;  // CIEDE2000 of bilinear lookups vs exact
    int lookup_error_samples = 0;
    std::string sigma_max_source;                   // why this sigma_max (empty: not recorded)
    std::optional<TableToleranceRecord> tolerance;  // set when the size was searched for
    std::string baked_by;                           // cmfilter version
};

// `storage`: pixel type, tiles and compression (default float, scanlines, zip).
Status write_gaussian_color_table(const std::string& path, const GaussianColorTable& table,
                                  const GaussianColorTableInfo& info, const ExrOutputOptions& storage = {});

struct LoadedGaussianColorTable {
    GaussianColorTable table;
    GaussianColorTableInfo info;
};

Expected<LoadedGaussianColorTable> read_gaussian_color_table(const std::string& path);

}  // namespace cmfilter
