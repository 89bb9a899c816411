// SPDX-License-Identifier: Apache-2.0
// The baked colour pyramid (`--method color-pyramid`): the exact filtered
// colour of a driver through a colour map known when the driver is baked.
// Level 0 holds C0(f) per driver texel (colormap/color_map.h) and level k the
// box mean of C0(f) over the same footprint whose moments a moment pyramid
// stores (the level geometry of box_pyramid.h, docs/moments-format.md):
// mean C0(f), which the paper's filtering aims at (sec. 3, eq. 1 with a box
// kernel), stored, where `--method reference` (color_pyramid.h) computes it
// from the driver on the fly. It is what `oiiotool DRIVER --colormap ... |
// maketx --filter box` makes for a power-of-two driver, with the map read
// through OpenColorIO and means of level 0 (never means of means) for any
// size.
//
// The file is a tiled, mip-mapped OpenEXR with channels R, G, B in the
// config's scene-linear space, float32 or half (ExrOutputOptions: 12 or 6
// bytes per level-0 texel), that any renderer's texture system reads as a
// plain colour texture. Its cmfilter:* metadata name the driver (path,
// SHA-256) and the map by the digest of C0 as evaluated
// (colormap/color_map_digest.h), so a lookup through another map is refused.
// Beyond the edges it wraps as the driver's pyramids do; with black wrap a
// renderer reads black there (a moment pyramid reads C0(c)).
#pragma once

#include "cmfilter/colormap/color_map.h"
#include "cmfilter/io/driver_image.h"
#include "cmfilter/io/method_tolerance_record.h"
#include "cmfilter/texture/pyramid_bake_options.h"
#include "cmfilter/util/error.h"

#include <OpenImageIO/imageio.h>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

namespace cmfilter {

inline constexpr const char* kColorPyramidKind = "color-pyramid";
inline constexpr int kColorPyramidFormatVersion = 1;

struct ColorPyramidInfo {
    int width = 0, height = 0;  // level 0 = the driver's size
    int levels = 0;             // down to 1 x 1
    ExrPixelType pixel_type = ExrPixelType::Float;
    std::string linear_space;  // the colour space of the channels (the config's scene_linear)
    std::string channel;       // the driver channel used (name, else its index)
    int channel_index = 0;
    TextureWrap wrap = TextureWrap::Clamp;
    double driver_min = 0, driver_max = 0;
    std::string source;  // driver path as given
    std::string source_sha256;
    std::size_t nonfinite_replaced = 0;
    std::string map_sha256;  // color_map_sha256 of C0
    std::string map_source;  // where C0 was read from (a path as given), for messages
    double map_vmin = 0, map_vmax = 1;
    std::string baked_by;  // cmfilter version (filled in on read)
    // Set when bake-moments --tolerance chose this representation.
    std::optional<MethodToleranceRecord> method_choice;

    std::size_t bytes_per_texel() const { return pixel_type == ExrPixelType::Half ? 6 : 12; }
};

// The cmfilter:* attributes (and "wrapmodes"), paths recorded relative to
// `path` (io/recorded_path.h). Reading gives BadInput naming `path` when the
// file is not a colour pyramid or its metadata is inconsistent.
void set_color_pyramid_metadata(OIIO::ImageSpec& spec, const ColorPyramidInfo& info, const std::string& path);
Expected<ColorPyramidInfo> get_color_pyramid_metadata(const OIIO::ImageSpec& spec, const std::string& path);

struct ColorPyramidBakeOptions : PyramidBakeOptions {
    const ColorMap* map = nullptr;  // C0, scene-linear (required)
    std::string map_source;         // where it came from, recorded for messages
    std::string linear_space;       // its colour space (ColorConfig::scene_linear_name), recorded
    std::string linear_interop_id;  // ColorConfig::interop_id of it (empty: none)
    std::optional<MethodToleranceRecord> method_choice;
    std::function<void(double fraction)> progress;  // optional, from the calling thread
};

struct ColorPyramidBakeResult {
    ColorPyramidInfo info;
    double read_ms = 0, build_ms = 0, write_ms = 0;  // as MomentBakeResult
};

// BadInput for a missing or invalid map (naming ColorPyramidBakeOptions::map)
// or, with half storage, a colour past a half's range; the errors of reading
// the driver and writing the file. All or nothing.
Expected<ColorPyramidBakeResult> bake_color_pyramid(const ColorPyramidBakeOptions& options);
// The same from a driver already read and hashed with options.driver_read().
Expected<ColorPyramidBakeResult> bake_color_pyramid(const ColorPyramidBakeOptions& options, const HashedDriver& driver);

// BadInput when `info`'s pyramid was baked through another map than `map`:
// names both digests, the pyramid's recorded map and `map_name`, and whether
// the domain, the wrap or the colours differ.
Status check_color_pyramid_map(const ColorPyramidInfo& info, const std::string& pyramid_path, const ColorMap& map,
                               const std::string& map_name);

}  // namespace cmfilter
