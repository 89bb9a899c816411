// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/stack_encoding.h"

#include "cmfilter/stack/color_channels.h"

namespace cmfilter {

Status convert_stack_encoding(std::vector<float>& values, int channels, StackEncoding from, StackEncoding to,
                              const ColorConfig& config)
{
    if (from == to || channels <= 0) return ok();
    auto srgb = config.srgb_texture_name();
    if (!srgb) return srgb.error();
    return convert_color_channels(values, channels, [&](std::vector<float>& rgb) {
        return to == StackEncoding::SceneLinear ? config.to_scene_linear(rgb, *srgb)
                                                : config.from_scene_linear(rgb, *srgb);
    });
}

}  // namespace cmfilter
