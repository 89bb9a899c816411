// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/noise/value_noise.h"

#include <cmath>

namespace cmfilter {

double ValueNoise::operator()(double x, double y) const
{
    const double fx = std::floor(x), fy = std::floor(y);
    const int i = lattice_index(fx), j = lattice_index(fy);
    const double u = quintic_fade(x - fx), v = quintic_fade(y - fy);
    auto value = [&](int a, int b) { return lattice_value(hash_(i + a, j + b)); };
    return lerp(v, lerp(u, value(0, 0), value(1, 0)), lerp(u, value(0, 1), value(1, 1)));
}

double ValueNoise::operator()(double x, double y, double z) const
{
    const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    const int i = lattice_index(fx), j = lattice_index(fy), k = lattice_index(fz);
    const double u = quintic_fade(x - fx), v = quintic_fade(y - fy), w = quintic_fade(z - fz);
    auto value = [&](int a, int b, int c) { return lattice_value(hash_(i + a, j + b, k + c)); };
    return blend_cell_corners(u, v, w, value);
}

}  // namespace cmfilter
