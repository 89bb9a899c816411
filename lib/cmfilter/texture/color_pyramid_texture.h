// SPDX-License-Identifier: Apache-2.0
// A baked colour pyramid (color_pyramid_file.h) opened for lookups the way a
// renderer reads it: OpenImageIO's TextureSystem with bilinear interpolation
// inside a level and trilinear blending across levels (as MomentTexture and
// HistogramTexture, so every method reads the same footprints). A lookup is
// the filtered colour itself, mean C0(f) over the footprint: one RGB texture
// read, no colour table.
#pragma once

#include "cmfilter/color/color.h"
#include "cmfilter/texture/color_pyramid_file.h"
#include "cmfilter/util/error.h"

#include <memory>
#include <string>

namespace OIIO_NAMESPACE {
class TextureSystem;
}

namespace cmfilter {

struct ColorPyramidSample {
    Rgb color;
    bool ok = true;  // false if TextureSystem failed or read a non-finite texel (then black)
};

class ColorPyramidTexture {
public:
    // Io when unreadable, BadInput when not a colour pyramid.
    static Expected<ColorPyramidTexture> open(const std::string& path);

    const ColorPyramidInfo& info() const { return info_; }
    const std::string& path() const { return path_; }
    // As MomentTexture::reachable_levels.
    int reachable_levels() const;

    // At (s, t) and lod with the conventions of MomentTexture::lookup (lod
    // clamped to the reachable levels). Thread-safe.
    ColorPyramidSample lookup(float s, float t, float lod) const;

private:
    ColorPyramidTexture() = default;
    std::string path_;
    ColorPyramidInfo info_;
    std::shared_ptr<OIIO::TextureSystem> ts_;
};

}  // namespace cmfilter
