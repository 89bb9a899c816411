// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/texture/filtered_texture.h"

#include "cmfilter/math/bilinear_texels.h"
#include "cmfilter/texture/texture_lod.h"

#include <algorithm>
#include <cmath>

namespace cmfilter {

Expected<FilteredTexture> FilteredTexture::create(MomentTexture moments, std::optional<std::vector<float>> level0,
                                                  std::shared_ptr<const TemporaryFile> owned)
{
    const MomentPyramidInfo& info = moments.info();
    const std::size_t texels = static_cast<std::size_t>(info.width) * static_cast<std::size_t>(info.height);
    if (level0 && level0->size() != texels)
        return bad_input("driver texture '" + moments.path() + "': " + std::to_string(level0->size()) +
                         " level-0 texels for a " + std::to_string(info.width) + " x " + std::to_string(info.height) +
                         " pyramid (expected " + std::to_string(texels) + ")");
    FilteredTexture out(std::move(moments));
    if (level0) out.level0_ = std::make_shared<const std::vector<float>>(std::move(*level0));
    out.owned_ = std::move(owned);
    return out;
}

MomentSample FilteredTexture::filter(double u, double v, double w) const
{
    // A periodic texture is the same a whole number of repeats away: brought
    // into [0, 1) first, far coordinates keep their precision in float.
    if (moments_.info().wrap == TextureWrap::Periodic) {
        u -= std::floor(u);
        v -= std::floor(v);
    }
    const double lod = trilinear_lod_for_box(this->lod(w));
    return moments_.lookup(static_cast<float>(u), static_cast<float>(v), static_cast<float>(lod));
}

double FilteredTexture::value(double u, double v) const
{
    if (!level0_) return moments_.reference();
    const std::vector<float>& f = *level0_;
    const int w = width();
    return bilinear_texels(u, v, w, height(), moments_.info().wrap, moments_.reference(),
                           [&](int x, int y) { return static_cast<double>(f[static_cast<std::size_t>(y) * w + x]); });
}

std::size_t FilteredTexture::distinct_values() const
{
    if (!level0_) return 0;
    std::vector<float> values = *level0_;
    std::sort(values.begin(), values.end());
    return static_cast<std::size_t>(std::unique(values.begin(), values.end()) - values.begin());
}

double FilteredTexture::lod(double w) const { return std::log2(w * width()); }

}  // namespace cmfilter
