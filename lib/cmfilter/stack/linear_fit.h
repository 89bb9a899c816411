// SPDX-License-Identifier: Apache-2.0
// A linear model (linear_model.h) fitted to every texel of an image stack
// in one solve: the light matrix A (one row per light, one column per basis
// function) is inverted once by SVD (Eigen's JacobiSVD), singular values
// below LinearFitOptions::singular_threshold times the largest taken as zero
// (pseudo-inverse), and every texel's coefficients are A^+ times its values
// under the lights: one matrix product over all texels and channels,
// threaded over blocks of texels.
//
// PtmLrgb: each light's luminance Y (Rec. 709 weights of the stack's RGB, or
// the one channel) is fitted by the polynomial P; the base colour c of a
// texel is then the least-squares colour for the fitted luminance,
// c = sum_k I_k P(l_k) / sum_k P(l_k)^2 (I_k the texel's value under light
// k), so that c P(l) is the best colour for the fitted shape (its Rec. 709
// luminance is then 1, or the one channel 1). Where sum_k P(l_k)^2 is
// negligible (below 1e-12 of sum_k Y_k^2, or 1e-30: a black or flat texel)
// c is the texel's mean colour over its mean luminance, or 0 when that is
// negligible too.
#pragma once

#include "cmfilter/stack/image_stack.h"
#include "cmfilter/stack/linear_model.h"
#include "cmfilter/util/error.h"

#include <cstddef>
#include <string>
#include <vector>

namespace cmfilter {

// How well the lights determine a model's coefficients.
struct LightSetConditioning {
    int lights = 0;
    int terms = 0;
    double largest_singular = 0, smallest_singular = 0;
    double condition_number = 0;  // largest / smallest kept
    int clamped = 0;              // singular values taken as zero
};

struct LinearFitOptions {
    LinearModel model = LinearModel::PtmRgb;
    // Singular values below this fraction of the largest are taken as zero.
    double singular_threshold = 1e-6;
    int threads = 0;  // 0: all cores
};

// The floats a texel of a `model` fit of `channels` channels holds (see
// LinearFit::coefficients), in 64 bits: a file may declare any count.
inline long long linear_fit_stride(LinearModel model, long long channels)
{
    return model == LinearModel::PtmLrgb ? basis_terms(model) + channels : channels * basis_terms(model);
}

struct LinearFit {
    LinearModel model = LinearModel::PtmRgb;
    int width = 0, height = 0, channels = 0;
    StackEncoding encoding = StackEncoding::SceneLinear;  // the values it reproduces
    std::string colorspace;                               // as the stack's
    LightSetConditioning conditioning;
    // Per texel (row-major, top row first) `stride()` floats:
    //   PtmRgb, Hsh2, Hsh3: channel c's term k at [c * terms + k];
    //   PtmLrgb: the luminance polynomial's 6 terms, then the base colour's
    //            `channels` values.
    std::vector<float> coefficients;

    int terms() const { return basis_terms(model); }
    int stride() const { return static_cast<int>(linear_fit_stride(model, channels)); }
    std::size_t texels() const { return static_cast<std::size_t>(width) * height; }
    const float* texel(std::size_t t) const { return coefficients.data() + t * stride(); }
};

// The conditioning of `lights` for `model` (the singular values of the
// light matrix), and BadInput when they cannot determine it, checked in this
// order: fewer lights than terms (field LinearFitOptions::model: another
// model may fit); all lights' projections (lu, lv) on one line, through the
// pole or not ("collinear": the smaller singular value of the centred 2 x N
// matrix of projections below 1e-4 of the larger; the message gives the
// line's azimuth and distance from the pole); all at one elevation (lz
// spread below 1e-4: "all at one elevation, 45.0 degrees"; a PTM's lu^2 +
// lv^2, an HSH's cos(theta) is then constant). A rank below the terms for
// another reason is not refused: the singular values below the threshold
// are counted in `clamped` and the fit is the minimum-norm least-squares
// one (a light matrix whose singular values are all zero is refused). BadInput naming
// LinearFitOptions::singular_threshold unless it is finite and in [0, 1).
Expected<LightSetConditioning> check_light_set(const std::vector<Vec3>& lights, LinearModel model,
                                               double singular_threshold = 1e-6);

// BadInput as check_light_set (naming the stack's light file); a PtmLrgb
// fit of a stack with other than 1 or 3 channels (field
// LinearFitOptions::model); a stack whose sizes and pixel count disagree.
// Deterministic for any thread count.
Expected<LinearFit> fit_linear(const ImageStack& stack, const LinearFitOptions& options);

// The model at light `light` (unit, z >= 0) for every texel:
// width * height * channels floats, row-major, top row first.
std::vector<float> relight(const LinearFit& fit, const Vec3& light, int threads = 0);

}  // namespace cmfilter
