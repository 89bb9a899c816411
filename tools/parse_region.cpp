// SPDX-License-Identifier: Apache-2.0
// "x0,y0,x1,y1" option values: a region of a frame's pixels (render --region,
// bench --region).
#include "command.h"

#include <cstdlib>

namespace cmfilter::cli {

Expected<PixelRegion> parse_region(const std::string& option, const std::string& text)
{
    int values[4] = {0, 0, 0, 0};
    std::size_t start = 0;
    bool good = true;
    for (int i = 0; i < 4 && good; ++i) {
        const std::size_t comma = text.find(',', start);
        if ((i < 3) != (comma != std::string::npos)) {
            good = false;
            break;
        }
        const std::string number = text.substr(start, i < 3 ? comma - start : std::string::npos);
        // Nine digits at most: far past any frame, and within an int.
        good = !number.empty() && number.size() <= 9 && number.find_first_not_of("0123456789") == std::string::npos;
        if (good) values[i] = static_cast<int>(std::strtol(number.c_str(), nullptr, 10));
        start = comma + 1;
    }
    if (!good)
        return bad_input(option + " '" + text +
                         "' is not a region (expected x0,y0,x1,y1: four integers >= 0, pixel coordinates of the "
                         "whole frame, x0,y0 inclusive, x1,y1 exclusive)");
    return PixelRegion{values[0], values[1], values[2], values[3]};
}

}  // namespace cmfilter::cli
