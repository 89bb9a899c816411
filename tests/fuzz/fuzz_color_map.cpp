// SPDX-License-Identifier: Apache-2.0
// Colour-map images (colormap/color_map_loading.h) of arbitrary sizes,
// channels, types and colour-space attributes, by row and by column.
#include "support/fuzz_checks.h"
#include "support/scratch_file.h"

#include "cmfilter/color/color_config.h"
#include "cmfilter/colormap/color_map_loading.h"

using namespace cmfilter;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    static const auto config = ColorConfig::load("");
    fuzz::require(config.has_value(), "the built-in colour configuration loads");
    const std::string path = fuzz::write_scratch_file("map.cmfuzz", data, size);
    ColorMapLoadOptions options;
    options.path = path;
    for (int pick = 0; pick < 3; ++pick) {
        options.row = pick == 1 ? std::optional<int>(0) : std::nullopt;
        options.column = pick == 2 ? std::optional<int>(0) : std::nullopt;
        if (auto map = load_color_map(options, *config)) (void)map;
    }
    return 0;
}
