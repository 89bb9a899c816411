// SPDX-License-Identifier: Apache-2.0
// A coordinate map (coordinate_map.h) as a float OpenEXR file
// (docs/synthesis.md#coordinate-maps): subimage 0 is the full-size map with
// channels "u", "v", each texel the centre of the sample texel it copies in
// normalised coordinates ((x + 0.5) / sample width, (y + 0.5) / sample
// height; v down, top row first), so a shader reads it as a texture
// coordinate into the sample. cmfilter:kind "coordinate-map",
// cmfilter:format_version 1, cmfilter:sample (path), cmfilter:sample_hash,
// cmfilter:sample_kind, cmfilter:sample_width/_height,
// cmfilter:sample_periodic, cmfilter:k, cmfilter:neighbourhood,
// cmfilter:levels, cmfilter:toroidal, cmfilter:seed (decimal text, exact
// for any 64-bit seed; an int attribute reads too), cmfilter:seconds (the
// synthesis time, a double; 0 when absent). Subimage 0 is named "level-0";
// subimages "level-1" .. hold the hierarchical levels' maps into the
// sample's pyramid levels (their cmfilter:sample_width/_height that level's
// size). Numbers written by other tools as int attributes (oiiotool's
// --attrib:type=int) read; a coordinate u reads as sample texel
// floor(u * width), so any u in [0, 1) names a texel.
#pragma once

#include "cmfilter/synthesis/coordinate_map.h"
#include "cmfilter/util/error.h"

#include <string>

namespace cmfilter {

inline constexpr const char* kCoordinateMapKind = "coordinate-map";

// Io when the file cannot be written; BadInput when a coordinate lies
// outside its level's sample. Nothing left behind on failure.
Status write_coordinate_map_exr(const std::string& path, const CoordinateMap& map);

// Io: missing or unreadable. BadInput naming the file: not a coordinate
// map, an unknown version, missing channels, non-finite coordinates, a
// coordinate outside [0, 1) (outside the sample, naming the texel and the
// value), a sample size missing or < 1.
Expected<CoordinateMap> read_coordinate_map_exr(const std::string& path);

}  // namespace cmfilter
