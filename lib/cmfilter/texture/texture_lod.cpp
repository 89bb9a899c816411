// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/texture/texture_lod.h"

#include "cmfilter/texture/moment_pyramid.h"
#include "cmfilter/util/memory_budget.h"

#include <OpenImageIO/texture.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace cmfilter {

Status check_tiled_mipmap(OIIO::ImageInput& in, int levels, const std::string& path)
{
    int found = 0;
    while (in.seek_subimage(0, found)) ++found;
    if (found != levels || in.spec(0, 0).tile_width <= 0)
        return bad_input("'" + path + "' is not a tiled MIP-map with the " + std::to_string(levels) +
                         " levels its metadata names (found " + std::to_string(found) + ")");
    // The image cache opens every level of every subimage on the first
    // lookup: a pyramid is one subimage.
    if (in.seek_subimage(1, 0))
        return bad_input("'" + path + "' has more than one subimage; a pyramid is a single tiled MIP-map");
    for (int level = 0; level < levels; ++level)
        if (auto st = check_texture_level(in.spec(0, level), level, path); !st) return st;
    return ok();
}

Status check_texture_level(const OIIO::ImageSpec& spec, int level, const std::string& path)
{
    const std::string where = "level " + std::to_string(level) + " of '" + path + "'";
    if (spec.width < 1 || spec.height < 1 || spec.depth != 1 || spec.nchannels < 1)
        return bad_input(where + " is " + std::to_string(spec.width) + " x " + std::to_string(spec.height) + " x " +
                         std::to_string(spec.depth) + " pixels of " + std::to_string(spec.nchannels) +
                         " channels; expected at least 1 x 1 x 1 and one channel");
    if (spec.tile_width < 1 || spec.tile_height < 1 || spec.tile_depth != 1)
        return bad_input(where + " has tiles of " + std::to_string(spec.tile_width) + " x " +
                         std::to_string(spec.tile_height) + " x " + std::to_string(spec.tile_depth) +
                         " pixels; expected at least 1 x 1 x 1");
    // The image cache counts a level's tiles in an int and keeps a bit for
    // each; it reads one whole tile of floats at a time.
    const double tiles = std::ceil(double(spec.width) / spec.tile_width) *
                         std::ceil(double(spec.height) / spec.tile_height);
    if (tiles > double(std::numeric_limits<int>::max()))
        return bad_input(where + " has " + std::to_string(static_cast<long long>(tiles)) + " tiles of " +
                         std::to_string(spec.tile_width) + " x " + std::to_string(spec.tile_height) +
                         " pixels; at most " + std::to_string(std::numeric_limits<int>::max()) + " are supported");
    const double tile_bytes = double(spec.tile_width) * spec.tile_height * spec.nchannels * sizeof(float);
    return check_allocation(tile_bytes + tiles / 8, where + " (tiles of " + std::to_string(spec.tile_width) + " x " +
                                                        std::to_string(spec.tile_height) + " pixels, " +
                                                        std::to_string(spec.nchannels) + " channels)");
}

std::shared_ptr<OIIO::TextureSystem> make_private_texture_system()
{
    std::shared_ptr<OIIO::TextureSystem> ts(OIIO::TextureSystem::create(false),
                                            [](OIIO::TextureSystem* t) { OIIO::TextureSystem::destroy(t, true); });
    // Its tile cache: OpenImageIO's default 1 GB, but at most a quarter of
    // what this process may still allocate (a farm slot's limit), and at
    // least 32 MB (a few rows of tiles of any pyramid).
    const double budget_mb = static_cast<double>(memory_budget().bytes) / (1024.0 * 1024.0);
    const float cache_mb = static_cast<float>(std::clamp(budget_mb / 4, 32.0, 1024.0));
    ts->attribute("max_memory_MB", cache_mb);
    return ts;
}

int reachable_texture_levels(int width, int height, int levels)
{
    int k = 0;
    while (k + 1 < levels && std::min(moment_level_extent(width, k), moment_level_extent(height, k)) > 1) ++k;
    return k + 1;
}

TextureLod texture_lod(int width, int height, int levels, float lod)
{
    // TextureSystem (OpenImageIO 2.4, trilinear) picks levels from the filter
    // width fw in texture units: at level m it takes fw_m = fw * min(w_m, h_m)
    // and, at the first m with fw_m <= 1, blends level m - 1 with weight
    // 1 - (2 fw_m - 1) and level m with weight 2 fw_m - 1 (checked by
    // tests/unit/test_moment_pyramid.cpp). So fw = 1 / min(w_k, h_k) reads
    // level k alone, and fw = (1 + frac) / (2 min(w_k+1, h_k+1)) blends levels
    // k and k + 1 with weights 1 - frac and frac: linear in lod.
    const int top = reachable_texture_levels(width, height, levels) - 1;
    TextureLod out;
    out.lod = std::isfinite(lod) ? std::clamp(lod, 0.0f, static_cast<float>(top)) : 0.0f;
    const int k = static_cast<int>(std::floor(out.lod));
    const float frac = out.lod - static_cast<float>(k);
    const auto minwh = [&](int level) {
        return static_cast<float>(std::min(moment_level_extent(width, level), moment_level_extent(height, level)));
    };
    if (frac > 0) {
        out.filter_width = (1.0f + frac) / (2.0f * minwh(k + 1));
    } else {
        out.filter_width = 1.0f / minwh(k);
        if (out.filter_width * minwh(k) > 1.0f)
            out.filter_width = std::nextafter(out.filter_width, 0.0f);  // stay on level k
    }
    return out;
}

double trilinear_lod_for_box(double box_lod) { return box_lod - 0.5 * std::log2(3.0); }

}  // namespace cmfilter
