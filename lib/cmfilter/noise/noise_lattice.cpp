// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/noise/noise_lattice.h"

namespace cmfilter {

LatticeHash::LatticeHash(std::uint64_t seed)
{
    for (int i = 0; i < period; ++i) perm_[i] = i;
    // Fisher-Yates with SplitMix64 draws; the modulo bias (< 256 / 2^64) is negligible.
    std::uint64_t state = seed;
    for (int i = period - 1; i > 0; --i) {
        const int j = static_cast<int>(splitmix64(state) % static_cast<std::uint64_t>(i + 1));
        std::swap(perm_[i], perm_[j]);
    }
    for (int i = 0; i < period; ++i) perm_[period + i] = perm_[i];
}

}  // namespace cmfilter
