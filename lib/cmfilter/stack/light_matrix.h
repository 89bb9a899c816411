// SPDX-License-Identifier: Apache-2.0
// The light matrix of a linear model (linear_model.h) and its
// pseudo-inverse, shared by the fit that holds a stack (linear_fit.h) and
// the one that streams it (streamed_fit.h). A has one row per light, one
// column per basis function (A[k][j] = basis j at light k); its thin SVD
// A = U S V^T (Eigen's JacobiSVD) gives P = V S^+ U^T, singular values at or
// below singular_threshold times the largest (or zero) taken as zero.
#pragma once

#include "cmfilter/math/vec3.h"
#include "cmfilter/stack/linear_model.h"

#include <Eigen/Dense>

#include <vector>

namespace cmfilter {

Eigen::MatrixXd light_matrix(const std::vector<Vec3>& lights, LinearModel model);

struct LightPseudoInverse {
    Eigen::MatrixXd a;  // lights x terms: the light matrix
    Eigen::MatrixXd p;  // terms x lights: its pseudo-inverse
    // terms x terms: S V^T, so that |A x| = |W x| for any x (U has
    // orthonormal columns): a texel's fitted values' energy and their dot
    // products without the lights.
    Eigen::MatrixXd w;
};

LightPseudoInverse light_pseudo_inverse(const std::vector<Vec3>& lights, LinearModel model, double singular_threshold);

}  // namespace cmfilter
