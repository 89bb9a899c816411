// SPDX-License-Identifier: Apache-2.0
// A segment pyramid (segment_pyramid_file.h) opened for lookups as a renderer
// reads it: OpenImageIO's TextureSystem, bilinear inside a level and
// trilinear across levels (the footprints of MomentTexture and
// ColorPyramidTexture). A lookup gives the K ramp means R_k of the footprint;
// ramp_color (colormap/map_breakpoints.h) turns them into the colour of any
// map on the same breakpoints.
#pragma once

#include "cmfilter/texture/segment_pyramid_file.h"
#include "cmfilter/util/error.h"

#include <memory>
#include <string>

namespace OIIO_NAMESPACE {
class TextureSystem;
}

namespace cmfilter {

class SegmentPyramidTexture {
public:
    // Io when unreadable, BadInput when not a segment pyramid.
    static Expected<SegmentPyramidTexture> open(const std::string& path);

    const SegmentPyramidInfo& info() const { return info_; }
    const std::string& path() const { return path_; }
    int channels() const { return info_.channels(); }
    // As MomentTexture::reachable_levels.
    int reachable_levels() const;

    // The channels() ramp means at (s, t) and lod (MomentTexture::lookup's
    // conventions), each clamped to [0, 1]; false if TextureSystem failed or
    // read a non-finite texel (then 0). Thread-safe.
    bool lookup(float s, float t, float lod, float* ramps) const;

private:
    SegmentPyramidTexture() = default;
    std::string path_;
    SegmentPyramidInfo info_;
    std::shared_ptr<OIIO::TextureSystem> ts_;
};

}  // namespace cmfilter
