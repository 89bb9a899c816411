// SPDX-License-Identifier: Apache-2.0
// Coordinate maps (synthesis/coordinate_map_file.h) from arbitrary
// multi-part headers.
#include "support/fuzz_checks.h"
#include "support/scratch_file.h"

#include "cmfilter/ops/artefact_info.h"
#include "cmfilter/synthesis/coordinate_map_file.h"

using namespace cmfilter;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string path = fuzz::write_scratch_file("map.cmfuzz", data, size);
    if (auto map = read_coordinate_map_exr(path)) {
        fuzz::require(!map->levels.empty(), "a coordinate map has a level");
        for (const CoordinateLevel& level : map->levels) {
            fuzz::require(level.coords.size() == std::size_t(level.width) * std::size_t(level.height) * 2,
                          "a level holds two coordinates per texel");
            for (std::size_t i = 0; i < level.coords.size(); i += 2)
                fuzz::require(level.coords[i] >= 0 && level.coords[i + 1] >= 0, "coordinates are non-negative");
        }
    }
    (void)read_artefact_info(path);
    return 0;
}
