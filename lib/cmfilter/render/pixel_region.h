// SPDX-License-Identifier: Apache-2.0
// A rectangle of a frame's pixels, as OpenImageIO's ROI and OpenEXR's data
// window spell it: columns x0 .. x1 - 1 and rows y0 .. y1 - 1 (x0, y0
// inclusive, x1, y1 exclusive), in the full frame's pixel coordinates (0, 0
// the top-left pixel). `render` computes only a region's pixels, each
// exactly as the full frame's render computes it (docs/farm.md).
#pragma once

#include "cmfilter/util/error.h"

#include <string>

namespace cmfilter {

struct PixelRegion {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    bool operator==(const PixelRegion& o) const { return x0 == o.x0 && y0 == o.y0 && x1 == o.x1 && y1 == o.y1; }
};

// The whole frame of width x height pixels.
inline PixelRegion whole_frame(int width, int height) { return {0, 0, width, height}; }

// "x0,y0,x1,y1".
std::string to_string(const PixelRegion& region);

// BadInput naming `field` and the region unless it holds at least one pixel
// (x0 < x1 and y0 < y1) and lies within the width x height frame
// (0 <= x0, x1 <= width, 0 <= y0, y1 <= height).
Status check_pixel_region(const PixelRegion& region, int width, int height,
                          const std::string& field = "RenderOptions::region");

}  // namespace cmfilter
