// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/texture/color_pyramid_texture.h"

#include "cmfilter/io/image_reading.h"
#include "cmfilter/texture/texture_lod.h"

#include <OpenImageIO/texture.h>

#include <cmath>

namespace cmfilter {

Expected<ColorPyramidTexture> ColorPyramidTexture::open(const std::string& path)
{
    auto in = open_image_input(path);
    if (!in) return in.error();
    auto info = get_color_pyramid_metadata((*in)->spec(), path);
    if (!info) return info.error();
    if (auto st = check_tiled_mipmap(**in, info->levels, path); !st) return st.error();
    ColorPyramidTexture tex;
    tex.path_ = path;
    tex.info_ = *info;
    tex.ts_ = make_private_texture_system();
    return tex;
}

int ColorPyramidTexture::reachable_levels() const
{
    return reachable_texture_levels(info_.width, info_.height, info_.levels);
}

ColorPyramidSample ColorPyramidTexture::lookup(float s, float t, float lod) const
{
    const float fw = texture_lod(info_.width, info_.height, info_.levels, lod).filter_width;
    OIIO::TextureOpt opt;
    opt.interpmode = OIIO::TextureOpt::InterpBilinear;
    opt.mipmode = OIIO::TextureOpt::MipModeTrilinear;
    opt.conservative_filter = true;
    float c[3] = {0, 0, 0};
    ColorPyramidSample out;
    out.ok = ts_->texture(OIIO::ustring(path_), opt, s, t, fw, 0, 0, fw, 3, c);
    if (!(std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]))) {
        out.ok = false;
        return out;
    }
    out.color = {c[0], c[1], c[2]};
    return out;
}

}  // namespace cmfilter
