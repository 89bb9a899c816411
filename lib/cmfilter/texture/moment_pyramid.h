// SPDX-License-Identifier: Apache-2.0
// Baking a moment pyramid (Heitz et al. 2013, sec. 4.2): for tabulated f,
// "precompute the first two moments of f, mean f and mean f^2, at each level
// of detail in a mipmap hierarchy"; a lookup then gets sigma_f^2 = mean f^2 -
// (mean f)^2 after linear interpolation of both. The file is a tiled,
// mip-mapped float32 OpenEXR that OpenImageIO's TextureSystem reads, with two
// channels per level: the box means of (f - c) and (f - c)^2 about a
// reference value c (the driver's mean, in the metadata), so that the
// variance does not cancel in float for drivers far from 0.
//
// Level k is w_k x h_k = max(1, W >> k) x max(1, H >> k) (OpenEXR's
// round-down mip levels), and its texel (x, y) is the exact box mean over the
// level-0 rectangle [x W / w_k, (x+1) W / w_k) x [y H / h_k, (y+1) H / h_k),
// fractional texels weighted by the part covered, for any size
// (docs/moments-format.md). The driver is held once in memory as float; level
// 0 is written tile row by tile row, encoded on a writer thread while the
// next row is computed, and every upper level is accumulated from the same
// rows, so the peak is about 1.7 driver copies.
#pragma once

#include "cmfilter/io/driver_image.h"
#include "cmfilter/util/error.h"
#include "cmfilter/texture/moment_pyramid_info.h"
#include "cmfilter/texture/pyramid_bake_options.h"
#include "cmfilter/math/texture_wrap.h"

#include <functional>
#include <optional>
#include <string>

namespace cmfilter {

struct MomentBakeOptions : PyramidBakeOptions {
    // 2: m1, m2 (the paper's two moments); 4: also the box means of (f - c)^3
    // and (f - c)^4, for the two-Gaussian mixture (math/moment_mixture.h).
    int order = 2;
    // Recorded in the file when set (bake-moments --tolerance:
    // MomentPyramidInfo::method_choice).
    std::optional<MethodToleranceRecord> method_choice;
    std::function<void(double fraction)> progress;  // optional, from the calling thread
};

struct MomentBakeResult {
    MomentPyramidInfo info;
    double read_ms = 0;   // decode the driver, scan it for non-finite texels and statistics
    double build_ms = 0;  // compute the moments of every level
    double write_ms = 0;  // encode and write the tiles (compression included) beyond
                          // what overlaps the build: read + build + write is the total
};

Expected<MomentBakeResult> bake_moment_pyramid(const MomentBakeOptions& options);

// The same from a driver already read (and hashed) from options.driver_path
// with options.driver_read(), for a caller that keeps its texels too; read_ms
// is 0.
Expected<MomentBakeResult> bake_moment_pyramid(const MomentBakeOptions& options, const HashedDriver& driver);

// Extent of level k along an axis of `extent` level-0 texels: max(1, extent >> k).
int moment_level_extent(int extent, int level);
// Levels down to 1 x 1: floor(log2(max(width, height))) + 1.
int moment_level_count(int width, int height);

}  // namespace cmfilter
