// SPDX-License-Identifier: Apache-2.0
// How cmfilter's pyramids (moment and histogram pyramids, same level
// geometry) are looked up at a level of detail through OpenImageIO's
// TextureSystem: which levels it can reach, the isotropic filter width that
// makes its trilinear mode read exactly level lod (integer lod) or blend
// levels floor(lod) and floor(lod) + 1 linearly in lod, and opening one.
#pragma once

#include "cmfilter/util/error.h"

#include <OpenImageIO/imageio.h>

#include <memory>
#include <string>

namespace OIIO_NAMESPACE {
class TextureSystem;
}

namespace cmfilter {

// BadInput naming `path` unless the opened file is a tiled MIP-map with
// exactly `levels` levels (as its metadata names) and a single subimage (OpenImageIO's image cache opens every level of
// every subimage on the first lookup); each level is then checked by
// check_texture_level.
Status check_tiled_mipmap(OIIO::ImageInput& in, int levels, const std::string& path);

// BadInput naming `path` and `level` unless the level is a 2D image of at
// least one pixel and one channel in tiles of at least one pixel, with no
// more tiles than OpenImageIO's image cache can count (it counts them in an
// int), and one tile of floats and the cache's bit a tile fit in the memory
// budget (util/memory_budget.h).
Status check_texture_level(const OIIO::ImageSpec& spec, int level, const std::string& path);

// A TextureSystem of the caller's own, so that its cache and options are
// nobody else's; destroyed with its last owner. Its tile cache holds at most
// a quarter of the memory budget (util/memory_budget.h), between 32 MB and
// OpenImageIO's default of 1 GB.
std::shared_ptr<OIIO::TextureSystem> make_private_texture_system();

// Levels TextureSystem can select for a pyramid of `levels` levels over a
// width x height level 0: it sizes filters by the smaller side of each level,
// so levels past the first whose smaller side is 1 texel are never read (all
// levels for a square driver).
int reachable_texture_levels(int width, int height, int levels);

struct TextureLod {
    float lod = 0;           // lod clamped to [0, reachable - 1] (NaN and Inf: 0)
    float filter_width = 0;  // in texture units, for TextureSystem::texture's dsdx = dtdy
};

TextureLod texture_lod(int width, int height, int levels, float lod);

// The trilinear lookup LOD that stands for a square box footprint of LOD
// `box_lod` (log2 of its width w in level-0 texels). A lookup at level k
// reads texels that are box means over 2^k texels and interpolates them
// bilinearly: its kernel along each axis is a box of width 2^k convolved with
// a tent of half-width 2^k, of variance 4^k / 12 + 4^k / 6 = 4^k / 4, three
// times that of the box, w^2 / 12. Matching the two, 4^k / 4 = w^2 / 12,
// gives k = log2(w / sqrt(3)): box_lod - log2(sqrt(3)) (as the rms footprint
// width matches variances, footprint_width.h). A box centred on a texel of
// level k + 1 reads that texel whatever the blend of levels k and k + 1: its
// bilinear weights at level k are the four texels it covers, 1/4 each.
double trilinear_lod_for_box(double box_lod);

}  // namespace cmfilter
