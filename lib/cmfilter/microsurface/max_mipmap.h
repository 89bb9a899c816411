// SPDX-License-Identifier: Apache-2.0
// A maximum mipmap over a periodic grid of n x n height nodes (n a power of
// two): level k >= 1 holds, for each block of 2^k x 2^k texels, the largest
// height of the (2^k + 1)^2 nodes at its corners and inside, so it bounds
// from above any surface that interpolates the nodes without overshoot (the
// bilinear patches of heightfield_tracer.h). Level 1 is built from the nodes,
// each higher level from the four blocks below it; level log2(n) is the whole
// grid. The maxima are stored as floats rounded up, never below the double
// they bound. Block indices wrap periodically. Immutable; thread-safe.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace cmfilter {

class MaxMipmap {
public:
    MaxMipmap() = default;
    // nodes: (n + 1) x (n + 1) heights, node (i, j) at nodes[j * (n + 1) + i],
    // the last row and column repeating the first (the periodic grid closed).
    // n: a power of two, >= 1.
    MaxMipmap(const double* nodes, int n);

    // The highest level, log2(n) (0: n = 1, no levels).
    int top_level() const { return static_cast<int>(levels_.size()); }
    // The bound over block (bx, by) of level k, 1 <= k <= top_level(); bx and
    // by wrap modulo n >> k.
    double block_max(int k, std::int64_t bx, std::int64_t by) const
    {
        const std::int64_t mask = (n_ >> k) - 1;
        return levels_[k - 1][static_cast<std::size_t>((by & mask) * (n_ >> k) + (bx & mask))];
    }

private:
    std::int64_t n_ = 1;
    std::vector<std::vector<float>> levels_;  // levels_[k - 1]: level k, row-major
};

}  // namespace cmfilter
