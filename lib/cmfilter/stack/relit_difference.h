// SPDX-License-Identifier: Apache-2.0
// How far apart two linear fits of the same texels are once relit: the
// largest |a(l) - b(l)| over every texel, channel and light l of a dense set
// over the hemisphere. The interchange files (ptm_file.h, rti_file.h) state
// their quantisation error this way, comparing a fit with what was decoded
// from the bytes written. Values are unclamped (a viewer clamps to [0, 1],
// which can only shrink a difference).
#pragma once

#include "cmfilter/math/vec3.h"
#include "cmfilter/stack/linear_fit.h"

#include <vector>

namespace cmfilter {

// The directions the error is taken over: the pole (0, 0, 1) first, then a
// Fibonacci spiral of `count` directions with z = 1 - (i + 1/2) / count
// (equal solid angle per direction) and azimuth i times the golden angle.
std::vector<Vec3> hemisphere_directions(int count = 256);

// The largest |relit a - relit b| over texels, channels and `lights`
// (relit as linear_fit.h defines it: the basis (linear_model.h) weighted by
// the coefficients; PtmLrgb the polynomial times the base colour). The fits
// must have the same model, size and channels; threaded over rows, the
// result independent of the thread count.
double max_relit_difference(const LinearFit& a, const LinearFit& b, const std::vector<Vec3>& lights, int threads = 0);

}  // namespace cmfilter
