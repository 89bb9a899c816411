// SPDX-License-Identifier: Apache-2.0
// Value noise (Lagae et al. 2010, sec. 3.1): a pseudo-random value v_c in
// [-1, 1] at each integer lattice point c, chosen by a seeded LatticeHash as
// v = 2 h / 255 - 1 (h in 0..255, so the 256 values are equally likely), and
// interpolated with the quintic fade:
//     n(p) = sum_c w_c(p) v_c,  w_c(p) = prod_k fade(1 - |p_k - c_k|).
// The weights are non-negative and sum to 1, so |n| <= 1 (attained at lattice
// points holding +-1). The base period is one lattice unit; the pattern
// repeats every 256 units. Mean 0 over a period (the values are symmetric).
#pragma once

#include "cmfilter/noise/noise_lattice.h"

#include <cstdint>

namespace cmfilter {

class ValueNoise {
public:
    static constexpr double bound = 1.0;

    explicit ValueNoise(std::uint64_t seed) : hash_(seed) {}

    double operator()(double x, double y) const;
    double operator()(double x, double y, double z) const;

    // The lattice value for hash h: 2 h / 255 - 1.
    static double lattice_value(int h) { return 2.0 * h / 255.0 - 1.0; }

private:
    LatticeHash hash_;
};

}  // namespace cmfilter
