// SPDX-License-Identifier: Apache-2.0
// The library's artefacts as the shaders of shaders/ take them: a colour
// table's axes as the CmfColorTable struct (std430 and std140 alike: nine
// 4-byte scalars), and a moment pyramid file's MIP levels as a renderer reads
// them, ready for float_texture (headless_gl.h).
#pragma once

#include "headless_gl.h"

#include "cmfilter/tables/gaussian_color_table.h"

#include <cstdint>
#include <string>
#include <vector>

namespace cmfilter_gl {

// CmfColorTable of shaders/cmfilter_color_table.glsl, field for field.
struct ColorTableBlock {
    float domain_min, domain_max, value_first, value_last, sigma_max;
    std::int32_t values, sigmas, wrap, sigma_spacing;
};

ColorTableBlock color_table_block(const cmfilter::TableAxes& axes);

// GL_REPEAT, GL_MIRRORED_REPEAT or GL_CLAMP_TO_EDGE for a colour map's wrap.
GLenum color_map_wrap(cmfilter::WrapMode wrap);

struct MomentLevels {
    std::vector<std::vector<float>> texels;  // per level: m1, m2 interleaved, rows in file order
    std::vector<TextureLevel> levels;        // views of texels
};

// Every MIP level of subimage 0 of the moment pyramid at `path` (two
// channels); throws std::runtime_error naming the file and the level.
MomentLevels read_moment_levels(const std::string& path);
// The same for any pyramid of `channels` channels (a colour pyramid: 3).
MomentLevels read_pyramid_levels(const std::string& path, int channels);

}  // namespace cmfilter_gl
