// SPDX-License-Identifier: Apache-2.0
// A segment pyramid (segment_pyramid_file.h) opened for lookups as a renderer
// reads it: bilinear inside a level and trilinear across levels (the
// footprints of MomentTexture and ColorPyramidTexture), at the levels
// texture_lod.h selects. A lookup gives the K ramp means R_k of the
// footprint; ramp_color (colormap/map_breakpoints.h) turns them into the
// colour of any map on the same breakpoints.
//
// Two ways to read it, the same lookups (float rounding apart; unit test):
//   TextureSystem  OpenImageIO's, tiles on demand through its cache;
//   Memory         each level read whole, as float, on its first lookup,
//                  and interpolated here (bilinear_texels.h's taps, the K
//                  channels in one loop): about 60 ns a channel less per
//                  lookup than TextureSystem's K-channel filter
//                  (docs/apply.md).
// PyramidReads::Auto takes Memory where every level as float fits in
// kMemoryReadsBytes and a quarter of the memory budget
// (util/memory_budget.h), else TextureSystem.
#pragma once

#include "cmfilter/texture/segment_pyramid_file.h"
#include "cmfilter/util/error.h"

#include <memory>
#include <string>

namespace OIIO_NAMESPACE {
class TextureSystem;
}

namespace cmfilter {

enum class PyramidReads { Auto, TextureSystem, Memory };

// The most bytes of float levels PyramidReads::Auto holds in memory.
constexpr double kMemoryReadsBytes = 1024.0 * 1024 * 1024;

class SegmentPyramidTexture {
public:
    // Io when unreadable, BadInput when not a segment pyramid (and, for
    // PyramidReads::Memory, when its levels do not fit the memory budget).
    static Expected<SegmentPyramidTexture> open(const std::string& path, PyramidReads reads = PyramidReads::Auto);

    const SegmentPyramidInfo& info() const { return info_; }
    const std::string& path() const { return path_; }
    int channels() const { return info_.channels(); }
    // As MomentTexture::reachable_levels.
    int reachable_levels() const;

    // Memory or TextureSystem (never Auto): how lookups read it.
    PyramidReads reads() const { return memory_ ? PyramidReads::Memory : PyramidReads::TextureSystem; }

    // The channels() ramp means at (s, t) and lod (MomentTexture::lookup's
    // conventions), each clamped to [0, 1]; false if the file could not be
    // read or a ramp mean is not finite (then 0). Thread-safe.
    bool lookup(float s, float t, float lod, float* ramps) const;

private:
    struct MemoryLevels;  // the levels read whole (PyramidReads::Memory)
    SegmentPyramidTexture() = default;
    bool lookup_memory(float s, float t, float lod, float* ramps) const;
    std::string path_;
    SegmentPyramidInfo info_;
    std::shared_ptr<OIIO::TextureSystem> ts_;
    std::shared_ptr<MemoryLevels> memory_;
};

}  // namespace cmfilter
