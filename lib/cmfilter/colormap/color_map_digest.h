// SPDX-License-Identifier: Apache-2.0
// The identity of a colour map C0 as it is evaluated (color_map.h): the
// SHA-256 of its scene-linear texels (float64, little-endian), its domain
// [vmin, vmax] and its wrap. Two maps with the same digest give the same
// C0(v) for every v, whichever file, format or colour space they were read
// from; a colour pyramid (texture/color_pyramid_file.h) records it to refuse
// a lookup through another map.
#pragma once

#include "cmfilter/colormap/color_map.h"

#include <string>

namespace cmfilter {

// 64 lowercase hexadecimal characters.
std::string color_map_sha256(const ColorMap& map);

}  // namespace cmfilter
