// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/stack_encoding.h"

namespace cmfilter {

Status convert_stack_encoding(std::vector<float>& values, int channels, StackEncoding from, StackEncoding to,
                              const ColorConfig& config)
{
    if (from == to || channels <= 0) return ok();
    auto srgb = config.resolve("sRGB");
    if (!srgb) return srgb.error();
    const std::size_t texels = values.size() / channels;
    const int colour = channels >= 3 ? 3 : 1;
    std::vector<float> rgb(texels * 3);
    for (std::size_t t = 0; t < texels; ++t)
        for (int c = 0; c < 3; ++c) rgb[3 * t + c] = values[t * channels + (colour == 3 ? c : 0)];
    Status st = to == StackEncoding::SceneLinear ? config.to_scene_linear(rgb, *srgb)
                                                 : config.from_scene_linear(rgb, *srgb);
    if (!st) return st;
    for (std::size_t t = 0; t < texels; ++t)
        for (int c = 0; c < colour; ++c) values[t * channels + c] = rgb[3 * t + c];
    return ok();
}

}  // namespace cmfilter
