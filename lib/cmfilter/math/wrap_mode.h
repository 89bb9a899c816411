// SPDX-License-Identifier: Apache-2.0
// How a colour map continues outside its driver domain [vmin, vmax].
#pragma once

#include "cmfilter/util/error.h"

#include <string>

namespace cmfilter {

enum class WrapMode {
    Clamp,   // the end colours continue forever
    Repeat,  // the map is periodic with period vmax - vmin
    Mirror,  // the map is reflected at vmin and vmax (period 2 (vmax - vmin))
};

const char* to_string(WrapMode mode);
Expected<WrapMode> parse_wrap_mode(const std::string& name);

// Index of the texel that integer node k stands for, for a map of n texels
// (k may be any integer, the node grid runs over the whole real line).
long wrap_texel_index(long k, long n, WrapMode mode);

// Reflects x into [0, period] (mirror) or [0, period) (repeat); clamp returns x.
double wrap_coordinate(double x, double period, WrapMode mode);

}  // namespace cmfilter
