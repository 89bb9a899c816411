// SPDX-License-Identifier: Apache-2.0
// A fit of an image stack of either kind, as relight and info read it: a
// linear fit (PTM or HSH, linear_fit.h: one view, the one it was fitted at,
// taken as (0, 0, 1)) or per-texel Lafortune lobes (lafortune_model.h: the
// view it was fitted at, and any other view the model renders).
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/stack/image_stack.h"
#include "cmfilter/stack/lafortune_model.h"
#include "cmfilter/stack/linear_fit.h"
#include "cmfilter/stack/relight_error.h"
#include "cmfilter/util/error.h"

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace cmfilter {

using StackFit = std::variant<LinearFit, LafortuneFit>;

// By extension: `.ptm` and `.rti` are linear (fit_loading.h); otherwise an
// EXR by its cmfilter:kind, "linear-fit" (fit_file.h) or "lafortune-fit"
// (lafortune_file.h). Io: missing or unreadable. BadInput naming the file:
// not an image, or an EXR of neither kind (naming the kind found), or the
// reader's own refusal.
Expected<StackFit> load_stack_fit(const std::string& path);

int stack_fit_width(const StackFit& fit);
int stack_fit_height(const StackFit& fit);
int stack_fit_channels(const StackFit& fit);
std::size_t stack_fit_texels(const StackFit& fit);
StackEncoding stack_fit_encoding(const StackFit& fit);  // the values it reproduces
// "ptm-rgb", "ptm-lrgb", "hsh2", "hsh3", "lafortune" (luminance) or
// "lafortune-rgb": the name `fit --model` takes.
std::string stack_fit_model_name(const StackFit& fit);
// The view it was fitted at: a Lafortune fit's own, (0, 0, 1) for a linear fit.
Vec3 stack_fit_view(const StackFit& fit);

// The fit at light `light` (unit, z >= 0) seen from `view` (unit, z > 0;
// none: the fitted view): width * height * channels floats in the fit's
// encoding. BadInput for a linear fit and a view other than (0, 0, 1) (to
// 1e-9): a PTM or HSH holds one view.
Expected<std::vector<float>> relight_stack_fit(const StackFit& fit, const Vec3& light,
                                               const std::optional<Vec3>& view = std::nullopt, int threads = 0);

// The fit's error at the lights of the stack `reference` (relight_error.h),
// streamed from its files one image per thread, rendered at `view` (none:
// the fitted view; a linear fit refuses another, as relight_stack_fit
// does). The errors of relit_model_error_from_files.
Expected<RelightError> stack_fit_error(const StackFit& fit, const StackLoadOptions& reference,
                                       const ColorConfig& config, int threads = 0,
                                       const std::optional<Vec3>& view = std::nullopt);

}  // namespace cmfilter
