#include "cmfilter/histogram_pyramid.h"

#include "cmfilter/image_reading.h"
#include "cmfilter/texture_lod.h"

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
    int levels = 0;
    while ((*in)->seek_subimage(0, levels)) ++levels;
    if (levels != info->levels || (*in)->spec(0, 0).tile_width <= 0)
        return bad_input("'" + path + "' is not a tiled MIP-map with the " +
                         std::to_string(info->levels) + " levels its metadata names (found " +
                         std::to_string(levels) + ")");
    HistogramTexture tex;
    tex.path_ = path;
    tex.info_ = *info;
    // A private TextureSystem, so that its cache and options are ours alone.
    tex.ts_.reset(OIIO::TextureSystem::create(false),
                  [](OIIO::TextureSystem* ts) { OIIO::TextureSystem::destroy(ts, true); });
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
