// SPDX-License-Identifier: Apache-2.0
// The synthesis module's random numbers, all SplitMix64 (Steele, Lea & Flood
// 2014): a small deterministic generator for the k-means start and the
// quality measures' fixed samples, and, for synthesis, random choices as a
// hash of what they are for (seed, pass, texel), not a stream, so the same
// output comes for any order of evaluation or thread count.
#pragma once

#include <cstdint>

namespace cmfilter {

inline std::uint64_t splitmix64_finalise(std::uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

class SplitMix64 {
public:
    explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next() { return splitmix64_finalise(state_ += 0x9E3779B97F4A7C15ull); }
    // A double in [0, 1) from the top 53 bits.
    double uniform() { return static_cast<double>(next() >> 11) * (1.0 / 9007199254740992.0); }

private:
    std::uint64_t state_;
};

inline std::uint64_t synthesis_hash(std::uint64_t seed, std::uint64_t pass, std::uint64_t texel)
{
    std::uint64_t h = splitmix64_finalise(seed + 0x9E3779B97F4A7C15ull);
    h = splitmix64_finalise(h ^ (pass + 0x9E3779B97F4A7C15ull * 2));
    return splitmix64_finalise(h ^ (texel + 0x9E3779B97F4A7C15ull * 3));
}

}  // namespace cmfilter
