// SPDX-License-Identifier: Apache-2.0
// How far a Lafortune fit's relighting (at its fitted view) is from a
// stack's images at the stack's own lights, measured as relight_error.h
// measures a linear fit (the same per-light comparison, relit_model_error):
// both sides in scene-linear, the RMSE over every texel, channel and light,
// and CIEDE2000 per texel and light.
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/stack/image_stack.h"
#include "cmfilter/stack/lafortune_model.h"
#include "cmfilter/stack/relight_error.h"
#include "cmfilter/util/error.h"

namespace cmfilter {

// The fit relit at `view` (relight_lafortune) as relit_model_error and
// relit_model_error_from_files measure it; holds a reference to `fit`.
RelitModel lafortune_relit_model(const LafortuneFit& fit, const Vec3& view);

// BadInput when the fit and the stack differ in size or channels.
Expected<RelightError> lafortune_relight_error(const LafortuneFit& fit, const ImageStack& reference,
                                               const ColorConfig& config, int threads = 0);

}  // namespace cmfilter
