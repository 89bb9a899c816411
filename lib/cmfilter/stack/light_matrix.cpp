// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/light_matrix.h"

namespace cmfilter {

Eigen::MatrixXd light_matrix(const std::vector<Vec3>& lights, LinearModel model)
{
    const int terms = basis_terms(model);
    Eigen::MatrixXd a(static_cast<Eigen::Index>(lights.size()), terms);
    for (std::size_t k = 0; k < lights.size(); ++k) {
        const auto b = evaluate_basis(model, lights[k]);
        for (int j = 0; j < terms; ++j) a(static_cast<Eigen::Index>(k), j) = b[static_cast<std::size_t>(j)];
    }
    return a;
}

LightPseudoInverse light_pseudo_inverse(const std::vector<Vec3>& lights, LinearModel model, double singular_threshold)
{
    LightPseudoInverse out;
    out.a = light_matrix(lights, model);
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(out.a, Eigen::ComputeThinU | Eigen::ComputeThinV);
    const Eigen::VectorXd& s = svd.singularValues();
    Eigen::VectorXd s_inverse(s.size());
    for (Eigen::Index j = 0; j < s.size(); ++j)
        s_inverse(j) = s(j) > singular_threshold * s(0) && s(j) > 0 ? 1 / s(j) : 0.0;
    out.p = svd.matrixV() * s_inverse.asDiagonal() * svd.matrixU().transpose();
    out.w = s.asDiagonal() * svd.matrixV().transpose();
    return out;
}

}  // namespace cmfilter
