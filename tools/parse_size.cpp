// SPDX-License-Identifier: Apache-2.0
// "WxH" option values.
#include "command.h"

#include "cmfilter/scene/scene.h"

#include <cstdlib>

namespace cmfilter::cli {

Expected<std::pair<int, int>> parse_size(const std::string& option, const std::string& text)
{
    const auto x = text.find_first_of("xX");
    const auto number = [](const std::string& s, long& out) {
        if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos) return false;
        out = std::strtol(s.c_str(), nullptr, 10);
        return out >= 1 && out <= 65536;
    };
    long w = 0, h = 0;
    if (x == std::string::npos || !number(text.substr(0, x), w) || !number(text.substr(x + 1), h))
        return bad_input(option + " '" + text + "' is not a size (expected WxH, two integers 1..65536)");
    return std::make_pair(static_cast<int>(w), static_cast<int>(h));
}

Expected<std::pair<int, int>> parse_image_size(const std::string& option, const std::string& text)
{
    auto size = parse_size(option, text);
    if (!size) return size.error();
    const auto [w, h] = *size;
    if (w > kMaxImageSide || h > kMaxImageSide)
        return bad_input(option + " '" + text + "' has a side above " + std::to_string(kMaxImageSide) +
                         " (a scene's largest)");
    if (static_cast<long long>(w) * h > kMaxImagePixels)
        return bad_input(option + " '" + text + "' is " + std::to_string(static_cast<long long>(w) * h) +
                         " pixels, above a scene's largest, " + std::to_string(kMaxImagePixels));
    return size;
}

}  // namespace cmfilter::cli
