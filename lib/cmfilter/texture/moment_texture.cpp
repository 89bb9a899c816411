// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/texture/moment_texture.h"

#include "cmfilter/io/image_reading.h"
#include "cmfilter/texture/moment_pyramid.h"
#include "cmfilter/texture/texture_lod.h"

#include <OpenImageIO/texture.h>

#include <algorithm>
#include <cmath>

namespace cmfilter {

Expected<MomentTexture> MomentTexture::open(const std::string& path)
{
    auto in = open_image_input(path);
    if (!in) return in.error();
    auto info = get_moment_pyramid_metadata((*in)->spec(), path);
    if (!info) return info.error();
    if (auto st = check_tiled_mipmap(**in, info->levels, path); !st) return st.error();
    MomentTexture tex;
    tex.path_ = path;
    tex.info_ = *info;
    tex.ts_ = make_private_texture_system();
    return tex;
}

MomentSample MomentTexture::finish(bool ok, const float m[4]) const
{
    MomentSample out;
    out.ok = ok && std::all_of(m, m + info_.order, [](float v) { return std::isfinite(v); });
    if (!out.ok) {
        out.mean = info_.reference;
        return out;
    }
    // sigma_f^2 = mean (f-c)^2 - (mean (f-c))^2: the shift by c leaves the
    // variance unchanged and keeps both terms small. Rounding can make it
    // slightly negative where the footprint is nearly constant: clamp.
    const double m1 = m[0], m2 = m[1];
    out.mean = info_.reference + m1;
    out.variance = std::max(0.0, m2 - m1 * m1);
    out.sigma = std::sqrt(out.variance);
    if (info_.order == 4) {
        // Central moments from the raw ones about c (d = f - c, mean d = m1).
        const double m3 = m[2], m4 = m[3], m1s = m1 * m1;
        out.mu3 = m3 - 3 * m1 * m2 + 2 * m1s * m1;
        out.mu4 = std::max(0.0, m4 - 4 * m1 * m3 + 6 * m1s * m2 - 3 * m1s * m1s);
    }
    return out;
}

int MomentTexture::reachable_levels() const
{
    return reachable_texture_levels(info_.width, info_.height, info_.levels);
}

MomentSample MomentTexture::lookup(float s, float t, float lod) const
{
    const float fw = texture_lod(info_.width, info_.height, info_.levels, lod).filter_width;
    OIIO::TextureOpt opt;
    opt.interpmode = OIIO::TextureOpt::InterpBilinear;
    opt.mipmode = OIIO::TextureOpt::MipModeTrilinear;
    opt.conservative_filter = true;
    float m[4] = {0, 0, 0, 0};
    const bool ok = ts_->texture(OIIO::ustring(path_), opt, s, t, fw, 0, 0, fw, info_.order, m);
    return finish(ok, m);
}

MomentSample MomentTexture::lookup(float s, float t, float dsdx, float dtdx, float dsdy, float dtdy) const
{
    OIIO::TextureOpt opt;
    opt.interpmode = OIIO::TextureOpt::InterpBilinear;
    opt.mipmode = OIIO::TextureOpt::MipModeAniso;
    float m[4] = {0, 0, 0, 0};
    const bool ok = ts_->texture(OIIO::ustring(path_), opt, s, t, dsdx, dtdx, dsdy, dtdy, info_.order, m);
    return finish(ok, m);
}

}  // namespace cmfilter
