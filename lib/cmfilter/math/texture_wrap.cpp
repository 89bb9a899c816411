// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/math/texture_wrap.h"

namespace cmfilter {

const char* to_string(TextureWrap wrap)
{
    switch (wrap) {
    case TextureWrap::Black: return "black";
    case TextureWrap::Clamp: return "clamp";
    case TextureWrap::Periodic: return "periodic";
    }
    return "clamp";
}

Expected<TextureWrap> parse_texture_wrap(const std::string& name)
{
    if (name == "black") return TextureWrap::Black;
    if (name == "clamp") return TextureWrap::Clamp;
    if (name == "periodic") return TextureWrap::Periodic;
    return bad_input("unknown wrap mode '" + name + "' (expected black, clamp or periodic)");
}

int wrap_texel(int i, int n, TextureWrap wrap)
{
    if (i >= 0 && i < n) return i;
    switch (wrap) {
    case TextureWrap::Periodic: return ((i % n) + n) % n;
    case TextureWrap::Black: return -1;
    case TextureWrap::Clamp: break;
    }
    return i < 0 ? 0 : n - 1;
}

}  // namespace cmfilter
