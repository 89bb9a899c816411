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

#include <functional>
#include <string>
#include <vector>

namespace cmfilter {

struct RelightError {
    int lights = 0;
    double rmse = 0;                    // scene-linear
    ErrorSummary delta_e;               // CIEDE2000 over texels x lights
    std::vector<double> light_rmse;     // per light, in the stack's order
    std::vector<double> light_delta_e;  // mean CIEDE2000 per light
};

// Any relighting model as the errors measure it: its size and channels,
// the values it reproduces, and its image at a light (width * height *
// channels floats in `encoding`, row-major, top row first), computed on the
// calling thread (the errors run one light per thread). `what` names it in
// messages ("the fit", "the Lafortune fit").
struct RelitModel {
    int width = 0, height = 0, channels = 0;
    StackEncoding encoding = StackEncoding::SceneLinear;
    std::function<std::vector<float>(const Vec3& light)> relight;
    std::string what = "the fit";
    std::size_t texels() const { return static_cast<std::size_t>(width) * height; }
};

// A linear fit as a RelitModel (relight(fit, light, 1)); holds a reference
// to `fit`.
RelitModel linear_relit_model(const LinearFit& fit);

// BadInput when the model and the stack differ in size or channels.
Expected<RelightError> relit_model_error(const RelitModel& model, const ImageStack& reference,
                                         const ColorConfig& config, int threads = 0);
// relit_model_error streamed from the stack's files, as
// relight_error_from_files below streams them.
Expected<RelightError> relit_model_error_from_files(const RelitModel& model, const StackLoadOptions& reference,
                                                    const ColorConfig& config, int threads = 0);

// BadInput when the fit and the stack differ in size or channels.
Expected<RelightError> relight_error(const LinearFit& fit, const ImageStack& reference, const ColorConfig& config,
                                     int threads = 0);

// relight_error(fit, load_image_stack(reference, config), config) without
// holding the stack: its images read one at a time per thread (`threads` of
// them in flight, 0: the hardware threads; StackLoadOptions::threads is not
// used), each relit, compared and dropped. The same RMSEs (the same sums in
// the same order) and CIEDE2000 mean (to rounding), maximum and exact
// 95th percentile (streamed_error_summary.h: its selection usually ends
// with the first reading of the images, and may read them again, up to
// three more times, when the percentile's estimate leaves the values it
// keeps: at most 2^23 of them, 64 MiB). The errors of load_image_stack (the
// light file, the light count, a missing or unreadable image, a non-finite
// value, an image whose size or channels differ from the first's), and
// BadInput when the first image's size or channels differ from the fit's.
// Peak memory: per image in flight the image, the fit relit at its light
// (4 bytes x texels x channels each) and its differences (8 bytes x texels).
Expected<RelightError> relight_error_from_files(const LinearFit& fit, const StackLoadOptions& reference,
                                                const ColorConfig& config, int threads = 0);

}  // namespace cmfilter
