// How cmfilter's pyramids (moment and histogram pyramids, same level
// geometry) are looked up at a level of detail through OpenImageIO's
// TextureSystem: which levels it can reach, the isotropic filter width that
// makes its trilinear mode read exactly level lod (integer lod) or blend
// levels floor(lod) and floor(lod) + 1 linearly in lod, and opening one.
#pragma once

#include "cmfilter/error.h"

#include <OpenImageIO/imageio.h>

#include <memory>
#include <string>

namespace OIIO_NAMESPACE {
class TextureSystem;
}

namespace cmfilter {

// BadInput naming `path` unless the opened file is a tiled MIP-map with
// exactly `levels` levels (as its metadata names).
Status check_tiled_mipmap(OIIO::ImageInput& in, int levels, const std::string& path);

// A TextureSystem of the caller's own, so that its cache and options are
// nobody else's; destroyed with its last owner.
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

}  // namespace cmfilter
