#include "cmfilter/moment_texture.h"

#include "cmfilter/image_reading.h"
#include "cmfilter/moment_pyramid.h"

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
    int levels = 0;
    while ((*in)->seek_subimage(0, levels)) ++levels;
    if (levels != info->levels || (*in)->spec(0, 0).tile_width <= 0)
        return bad_input("'" + path + "' is not a tiled MIP-map with the " +
                         std::to_string(info->levels) + " levels its metadata names (found " +
                         std::to_string(levels) + ")");

    MomentTexture tex;
    tex.path_ = path;
    tex.info_ = *info;
    // A private TextureSystem, so that its cache and options are ours alone.
    tex.ts_.reset(OIIO::TextureSystem::create(false),
                  [](OIIO::TextureSystem* ts) { OIIO::TextureSystem::destroy(ts, true); });
    return tex;
}

MomentSample MomentTexture::finish(bool ok, const float m[2]) const
{
    MomentSample out;
    out.ok = ok && std::isfinite(m[0]) && std::isfinite(m[1]);
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
    return out;
}

int MomentTexture::reachable_levels() const
{
    int k = 0;
    while (k + 1 < info_.levels && std::min(moment_level_extent(info_.width, k),
                                            moment_level_extent(info_.height, k)) > 1)
        ++k;
    return k + 1;
}

MomentSample MomentTexture::lookup(float s, float t, float lod) const
{
    // TextureSystem (OpenImageIO 2.4, trilinear) picks levels from the filter
    // width fw in texture units: at level m it takes fw_m = fw * min(w_m, h_m)
    // and, at the first m with fw_m <= 1, blends level m - 1 with weight
    // 1 - (2 fw_m - 1) and level m with weight 2 fw_m - 1 (checked by
    // tests/unit/test_moment_texture.cpp). So fw = 1 / min(w_k, h_k) reads
    // level k alone, and fw = (1 + frac) / (2 min(w_k+1, h_k+1)) blends levels
    // k and k + 1 with weights 1 - frac and frac: linear in lod.
    const int top = reachable_levels() - 1;
    lod = std::isfinite(lod) ? std::clamp(lod, 0.0f, static_cast<float>(top)) : 0.0f;
    const int k = static_cast<int>(std::floor(lod));
    const float frac = lod - static_cast<float>(k);
    const auto minwh = [&](int level) {
        return static_cast<float>(std::min(moment_level_extent(info_.width, level),
                                           moment_level_extent(info_.height, level)));
    };
    float fw;
    if (frac > 0) {
        fw = (1.0f + frac) / (2.0f * minwh(k + 1));
    } else {
        fw = 1.0f / minwh(k);
        if (fw * minwh(k) > 1.0f) fw = std::nextafter(fw, 0.0f);  // stay on level k
    }
    OIIO::TextureOpt opt;
    opt.interpmode = OIIO::TextureOpt::InterpBilinear;
    opt.mipmode = OIIO::TextureOpt::MipModeTrilinear;
    opt.conservative_filter = true;
    float m[2] = {0, 0};
    const bool ok = ts_->texture(OIIO::ustring(path_), opt, s, t, fw, 0, 0, fw, 2, m);
    return finish(ok, m);
}

MomentSample MomentTexture::lookup(float s, float t, float dsdx, float dtdx, float dsdy,
                                   float dtdy) const
{
    OIIO::TextureOpt opt;
    opt.interpmode = OIIO::TextureOpt::InterpBilinear;
    opt.mipmode = OIIO::TextureOpt::MipModeAniso;
    float m[2] = {0, 0};
    const bool ok = ts_->texture(OIIO::ustring(path_), opt, s, t, dsdx, dtdx, dsdy, dtdy, 2, m);
    return finish(ok, m);
}

}  // namespace cmfilter
