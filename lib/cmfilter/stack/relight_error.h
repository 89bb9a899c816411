// SPDX-License-Identifier: Apache-2.0
// How far a fit's relighting is from a stack's images at the stack's own
// lights: the training lights of the stack it was fitted to, or held-out
// lights rendered by make-stack. Both sides are compared in scene-linear
// (display-encoded values decoded first, stack_encoding.h): the RMSE over
// every texel, channel and light, and CIEDE2000 per texel and light
// (ciede2000.h: clipped to [0, 1], a grey channel taken as a grey colour).
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/color/error_summary.h"
#include "cmfilter/stack/image_stack.h"
#include "cmfilter/stack/linear_fit.h"
#include "cmfilter/util/error.h"

#include <vector>

namespace cmfilter {

struct RelightError {
    int lights = 0;
    double rmse = 0;                    // scene-linear
    ErrorSummary delta_e;               // CIEDE2000 over texels x lights
    std::vector<double> light_rmse;     // per light, in the stack's order
    std::vector<double> light_delta_e;  // mean CIEDE2000 per light
};

// BadInput when the fit and the stack differ in size or channels.
Expected<RelightError> relight_error(const LinearFit& fit, const ImageStack& reference, const ColorConfig& config,
                                     int threads = 0);

}  // namespace cmfilter
