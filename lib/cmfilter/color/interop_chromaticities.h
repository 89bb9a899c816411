// SPDX-License-Identifier: Apache-2.0
// The CIE xy chromaticities (red, green, blue primaries and white point) of
// the linear colour spaces cmfilter's built-in config knows, by colour
// interop ID: what OpenEXR's standard "chromaticities" attribute holds, so
// that a file cmfilter writes tells OpenEXR readers its primaries, and a file
// another tool wrote with only that attribute is read in the right space.
#pragma once

#include <array>
#include <optional>
#include <string>

namespace cmfilter {

using Chromaticities = std::array<float, 8>;  // red x y, green x y, blue x y, white x y

// The chromaticities of a linear space's interop ID ("lin_rec709_scene",
// "lin_ap1_scene", "lin_ap0_scene", "lin_p3d65_scene"); none for others.
std::optional<Chromaticities> interop_chromaticities(const std::string& interop_id);

// The interop ID whose chromaticities these are, each within 1e-3; empty
// when none is.
std::string interop_id_of_chromaticities(const Chromaticities& c);

}  // namespace cmfilter
