// SPDX-License-Identifier: Apache-2.0
// Reading a moment pyramid back and looking it up the way a renderer does:
// through OpenImageIO's TextureSystem with bilinear interpolation inside a
// level and trilinear (or anisotropic) blending across levels, never bicubic
// (TextureSystem's default smart-bicubic has negative weights and can make
// m2 < m1^2). A lookup returns the footprint's mean f = c + m1 and variance
// sigma_f^2 = max(0, m2 - m1^2) (Heitz et al. 2013, sec. 4.2), ready for the
// colour table lookup T(mean, sigma) of eq. 10.
#pragma once

#include "cmfilter/util/error.h"
#include "cmfilter/texture/moment_pyramid_info.h"

#include <memory>
#include <string>

namespace OIIO_NAMESPACE {
class TextureSystem;
}

namespace cmfilter {

struct MomentSample {
    double mean = 0;      // c + m1
    double variance = 0;  // max(0, m2 - m1^2), never NaN
    double sigma = 0;     // sqrt(variance)
    // Third and fourth central moments of the footprint, from a pyramid of
    // order 4 (else 0): mu3 = E[(f - mean)^3], mu4 = E[(f - mean)^4].
    double mu3 = 0, mu4 = 0;
    bool ok = true;  // false if TextureSystem failed (then mean = c, variance = 0)
};

class MomentTexture {
public:
    // Io when the file cannot be read, BadInput when it is not a moment
    // pyramid (cmfilter:kind) or its metadata is inconsistent.
    static Expected<MomentTexture> open(const std::string& path);

    const MomentPyramidInfo& info() const { return info_; }
    const std::string& path() const { return path_; }
    double reference() const { return info_.reference; }

    // Isotropic trilinear lookup at texture coordinates (s, t) in [0, 1]
    // ((0, 0) is the top-left corner of the image, t grows downwards) at
    // level of detail lod: integer lod reads level lod alone (bilinear; the
    // centre of texel x of level k is at s = (x + 0.5) / w_k), fractional lod
    // blends levels floor(lod) and floor(lod) + 1 linearly in lod. For a
    // power-of-two driver, lod = log2 of the footprint width in level-0
    // texels. lod is clamped to [0, reachable_levels() - 1]. Thread-safe.
    MomentSample lookup(float s, float t, float lod) const;

    // Anisotropic lookup over the footprint spanned by the screen-space
    // derivatives of (s, t), as TextureSystem::texture takes them, with
    // bilinear probes. Thread-safe.
    MomentSample lookup(float s, float t, float dsdx, float dtdx, float dsdy, float dtdy) const;

    // Levels TextureSystem can select: it sizes filters by the smaller side of
    // each level, so levels past the first whose smaller side is 1 texel are
    // never read (all levels for a square driver).
    int reachable_levels() const;

private:
    MomentTexture() = default;
    MomentSample finish(bool ok, const float m[4]) const;
    std::string path_;
    MomentPyramidInfo info_;
    std::shared_ptr<OIIO::TextureSystem> ts_;
};

}  // namespace cmfilter
