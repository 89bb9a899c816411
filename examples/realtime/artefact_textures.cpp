// SPDX-License-Identifier: Apache-2.0
#include "artefact_textures.h"

#include "cmfilter/io/image_reading.h"

#include <stdexcept>

namespace cmfilter_gl {

ColorTableBlock color_table_block(const cmfilter::TableAxes& ax)
{
    using cmfilter::WrapMode;
    const std::int32_t wrap = ax.wrap == WrapMode::Clamp ? 0 : ax.wrap == WrapMode::Mirror ? 1 : 2;
    return {static_cast<float>(ax.vmin),
            static_cast<float>(ax.vmax),
            static_cast<float>(ax.value_first()),
            static_cast<float>(ax.value_last()),
            static_cast<float>(ax.sigma_max),
            ax.values,
            ax.sigmas,
            wrap,
            ax.spacing == cmfilter::SigmaSpacing::Sqrt ? 1 : 0};
}

GLenum color_map_wrap(cmfilter::WrapMode wrap)
{
    using cmfilter::WrapMode;
    return wrap == WrapMode::Repeat ? GL_REPEAT : wrap == WrapMode::Mirror ? GL_MIRRORED_REPEAT : GL_CLAMP_TO_EDGE;
}

MomentLevels read_moment_levels(const std::string& path) { return read_pyramid_levels(path, 2); }

MomentLevels read_pyramid_levels(const std::string& path, int channels)
{
    auto in = cmfilter::open_image_input(path);
    if (!in) throw std::runtime_error(in.error().message);
    MomentLevels out;
    for (int k = 0; (*in)->seek_subimage(0, k); ++k) {
        const OIIO::ImageSpec& spec = (*in)->spec();
        if (spec.nchannels != channels)
            throw std::runtime_error(path + ": level " + std::to_string(k) + " has not " + std::to_string(channels) +
                                     " channels");
        out.texels.emplace_back(static_cast<std::size_t>(spec.width) * spec.height * channels);
        if (!cmfilter::read_float_pixels(**in, 0, k, 0, channels, out.texels.back().data()))
            throw std::runtime_error(path + ": cannot read MIP level " + std::to_string(k));
        out.levels.push_back({spec.width, spec.height, nullptr});
    }
    for (std::size_t k = 0; k < out.levels.size(); ++k) out.levels[k].texels = out.texels[k].data();
    return out;
}

}  // namespace cmfilter_gl
