// SPDX-License-Identifier: Apache-2.0
// Converting a stack's or a fit's values between scene-linear and the
// display encoding that .ptm and .rti hold (the config's sRGB encoding,
// image_stack.h StackEncoding). The colour channels are the first three
// (or the one grey channel, converted as a grey colour); a fourth channel
// (alpha) is left as it is.
#pragma once

#include "cmfilter/color/color_config.h"
#include "cmfilter/stack/image_stack.h"
#include "cmfilter/util/error.h"

#include <vector>

namespace cmfilter {

// `values`: texels * channels floats, interleaved. From `from` to `to`
// (nothing to do when they are equal).
Status convert_stack_encoding(std::vector<float>& values, int channels, StackEncoding from, StackEncoding to,
                              const ColorConfig& config);

}  // namespace cmfilter
