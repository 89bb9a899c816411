// SPDX-License-Identifier: Apache-2.0
// The colour map C0 a Gaussian colour table was baked from, rebuilt from the
// table's own metadata (docs/table-format.md): the source image
// (cmfilter:source), its colour space (cmfilter:colorspace), the gradient
// picked from it (cmfilter:source_selection), the driver domain and the wrap.
// Methods that evaluate C0 exactly (naive, exact, reference) need it: the
// table's row 0 holds C0 only at its value nodes, which are coarser than the
// map's texels. The source file's SHA-256 is checked against
// cmfilter:source_sha256, so a map edited since the bake is not silently used.
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/colormap/color_map_loading.h"
#include "cmfilter/util/error.h"
#include "cmfilter/tables/gaussian_color_table_file.h"

#include <string>
#include <vector>

namespace cmfilter {

struct TableColorMapOptions {
    std::string table_path;    // for messages
    std::string map_override;  // empty: the recorded cmfilter:source
};

struct TableColorMap {
    LoadedColorMap map;
    std::vector<std::string> warnings;  // e.g. a hash mismatch with an override
};

// Io (saying to set map_override) when the recorded source cannot be read and no
// override was given; BadInput when its hash differs from the recorded one
// (only a warning with an override), or the metadata names no usable map.
Expected<TableColorMap> load_table_color_map(const LoadedGaussianColorTable& table, const TableColorMapOptions& options,
                                             const ColorConfig& config);

}  // namespace cmfilter
