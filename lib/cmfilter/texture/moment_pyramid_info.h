// SPDX-License-Identifier: Apache-2.0
// What a moment pyramid file says about itself: the cmfilter:* metadata that
// bake_moment_pyramid writes into the file's header and MomentTexture reads
// back (docs/moments-format.md). The attribute names live only here.
#pragma once

#include "cmfilter/util/error.h"
#include "cmfilter/io/method_tolerance_record.h"
#include "cmfilter/math/texture_wrap.h"

#include <OpenImageIO/imageio.h>

#include <cstddef>
#include <optional>
#include <string>

namespace cmfilter {

inline constexpr const char* kMomentPyramidKind = "moment-pyramid";
inline constexpr int kMomentPyramidFormatVersion = 1;

struct MomentPyramidInfo {
    int width = 0, height = 0;  // level 0 = the driver's size
    int levels = 0;             // down to 1 x 1
    double reference = 0;       // c: channels hold box means of (f - c) and (f - c)^2
    int order = 2;              // moments per texel: 2 (m1, m2) or 4 (also (f - c)^3, (f - c)^4)
    double driver_min = 0, driver_max = 0;
    std::string channel;  // the driver channel used (name, else its index)
    int channel_index = 0;
    TextureWrap wrap = TextureWrap::Clamp;
    std::string source;  // driver path as given
    std::string source_sha256;
    std::string source_pixel_type;
    std::size_t nonfinite_replaced = 0;
    std::string baked_by;  // cmfilter version (filled in on write)
    // Set when the order was chosen for a tolerance (bake-moments
    // --tolerance): the method that met it against the colour table
    // `method_choice->table` (a path as given; recorded relative to the file).
    std::optional<MethodToleranceRecord> method_choice;
};

// Sets the cmfilter:* attributes (and the "wrapmodes" TextureSystem reads) on
// the level-0 spec of the pyramid being written to `path` (the source
// recorded relative to it: io/recorded_path.h).
void set_moment_pyramid_metadata(OIIO::ImageSpec& spec, const MomentPyramidInfo& info, const std::string& path);

// Reads them back from a file's level-0 spec. BadInput naming `path` when the
// file is not a moment pyramid, has another format version, or its metadata
// is missing or inconsistent with its size.
Expected<MomentPyramidInfo> get_moment_pyramid_metadata(const OIIO::ImageSpec& spec, const std::string& path);

}  // namespace cmfilter
