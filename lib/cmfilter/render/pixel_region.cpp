// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/render/pixel_region.h"

namespace cmfilter {

std::string to_string(const PixelRegion& region)
{
    return std::to_string(region.x0) + "," + std::to_string(region.y0) + "," + std::to_string(region.x1) + "," +
           std::to_string(region.y1);
}

Status check_pixel_region(const PixelRegion& region, int width, int height, const std::string& field)
{
    const std::string expected = "x0,y0 inclusive, x1,y1 exclusive, in the " + std::to_string(width) + " x " +
                                 std::to_string(height) + " frame: 0 <= x0 < x1 <= " + std::to_string(width) +
                                 " and 0 <= y0 < y1 <= " + std::to_string(height);
    if (region.x1 <= region.x0 || region.y1 <= region.y0)
        return bad_input(field + " " + to_string(region) + " is empty (expected " + expected + ")", field);
    if (region.x0 < 0 || region.y0 < 0 || region.x1 > width || region.y1 > height)
        return bad_input(field + " " + to_string(region) + " lies outside the frame (expected " + expected + ")",
                         field);
    return ok();
}

}  // namespace cmfilter
