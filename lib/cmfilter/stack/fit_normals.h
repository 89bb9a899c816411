// SPDX-License-Identifier: Apache-2.0
// Surface normals from a linear fit: per texel the light direction at which
// the model's luminance is largest. For a PTM the polynomial's stationary
// point (Malzbender et al. 2001, eq. 16-17):
//   lu0 = (a2 a4 - 2 a1 a3) / (4 a0 a1 - a2^2),
//   lv0 = (a2 a3 - 2 a0 a4) / (4 a0 a1 - a2^2),
//   n = (lu0, lv0, sqrt(1 - lu0^2 - lv0^2)),
// when it is a maximum inside the unit disc; otherwise (a saddle, a
// minimum, a flat or degenerate polynomial, a point outside the disc) the
// maximum over the disc's boundary or a search over the hemisphere, and the
// texel is counted as degenerate. For HSH a search over the hemisphere.
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
