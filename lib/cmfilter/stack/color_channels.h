// SPDX-License-Identifier: Apache-2.0
// The colour channels of interleaved stack values (the first three, or the
// one grey channel taken as a grey colour; a fourth channel, alpha, left as
// it is) passed through a conversion of interleaved RGB, as OpenColorIO's
// processors take them: what decoding a stack's images and changing a
// stack's or fit's encoding share (image_stack.cpp, stack_encoding.h).
#pragma once

#include "cmfilter/util/error.h"

#include <cstddef>
#include <vector>

namespace cmfilter {

// `values`: texels * channels floats; `convert`: Status(std::vector<float>& rgb).
template <typename Convert>
Status convert_color_channels(std::vector<float>& values, int channels, Convert&& convert)
{
    if (channels <= 0) return ok();
    const std::size_t texels = values.size() / channels;
    const int colour = channels >= 3 ? 3 : 1;
    std::vector<float> rgb(texels * 3);
    for (std::size_t t = 0; t < texels; ++t)
        for (int c = 0; c < 3; ++c) rgb[3 * t + c] = values[t * channels + (colour == 3 ? c : 0)];
    if (auto st = convert(rgb); !st) return st;
    for (std::size_t t = 0; t < texels; ++t)
        for (int c = 0; c < colour; ++c) values[t * channels + c] = rgb[3 * t + c];
    return ok();
}

}  // namespace cmfilter
