// SPDX-License-Identifier: Apache-2.0
// Gauss-Hermite quadrature for the standard normal: n nodes z_i and weights
// w_i (summing to 1) with E[f(Z)] ~ sum_i w_i f(z_i) for Z ~ N(0, 1), exact
// for polynomials of degree <= 2n - 1. The nodes are the roots of the
// Hermite polynomial H_n, found by Newton's method on the orthonormal
// recurrence (initial guesses after Numerical Recipes' gauher), scaled from
// the weight e^{-x^2} to the normal's: z = sqrt(2) x, w = w_x / sqrt(pi).
#pragma once

#include <vector>

namespace cmfilter {

struct GaussHermiteRule {
    std::vector<double> nodes;    // ascending
    std::vector<double> weights;  // > 0, sum 1
};

// n in [1, 100]; clamped into it.
GaussHermiteRule gauss_hermite_rule(int n);

}  // namespace cmfilter
