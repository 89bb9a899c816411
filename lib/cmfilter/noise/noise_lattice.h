// SPDX-License-Identifier: Apache-2.0
// The seeded integer lattice shared by gradient and value noise (Perlin 1985,
// 2002): a permutation of 0..255 drawn from an explicit seed, so each noise
// object owns its table and two objects with the same seed agree bit for bit
// on every platform (the shuffle uses its own generator, never std::shuffle,
// whose draws are implementation-defined). Lattice coordinates wrap modulo 256:
// every lattice noise built on it has period 256 along each axis.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

namespace cmfilter {

// SplitMix64 (Steele, Lea, Flood 2014): one step of a well-mixed 64-bit
// sequence; also a good hash of a 64-bit key.
inline std::uint64_t splitmix64(std::uint64_t& state)
{
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

// A uniform double in [0, 1) from the top 53 bits of a 64-bit draw.
inline double unit_interval(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }

class LatticeHash {
public:
    static constexpr int period = 256;

    explicit LatticeHash(std::uint64_t seed);

    // A value in 0..255 per lattice point, uniformly distributed over the
    // points of one period (each value occurs equally often along any axis).
    int operator()(int i, int j) const { return perm_[perm_[wrap(i)] + wrap(j)]; }
    int operator()(int i, int j, int k) const { return perm_[perm_[perm_[wrap(i)] + wrap(j)] + wrap(k)]; }

private:
    static int wrap(int i) { return i & (period - 1); }
    std::array<int, 2 * period> perm_{};  // the permutation, repeated once to skip a wrap
};

// The lattice cell of coordinate x: its index modulo the period, for LatticeHash.
// Reduced in double (exact for an integral value) so that a coordinate past
// long long's range, as many octaves reach, is not cast out of range.
inline int lattice_index(double floored_x)
{
    if (!std::isfinite(floored_x)) return 0;
    double i = std::fmod(floored_x, static_cast<double>(LatticeHash::period));
    if (i < 0) i += LatticeHash::period;
    return static_cast<int>(i) & (LatticeHash::period - 1);
}

inline double lerp(double t, double a, double b) { return a + t * (b - a); }

// Blends corner(a, b, c), a, b, c in {0, 1}, of a lattice cell with the faded
// fractions (u, v, w): the trilinear step both 3-D lattice noises share.
template <typename Corner>
double blend_cell_corners(double u, double v, double w, Corner&& corner)
{
    const double x00 = lerp(u, corner(0, 0, 0), corner(1, 0, 0));
    const double x10 = lerp(u, corner(0, 1, 0), corner(1, 1, 0));
    const double x01 = lerp(u, corner(0, 0, 1), corner(1, 0, 1));
    const double x11 = lerp(u, corner(0, 1, 1), corner(1, 1, 1));
    return lerp(w, lerp(v, x00, x10), lerp(v, x01, x11));
}

// Perlin's improved fade (2002): 6t^5 - 15t^4 + 10t^3, C2 across lattice cells.
inline double quintic_fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

}  // namespace cmfilter
