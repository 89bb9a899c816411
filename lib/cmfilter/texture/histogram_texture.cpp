// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/texture/histogram_pyramid.h"

#include "cmfilter/io/image_reading.h"
#include "cmfilter/texture/texture_lod.h"

#include <OpenImageIO/texture.h>

#include <algorithm>
#include <cmath>

namespace cmfilter {

Expected<HistogramTexture> HistogramTexture::open(const std::string& path)
{
    auto in = open_image_input(path);
    if (!in) return in.error();
    auto info = get_histogram_pyramid_metadata((*in)->spec(), path);
    if (!info) return info.error();
    if (auto st = check_tiled_mipmap(**in, info->levels, path); !st) return st.error();
    HistogramTexture tex;
    tex.path_ = path;
    tex.info_ = *info;
    tex.ts_ = make_private_texture_system();
    return tex;
}

bool HistogramTexture::lookup(float s, float t, float lod, float* weights) const
{
    // Bilinear inside a level and linear across levels: positive weights, so
    // the histograms stay histograms (never bicubic, whose negative lobes
    // would make some fractions negative).
    const float fw = texture_lod(info_.width, info_.height, info_.levels, lod).filter_width;
    OIIO::TextureOpt opt;
    opt.interpmode = OIIO::TextureOpt::InterpBilinear;
    opt.mipmode = OIIO::TextureOpt::MipModeTrilinear;
    opt.conservative_filter = true;
    const int n = bins();
    std::fill(weights, weights + n, 0.0f);
    bool ok = ts_->texture(OIIO::ustring(path_), opt, s, t, fw, 0, 0, fw, n, weights);
    for (int b = 0; b < n; ++b) {
        if (!std::isfinite(weights[b])) ok = false;
        weights[b] = std::isfinite(weights[b]) ? std::max(0.0f, weights[b]) : 0.0f;
    }
    return ok;
}

}  // namespace cmfilter
