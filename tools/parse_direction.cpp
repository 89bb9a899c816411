// SPDX-License-Identifier: Apache-2.0
// "x,y,z" direction option values (light and view directions).
#include "command.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace cmfilter::cli {

Expected<Vec3> parse_direction(const std::string& option, const std::string& text)
{
    double v[3];
    std::size_t start = 0;
    for (int i = 0; i < 3; ++i) {
        const std::size_t comma = text.find(',', start);
        const bool last = i == 2;
        if ((comma == std::string::npos) != last)
            return bad_input(option + " '" + text + "' is not a direction (expected three numbers, x,y,z)");
        const std::string field = text.substr(start, last ? std::string::npos : comma - start);
        char* end = nullptr;
        v[i] = std::strtod(field.c_str(), &end);
        if (field.empty() || end != field.c_str() + field.size() || !std::isfinite(v[i]))
            return bad_input(option + " '" + text + "': '" + field + "' is not a finite number (expected x,y,z)");
        start = comma + 1;
    }
    // Scaled by its largest component first, so that the length of a huge
    // (finite) vector does not overflow to infinity.
    const double largest = std::max({std::fabs(v[0]), std::fabs(v[1]), std::fabs(v[2])});
    if (!(largest > 0)) return bad_input(option + " '" + text + "' is zero (expected a direction)");
    const Vec3 d{v[0] / largest, v[1] / largest, v[2] / largest};
    const Vec3 unit = d / length(d);
    if (unit.z < 0)
        return bad_input(option + " '" + text + "' is below the horizon (expected z >= 0, towards the camera)");
    return unit;
}

}  // namespace cmfilter::cli
