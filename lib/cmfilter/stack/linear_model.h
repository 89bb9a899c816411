// SPDX-License-Identifier: Apache-2.0
// The linear reflectance models of an image stack, each a set of basis
// functions of the light direction l = (lu, lv, lw) (unit, in the stack's
// frame, light_file.h) whose weighted sum approximates a texel's value:
//   PtmRgb   Polynomial Texture Map (Malzbender et al. 2001, eq. 2; the
//            second paper's sec. 3.1), per channel
//            a0 lu^2 + a1 lv^2 + a2 lu lv + a3 lu + a4 lv + a5;
//   PtmLrgb  the same polynomial for the luminance, times a per-texel base
//            colour (linear_fit.h says how it is chosen);
//   Hsh2     hemispherical harmonics (Gautron et al. 2004) of order 2, 4
//            terms per channel, as RTIViewer and relight define them;
//   Hsh3     order 3, 9 terms per channel.
#pragma once

#include "cmfilter/math/vec3.h"

#include <array>
#include <optional>
#include <string>

namespace cmfilter {

enum class LinearModel { PtmRgb, PtmLrgb, Hsh2, Hsh3 };

constexpr int kMaxLinearTerms = 9;

// The luminance a PTM-LRGB fits and a normal maximises (linear_fit.h,
// fit_normals.h): Rec. 709 weights of R, G, B (of linear or encoded values
// alike, as RTI tools take them).
constexpr double kRec709Luminance[3] = {0.2126, 0.7152, 0.0722};

const char* to_string(LinearModel model);                                // "ptm-rgb", "ptm-lrgb", "hsh2", "hsh3"
std::optional<LinearModel> parse_linear_model(const std::string& name);  // the same names

// Basis functions per channel (6, 6, 4, 9).
int basis_terms(LinearModel model);

// The basis functions at light direction l (unit, z >= 0), terms 0 ..
// basis_terms - 1 in the order the files store them: PTM a0..a5 as above;
// HSH in RTIViewer's order.
std::array<double, kMaxLinearTerms> evaluate_basis(LinearModel model, const Vec3& light);

}  // namespace cmfilter
