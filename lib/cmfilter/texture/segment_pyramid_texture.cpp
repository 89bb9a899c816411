// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/texture/segment_pyramid_texture.h"

#include "cmfilter/io/image_reading.h"
#include "cmfilter/texture/texture_lod.h"

#include <OpenImageIO/texture.h>

#include <algorithm>
#include <cmath>

namespace cmfilter {

Expected<SegmentPyramidTexture> SegmentPyramidTexture::open(const std::string& path)
{
    auto in = open_image_input(path);
    if (!in) return in.error();
    auto info = get_segment_pyramid_metadata((*in)->spec(), path);
    if (!info) return info.error();
    if (auto st = check_tiled_mipmap(**in, info->levels, path); !st) return st.error();
    SegmentPyramidTexture tex;
    tex.path_ = path;
    tex.info_ = *info;
    tex.ts_ = make_private_texture_system();
    return tex;
}

int SegmentPyramidTexture::reachable_levels() const
{
    return reachable_texture_levels(info_.width, info_.height, info_.levels);
}

bool SegmentPyramidTexture::lookup(float s, float t, float lod, float* ramps) const
{
    // Bilinear and trilinear weights are positive: the means stay in [0, 1].
    const float fw = texture_lod(info_.width, info_.height, info_.levels, lod).filter_width;
    OIIO::TextureOpt opt;
    opt.interpmode = OIIO::TextureOpt::InterpBilinear;
    opt.mipmode = OIIO::TextureOpt::MipModeTrilinear;
    opt.conservative_filter = true;
    const int n = channels();
    std::fill(ramps, ramps + n, 0.0f);
    bool ok = ts_->texture(OIIO::ustring(path_), opt, s, t, fw, 0, 0, fw, n, ramps);
    for (int k = 0; k < n; ++k) {
        if (!std::isfinite(ramps[k])) ok = false;
        ramps[k] = std::isfinite(ramps[k]) ? std::clamp(ramps[k], 0.0f, 1.0f) : 0.0f;
    }
    return ok;
}

}  // namespace cmfilter
