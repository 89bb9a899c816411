// SPDX-License-Identifier: Apache-2.0
// The random choices of synthesis as a hash of what they are for (seed,
// pass, texel), not a stream: the same output for any order of evaluation
// or thread count. SplitMix64's finaliser (Steele, Lea & Flood 2014).
#pragma once

#include <cstdint>

namespace cmfilter {

inline std::uint64_t splitmix64_finalise(std::uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

inline std::uint64_t synthesis_hash(std::uint64_t seed, std::uint64_t pass, std::uint64_t texel)
{
    std::uint64_t h = splitmix64_finalise(seed + 0x9E3779B97F4A7C15ull);
    h = splitmix64_finalise(h ^ (pass + 0x9E3779B97F4A7C15ull * 2));
    return splitmix64_finalise(h ^ (texel + 0x9E3779B97F4A7C15ull * 3));
}

}  // namespace cmfilter
