// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/texture/segment_pyramid_texture.h"

#include "cmfilter/io/image_reading.h"
#include "cmfilter/math/bilinear_texels.h"
#include "cmfilter/texture/moment_pyramid.h"
#include "cmfilter/texture/texture_lod.h"
#include "cmfilter/util/memory_budget.h"

#include <OpenImageIO/imageio.h>
#include <OpenImageIO/texture.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <vector>

namespace cmfilter {

// Level k of the file, channels() floats a texel, row-major from the top
// row, read on its first lookup (once, whichever thread asks first).
struct SegmentPyramidTexture::MemoryLevels {
    struct Level {
        int w = 0, h = 0;
        std::vector<float> texels;
        bool read = false;  // false: unreadable, every lookup there fails
    };
    std::vector<Level> levels;
    std::unique_ptr<std::once_flag[]> once;
    std::vector<float> zeros;  // a black neighbour: every ramp mean 0 (C_0)

    const Level& level(int k, const std::string& path)
    {
        std::call_once(once[k], [&] {
            Level& L = levels[k];
            auto in = open_image_input(path);
            if (!in) return;
            // The level as the file has it must be the level as its metadata
            // sizes it (a file changed since open, or not the one checked).
            const OIIO::ImageSpec spec = (*in)->spec(0, k);
            const int n = static_cast<int>(zeros.size());
            if (spec.width != L.w || spec.height != L.h || spec.nchannels < n) return;
            L.texels.resize(static_cast<std::size_t>(L.w) * L.h * zeros.size());
            L.read = read_float_pixels(**in, 0, k, 0, n, L.texels.data());
            if (!L.read) L.texels.clear();
        });
        return levels[k];
    }
};

namespace {

// Every level's texels as float: what PyramidReads::Memory holds at most.
double memory_bytes(const SegmentPyramidInfo& info)
{
    double texels = 0;
    for (int k = 0; k < info.levels; ++k)
        texels += double(moment_level_extent(info.width, k)) * double(moment_level_extent(info.height, k));
    return texels * info.channels() * sizeof(float);
}

}  // namespace

Expected<SegmentPyramidTexture> SegmentPyramidTexture::open(const std::string& path, PyramidReads reads)
{
    auto in = open_image_input(path);
    if (!in) return in.error();
    auto info = get_segment_pyramid_metadata((*in)->spec(), path);
    if (!info) return info.error();
    if (auto st = check_tiled_mipmap(**in, info->levels, path); !st) return st.error();
    SegmentPyramidTexture tex;
    tex.path_ = path;
    tex.info_ = *info;
    const double bytes = memory_bytes(*info);
    if (reads == PyramidReads::Auto)
        reads = bytes <= std::min(kMemoryReadsBytes, 0.25 * double(memory_budget().bytes))
                    ? PyramidReads::Memory
                    : PyramidReads::TextureSystem;
    if (reads == PyramidReads::Memory) {
        if (auto st = check_allocation(bytes, "segment pyramid '" + path + "' read into memory (" +
                                                  std::to_string(info->levels) + " levels of " +
                                                  std::to_string(info->channels()) + " channels as float)");
            !st)
            return st.error();
        auto memory = std::make_shared<MemoryLevels>();
        memory->levels.resize(static_cast<std::size_t>(info->levels));
        for (int k = 0; k < info->levels; ++k)
            memory->levels[k] = {moment_level_extent(info->width, k), moment_level_extent(info->height, k), {}, false};
        memory->once = std::make_unique<std::once_flag[]>(static_cast<std::size_t>(info->levels));
        memory->zeros.assign(static_cast<std::size_t>(info->channels()), 0.0f);
        tex.memory_ = std::move(memory);
    } else {
        tex.ts_ = make_private_texture_system();
    }
    return tex;
}

int SegmentPyramidTexture::reachable_levels() const
{
    return reachable_texture_levels(info_.width, info_.height, info_.levels);
}

bool SegmentPyramidTexture::lookup_memory(float s, float t, float lod, float* ramps) const
{
    // The levels texture_lod selects, blended as TextureSystem blends them:
    // level k alone at an integer lod, else k and k + 1 linearly in lod.
    const int n = channels();
    const float at = texture_lod(info_.width, info_.height, info_.levels, lod).lod;
    const int k = static_cast<int>(std::floor(at));
    const float frac = at - static_cast<float>(k);
    bool ok = true;
    std::fill(ramps, ramps + n, 0.0f);
    for (int j = 0; j < (frac > 0 ? 2 : 1); ++j) {
        const MemoryLevels::Level& L = memory_->level(k + j, path_);
        if (!L.read) {
            ok = false;
            continue;
        }
        const BilinearTaps taps = bilinear_taps(s, t, L.w, L.h, info_.wrap);
        const auto texel = [&](int i, int r) {
            const int x = taps.x[i], y = taps.y[r];
            return x < 0 || y < 0 ? memory_->zeros.data()
                                  : L.texels.data() + (static_cast<std::size_t>(y) * L.w + x) * n;
        };
        const float *p00 = texel(0, 0), *p10 = texel(1, 0), *p01 = texel(0, 1), *p11 = texel(1, 1);
        const double a = taps.a, b = taps.b, weight = j == 0 ? 1.0 - frac : frac;
        for (int c = 0; c < n; ++c) {
            const double top = p00[c] + a * (p10[c] - p00[c]);
            const double bottom = p01[c] + a * (p11[c] - p01[c]);
            ramps[c] += static_cast<float>(weight * (top + b * (bottom - top)));
        }
    }
    return ok;
}

bool SegmentPyramidTexture::lookup(float s, float t, float lod, float* ramps) const
{
    const int n = channels();
    bool ok = true;
    if (memory_) {
        ok = lookup_memory(s, t, lod, ramps);
    } else {
        // Bilinear and trilinear weights are positive: the means stay in [0, 1].
        const float fw = texture_lod(info_.width, info_.height, info_.levels, lod).filter_width;
        OIIO::TextureOpt opt;
        opt.interpmode = OIIO::TextureOpt::InterpBilinear;
        opt.mipmode = OIIO::TextureOpt::MipModeTrilinear;
        opt.conservative_filter = true;
        std::fill(ramps, ramps + n, 0.0f);
        ok = ts_->texture(OIIO::ustring(path_), opt, s, t, fw, 0, 0, fw, n, ramps);
    }
    for (int k = 0; k < n; ++k) {
        if (!std::isfinite(ramps[k])) ok = false;
        ramps[k] = std::isfinite(ramps[k]) ? std::clamp(ramps[k], 0.0f, 1.0f) : 0.0f;
    }
    return ok;
}

}  // namespace cmfilter
