// SPDX-License-Identifier: Apache-2.0
// "vmin:vmax" option values.
#include "command.h"

#include <cmath>
#include <cstdlib>

namespace cmfilter::cli {

namespace {

bool parse_number(const std::string& text, double& out)
{
    if (text.empty()) return false;
    char* end = nullptr;
    out = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size() && std::isfinite(out);
}

}  // namespace

Expected<std::pair<double, double>> parse_range(const std::string& option, const std::string& text)
{
    const auto colon = text.find(':');
    double a = 0, b = 0;
    if (colon == std::string::npos || !parse_number(text.substr(0, colon), a) ||
        !parse_number(text.substr(colon + 1), b))
        return bad_input(option + " '" + text + "' is not a range (expected two finite numbers, MIN:MAX)");
    if (!(a < b)) return bad_input(option + " '" + text + "' is empty (expected MIN < MAX)");
    return std::make_pair(a, b);
}

}  // namespace cmfilter::cli
