// SPDX-License-Identifier: Apache-2.0
// Closed-form box correlations (box_correlation.h) of the 2-D lattice noises,
// from the kernel s(t) = fade(1 - |t|) on [-1, 1] that both share
// (noise_lattice.h), with independent zero-mean lattice draws:
//   gradient: n(p) = sum_c <g_c, p - c> S(p - c), S(q) = s(q_x) s(q_y),
//             E[g g^T] = I / 2 (8 unit gradients), so averaged over p
//             R(d) = 1/2 integral <q, q + d> S(q) S(q + d) dq
//                  = 1/2 (A(d_x) B(d_y) + B(d_x) A(d_y)),
//             A(d) = integral t (t + d) s(t) s(t + d) dt, B(d) = integral s(t) s(t + d) dt;
//             the box mean of R over [-k/2, k/2]^2 is Abar(k) Bbar(k), so
//             beta(k) = Abar(k) Bbar(k) / (A(0) B(0)), and beta = 0 exactly for
//             k >= 4 (the box holds R's whole support, and the integral of R is 0).
//   value:    n(p) = sum_c v_c S(p - c): R(d) = Var v B(d_x) B(d_y),
//             beta(k) = (Bbar(k) / B(0))^2 (falls as 1 / k^2: value noise
//             keeps power at frequency 0).
// Abar(k) = (1/k) integral over [-k/2, k/2] of A. The integrands are piecewise
// polynomials (degree <= 12) with kinks at t = 0, -d and at d = 1: 8-point
// Gauss-Legendre on each piece integrates them exactly. Both are tested
// against brute-force box means of the noises (test_box_correlation.cpp).
#pragma once

#include "cmfilter/noise/box_correlation.h"

namespace cmfilter {

BoxCorrelation gradient_noise_box_correlation();
BoxCorrelation value_noise_box_correlation();

}  // namespace cmfilter
