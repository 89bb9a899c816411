// SPDX-License-Identifier: Apache-2.0
// Surface normals from a linear fit: per texel the light direction at which
// the model's luminance is largest. For a PTM the polynomial's stationary
// point (Malzbender et al. 2001, eq. 16-17):
//   lu0 = (a2 a4 - 2 a1 a3) / (4 a0 a1 - a2^2),
//   lv0 = (a2 a3 - 2 a0 a4) / (4 a0 a1 - a2^2),
//   n = (lu0, lv0, sqrt(1 - lu0^2 - lv0^2)),
// when it is a maximum (4 a0 a1 - a2^2 > 0, a0 < 0) inside the unit disc.
// Otherwise (a saddle, a minimum, a near-zero determinant, a point outside
// the disc) a quadratic is largest on the disc's boundary, and the normal is
// the horizon direction found there by a search; a flat polynomial (no
// non-constant term) gives (0, 0, 1). Either way the texel is counted as
// degenerate. The luminance is PtmLrgb's own polynomial, else the Rec. 709
// combination of the first three channels' coefficients (one channel:
// itself; two: their mean). For HSH a search over the hemisphere (a coarse
// grid, then a local refinement); a texel is degenerate when its maximum
// lies on the horizon or the function is flat.
#pragma once

#include "cmfilter/stack/linear_fit.h"

#include <cstddef>
#include <vector>

namespace cmfilter {

struct FitNormals {
    int width = 0, height = 0;
    std::vector<float> normals;  // width * height * 3, unit, z >= 0, in the stack's frame
    std::size_t degenerate = 0;  // texels whose maximum was not an interior stationary point
};

FitNormals fit_normals(const LinearFit& fit, int threads = 0);

}  // namespace cmfilter
