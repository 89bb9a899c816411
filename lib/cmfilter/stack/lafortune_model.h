// SPDX-License-Identifier: Apache-2.0
// Per-texel Lafortune lobes (Lafortune et al. 1997; per texel as McAllister
// et al. 2002; the second paper, sec. 3.2): the reflectance of a texel is
//   f(u, v) = rho_d + sum_i [Cx,i ux vx + Cy,i uy vy + Cz,i uz vz]^n_i,
// u the light and v the view direction, both unit, in the texel frame (the
// stack frame: x right, y up, z out of the surface), the bracket clamped at
// 0 (a lobe is 0 where the dot product is not positive). An image holds f
// times the light's cosine: value(u) = uz f(u, v).
//
// The images of one view v determine only the products
// a_i = (Cx,i vx, Cy,i vy, Cz,i vz), the lobe's axis at that view:
// f(u, v) = rho_d + sum_i max(0, a_i . u)^n_i. A fit stores a_i (and
// v); with the usual view (0, 0, 1) a_i is any vector and the C of the
// paper is (undetermined, undetermined, az). At another view w, Lafortune's
// form gives the axis a_i,k w_k / v_k for each component k whose v_k is not
// 0 (|v_k| >= kLafortuneViewEpsilon); a component the fitted view does not
// see (v_k = 0) is kept as fitted. Every evaluation is finite for any light
// and view: sums are done in double and clamped to the float range.
//
// Variants (the paper, sec. 3.2):
//   Rgb: per colour channel c its own rho_d,c and lobes (at most
//        kLafortuneMaxRgbLobes); value_c(u) = uz f_c(u, v).
//   Luminance: one scalar f fitted to the luminance Y of each light (Rec.
//        709 weights of R, G, B, or the one channel), up to
//        kLafortuneMaxLuminanceLobes lobes, times a per-texel base colour c:
//        value_c(u) = c_c uz f(u, v). The base colour is chosen as PTM-LRGB's
//        (linear_fit.h): the least-squares colour for the fitted luminance,
//        c = sum_k I_k Yf_k / sum_k Yf_k^2 (I_k the texel's colour under light
//        k, Yf_k = uz,k f(u_k, v)); where sum_k Yf_k^2 is below 1e-12 of
//        sum_k Y_k^2 (or 1e-30) it is the mean colour over the mean
//        luminance, or 0 when that is negligible too.
#pragma once

#include "cmfilter/math/vec3.h"
#include "cmfilter/stack/image_stack.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace cmfilter {

enum class LafortuneVariant { Rgb, Luminance };
const char* to_string(LafortuneVariant variant);  // "rgb", "luminance"
std::optional<LafortuneVariant> parse_lafortune_variant(const std::string& name);

constexpr int kLafortuneMaxRgbLobes = 2;
constexpr int kLafortuneMaxLuminanceLobes = 7;
int max_lafortune_lobes(LafortuneVariant variant);

// The exponents a fit may choose (n = 1: a cosine; 500: a sharp highlight).
constexpr double kLafortuneMinExponent = 1.0;
constexpr double kLafortuneMaxExponent = 500.0;
// A fitted view component smaller than this is one the images do not see.
constexpr double kLafortuneViewEpsilon = 1e-6;

// Floats per lobe: ax, ay, az, n.
constexpr int kLafortuneLobeFloats = 4;

struct LafortuneFit {
    LafortuneVariant variant = LafortuneVariant::Luminance;
    int width = 0, height = 0, channels = 0;
    int lobes = 0;                                        // lobe slots per texel (Rgb: per channel)
    bool auto_lobes = false;                              // lobes chosen per texel (then `lobes` is the most)
    Vec3 view{0, 0, 1};                                   // the view the images were taken from (unit, z > 0)
    StackEncoding encoding = StackEncoding::SceneLinear;  // the values it reproduces
    std::string colorspace;                               // as the stack's
    // Per texel (row-major, top row first) `stride()` floats:
    //   Luminance: rho_d, then per lobe slot ax, ay, az, n, then the base
    //              colour's `channels` values;
    //   Rgb: per channel c, rho_d,c then per lobe slot ax, ay, az, n.
    // An unused slot is (0, 0, 0, 1): it adds 0.
    std::vector<float> parameters;
    // Lobes used per texel (Luminance) or per texel and channel (Rgb, at
    // [t * channels + c]).
    std::vector<unsigned char> lobe_counts;
    // Refinements discarded for their start (lafortune_scalar_fit.h).
    long long fallbacks = 0;

    int scalar_stride() const { return 1 + kLafortuneLobeFloats * lobes; }
    int stride() const
    {
        return variant == LafortuneVariant::Luminance ? scalar_stride() + channels : channels * scalar_stride();
    }
    std::size_t texels() const { return static_cast<std::size_t>(width) * height; }
    const float* texel(std::size_t t) const { return parameters.data() + t * stride(); }
    // Texels (Rgb: texel channels) by lobe count: [0 .. lobes].
    std::vector<long long> lobe_histogram() const;
};

// The axis of a lobe fitted with axis `a` at view `fitted_view`, at `view`.
Vec3 lafortune_axis_at_view(const Vec3& a, const Vec3& fitted_view, const Vec3& view);

// max(0, a . u)^n: 0 where a . u <= 0, finite for any n >= 1.
double lafortune_lobe(const Vec3& a, double n, const Vec3& u);

// f(u) for one scalar's parameters (rho_d then `lobes` slots of ax, ay, az,
// n), with each axis taken at `view`; not times uz; clamped to [0, FLT_MAX].
double lafortune_reflectance(const float* scalar, int lobes, const Vec3& u, const Vec3& fitted_view, const Vec3& view);

// The value an image holds at texel `t` for light u and view v:
// `fit.channels` floats written to out (uz f, times the base colour for
// Luminance). uz < 0 is taken as 0.
void lafortune_texel_value(const LafortuneFit& fit, std::size_t t, const Vec3& light, const Vec3& view, float* out);

}  // namespace cmfilter
