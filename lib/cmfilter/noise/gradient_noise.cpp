// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/noise/gradient_noise.h"

#include <cmath>

namespace cmfilter {

namespace {

// <g_h, (dx, dy)> for the 8 unit gradients at multiples of 45 degrees.
double dot_gradient_2d(int h, double dx, double dy)
{
    constexpr double d = 0.70710678118654752;  // cos 45 degrees
    switch (h & 7) {
    case 0: return dx;
    case 1: return d * (dx + dy);
    case 2: return dy;
    case 3: return d * (dy - dx);
    case 4: return -dx;
    case 5: return -d * (dx + dy);
    case 6: return -dy;
    default: return d * (dx - dy);
    }
}

// <g_h, (dx, dy, dz)> for Perlin's 12 cube-edge gradients (2002), indexed
// h mod 12 so every edge is equally likely over a period (256 = 12 * 21 + 4:
// edges 0-3 occur 22 times in 256, the others 21; the test accounts for it).
double dot_gradient_3d(int h, double dx, double dy, double dz)
{
    switch (h % 12) {
    case 0: return dx + dy;
    case 1: return -dx + dy;
    case 2: return dx - dy;
    case 3: return -dx - dy;
    case 4: return dx + dz;
    case 5: return -dx + dz;
    case 6: return dx - dz;
    case 7: return -dx - dz;
    case 8: return dy + dz;
    case 9: return -dy + dz;
    case 10: return dy - dz;
    default: return -dy - dz;
    }
}

}  // namespace

double GradientNoise::operator()(double x, double y) const
{
    const double fx = std::floor(x), fy = std::floor(y);
    const int i = lattice_index(fx);
    const int j = lattice_index(fy);
    const double dx = x - fx, dy = y - fy;
    const double u = quintic_fade(dx), v = quintic_fade(dy);
    const double n00 = dot_gradient_2d(hash_(i, j), dx, dy);
    const double n10 = dot_gradient_2d(hash_(i + 1, j), dx - 1, dy);
    const double n01 = dot_gradient_2d(hash_(i, j + 1), dx, dy - 1);
    const double n11 = dot_gradient_2d(hash_(i + 1, j + 1), dx - 1, dy - 1);
    return lerp(v, lerp(u, n00, n10), lerp(u, n01, n11));
}

double GradientNoise::operator()(double x, double y, double z) const
{
    const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    const int i = lattice_index(fx);
    const int j = lattice_index(fy);
    const int k = lattice_index(fz);
    const double dx = x - fx, dy = y - fy, dz = z - fz;
    const double u = quintic_fade(dx), v = quintic_fade(dy), w = quintic_fade(dz);
    auto corner = [&](int a, int b, int c) {
        return dot_gradient_3d(hash_(i + a, j + b, k + c), dx - a, dy - b, dz - c);
    };
    return blend_cell_corners(u, v, w, corner);
}

}  // namespace cmfilter
