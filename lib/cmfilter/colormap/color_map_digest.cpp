// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/colormap/color_map_digest.h"

#include "cmfilter/util/sha256.h"

#include <cstdint>
#include <cstring>
#include <vector>

namespace cmfilter {

namespace {

void append_double(std::vector<unsigned char>& bytes, double v)
{
    std::uint64_t u = 0;
    std::memcpy(&u, &v, sizeof u);
    for (int i = 0; i < 8; ++i) bytes.push_back(static_cast<unsigned char>(u >> (8 * i)));  // little-endian
}

}  // namespace

std::string color_map_sha256(const ColorMap& map)
{
    std::vector<unsigned char> bytes;
    bytes.reserve(24 * map.texels.size() + 32);
    const char* wrap = to_string(map.wrap);
    bytes.insert(bytes.end(), wrap, wrap + std::strlen(wrap));
    bytes.push_back(0);
    append_double(bytes, map.vmin);
    append_double(bytes, map.vmax);
    for (const Rgb& c : map.texels)
        for (int ch = 0; ch < 3; ++ch) append_double(bytes, c[ch]);
    return sha256_hex(bytes.data(), bytes.size());
}

}  // namespace cmfilter
