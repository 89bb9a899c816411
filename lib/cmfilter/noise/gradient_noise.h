// SPDX-License-Identifier: Apache-2.0
// Gradient (Perlin) noise in 2-D and 3-D, after Perlin's improved noise
// (SIGGRAPH 2002): a pseudo-random gradient g_c at each integer lattice point c
// chosen by a seeded LatticeHash, and
//     n(p) = sum_c w_c(p) <g_c, p - c>,  w_c(p) = prod_k fade(1 - |p_k - c_k|),
// over the 2^D corners of p's cell, fade = quintic_fade. n = 0 at every
// lattice point; the base period (feature size) is one lattice unit, and the
// whole pattern repeats every 256 units.
//
// Gradient sets and ranges (docs/noise.md):
//   2-D: the 8 unit vectors at multiples of 45 degrees. |n| <= sum_c w_c |p - c|,
//        whose maximum over the cell is sqrt(2)/2, at the cell centre; it is
//        reached when all four gradients point at the centre. Bound: sqrt(2)/2.
//   3-D: Perlin's 12 cube-edge vectors (+-1, +-1, 0) etc. |n| <= sum_c w_c
//        max_g |<g, p - c>|, whose maximum over the cell, found by grid search
//        (test_gradient_noise.cpp), is about 1.035, off the centre (where it is
//        exactly 1). Bound: gradient_noise_3d_bound = 1.04.
#pragma once

#include "cmfilter/noise/noise_lattice.h"

#include <cstdint>

namespace cmfilter {

class GradientNoise {
public:
    static constexpr double bound_2d = 0.70710678118654752;  // sqrt(2)/2, attained
    static constexpr double bound_3d = 1.04;                 // measured envelope maximum, rounded up

    explicit GradientNoise(std::uint64_t seed) : hash_(seed) {}

    double operator()(double x, double y) const;
    double operator()(double x, double y, double z) const;

private:
    LatticeHash hash_;
};

}  // namespace cmfilter
