// SPDX-License-Identifier: Apache-2.0
// A driver texture f for the renderer, in texture coordinates (s, t) = (u, v)
// of the surface (scene.h): one repeat, [0, 1]^2, is the whole image, (0, 0)
// its top-left corner and t growing downwards (as in moment_texture.h), and
// beyond the repeat the texture continues as its moment pyramid's wrap says
// (texture_wrap.h: periodic tiles the plane). Two views of the same f:
//   filter  the mean and sigma of f over a square footprint of width w,
//           from the moment pyramid through TextureSystem: mean f and mean
//           f^2 at each level give sigma_f^2 = mean f^2 - (mean f)^2 (Heitz
//           et al. 2013, sec. 4.2), for C0(mean) and T(mean, sigma) (eq. 10);
//           a trilinear lookup at the LOD whose kernel has the box's
//           variance (trilinear_lod_for_box, texture_lod.h). Anisotropic
//           footprints are cut into such squares (texture_footprint.h);
//   value   f itself at a point: the level-0 texels (data, as read: never
//           colour-converted) interpolated bilinearly with the same texel
//           centres and wrap (bilinear_texels.h; black reads the reference
//           value c, the point mass that black moments stand for), for the
//           supersampled methods' C0(f). Level 0 is optional: a moment
//           pyramid whose driver is gone still filters (naive, gaussian).
// Immutable once made; both lookups are thread-safe.
#pragma once

#include "cmfilter/util/error.h"
#include "cmfilter/texture/moment_texture.h"
#include "cmfilter/util/temporary_file.h"

#include <memory>
#include <optional>
#include <vector>

namespace cmfilter {

class FilteredTexture {
public:
    // level0: the pyramid's driver, info().width x info().height texels,
    // row-major, top row first (BadInput if the count differs), or none.
    // `owned`: a file to keep until the last copy is gone (a pyramid baked in
    // process).
    static Expected<FilteredTexture> create(MomentTexture moments, std::optional<std::vector<float>> level0,
                                            std::shared_ptr<const TemporaryFile> owned = {});

    // Mean and sigma of f over a square of width w (texture repeats) at (u, v).
    MomentSample filter(double u, double v, double w) const;
    // Whether the level-0 texels are here (value() needs them).
    bool has_level0() const { return level0_ != nullptr; }
    // The level-0 texels (width() x height(), row-major, top row first), or
    // null without them.
    const std::vector<float>* level0() const { return level0_.get(); }
    // How many distinct values level 0 holds (0 without level 0).
    std::size_t distinct_values() const;
    // f at (u, v), bilinear in level 0; the reference value c without level 0.
    double value(double u, double v) const;
    // log2 of a footprint width w (texture repeats) in level-0 texels,
    // log2(w * width); -inf for w = 0.
    double lod(double w) const;

    const MomentTexture& moments() const { return moments_; }
    int width() const { return moments_.info().width; }
    int height() const { return moments_.info().height; }

private:
    explicit FilteredTexture(MomentTexture moments) : moments_(std::move(moments)) {}
    std::shared_ptr<const TemporaryFile> owned_;  // first: removed after the TextureSystem closes it
    MomentTexture moments_;
    std::shared_ptr<const std::vector<float>> level0_;  // shared: copies stay cheap; null: none
};

}  // namespace cmfilter
