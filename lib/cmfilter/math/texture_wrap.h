// SPDX-License-Identifier: Apache-2.0
// How a texture continues beyond its edges when a lookup's footprint crosses
// them, named as maketx and OpenImageIO's TextureSystem name them. A moment
// pyramid stores its mode in the file ("wrapmodes"), so TextureSystem applies
// it without being told.
#pragma once

#include "cmfilter/util/error.h"

#include <string>

namespace cmfilter {

enum class TextureWrap {
    Black,     // outside is 0: for moments about c, a point mass at f = c
    Clamp,     // the edge texels continue forever
    Periodic,  // the texture tiles the plane
};

// "black", "clamp", "periodic".
const char* to_string(TextureWrap wrap);
Expected<TextureWrap> parse_texture_wrap(const std::string& name);

// The texel that index i stands for along an axis of n texels: i itself
// inside [0, n); beyond, i mod n (periodic), the nearest edge texel (clamp),
// or -1, no texel (black).
int wrap_texel(int i, int n, TextureWrap wrap);

}  // namespace cmfilter
