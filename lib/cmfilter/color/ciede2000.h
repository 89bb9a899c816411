// SPDX-License-Identifier: Apache-2.0
// CIEDE2000 colour difference between scene-linear Rec.709 colours: the
// conversion to CIE L*a*b* (D65, white RGB (1,1,1) at L* = 100) and the full
// CIEDE2000 formula with kL = kC = kH = 1, implemented after Sharma, Wu & Dalal,
// "The CIEDE2000 color-difference formula: implementation notes, supplementary
// test data, and mathematical observations", Color Res. Appl. 30(1), 2005.
#pragma once

#include "cmfilter/color/color.h"

namespace cmfilter {

// A CIE 1976 L*a*b* colour (CIE 15:2004, section 8.2.1).
struct Lab {
    double L = 0, a = 0, b = 0;
};

// Scene-linear Rec.709 (sRGB primaries, D65 white) to CIE L*a*b*. Each channel
// is first clipped to [0, 1] (NaN becomes 0), so out-of-gamut and HDR values
// are measured as their clipped display colour. The reference white is the XYZ
// of RGB (1,1,1) under the same matrix: white maps to exactly (100, 0, 0).
Lab linear_rec709_to_lab(const Rgb& c);

// CIEDE2000 colour difference Delta E00 (kL = kC = kH = 1). Symmetric in its
// arguments up to rounding.
double ciede2000(const Lab& x, const Lab& y);

// ciede2000(linear_rec709_to_lab(x), linear_rec709_to_lab(y)).
double ciede2000_linear_rgb(const Rgb& x, const Rgb& y);

}  // namespace cmfilter
