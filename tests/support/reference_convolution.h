// SPDX-License-Identifier: Apache-2.0
// Test-only reference for eq. 10, written independently of libcmfilter: the
// piecewise-linear colour map evaluated straight from its definition, and
// (C0 * N(0, sigma^2))(v) by brute-force Gauss-Legendre quadrature over
// z in [-12, 12] (neglected mass 2 Phi(-12) < 4e-33), split at every kink of
// C0(v + sigma z) and into pieces no longer than 0.25 in z. On each piece the
// integrand is a linear function times a Gaussian, which 10-point
// Gauss-Legendre integrates to far below 1e-12.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace cmfilter_test {

using Rgb3 = std::array<double, 3>;

struct ReferenceMap {
    std::vector<Rgb3> texels;
    double vmin = 0, vmax = 1;
    std::string wrap = "clamp";  // clamp | repeat | mirror
};

// Linear interpolation through texel centres vmin + (i + 0.5) h.
inline Rgb3 reference_map_value(const ReferenceMap& m, double v)
{
    const int n = static_cast<int>(m.texels.size());
    const double period = m.vmax - m.vmin;
    double u = v - m.vmin;
    if (m.wrap == "repeat") {
        u = std::fmod(u, period);
        if (u < 0) u += period;
        double p = u / period * n - 0.5;  // in [-0.5, n - 0.5)
        int i0 = static_cast<int>(std::floor(p));
        const double t = p - i0;
        const Rgb3& a = m.texels[(i0 + n) % n];
        const Rgb3& b = m.texels[(i0 + 1) % n];
        return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
    }
    if (m.wrap == "mirror") {
        u = std::fmod(u, 2 * period);
        if (u < 0) u += 2 * period;
        if (u > period) u = 2 * period - u;
    }
    const double p = u / period * n - 0.5;
    if (p <= 0) return m.texels.front();
    if (p >= n - 1) return m.texels.back();
    const int i0 = static_cast<int>(std::floor(p));
    const double t = p - i0;
    const Rgb3& a = m.texels[i0];
    const Rgb3& b = m.texels[i0 + 1];
    return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}

inline Rgb3 reference_convolution(const ReferenceMap& m, double v, double sigma)
{
    if (sigma <= 0) return reference_map_value(m, v);
    static const double gx[5] = {0.1488743389816312, 0.4333953941292472, 0.6794095682990244, 0.8650633666889845,
                                 0.9739065285171717};
    static const double gw[5] = {0.2955242247147529, 0.2692667193099963, 0.2190863625159820, 0.1494513491505806,
                                 0.0666713443086881};
    const double z_lo = -12, z_hi = 12;
    // Breakpoints: kinks of C0(v + sigma z) inside [z_lo, z_hi].
    const int n = static_cast<int>(m.texels.size());
    const double h = (m.vmax - m.vmin) / n;
    std::vector<double> cuts = {z_lo, z_hi};
    const double k_first = std::ceil((v + sigma * z_lo - m.vmin) / h - 0.5);
    const double k_last = std::floor((v + sigma * z_hi - m.vmin) / h - 0.5);
    for (double k = k_first; k <= k_last; k += 1) cuts.push_back((m.vmin + (k + 0.5) * h - v) / sigma);
    std::sort(cuts.begin(), cuts.end());
    Rgb3 acc = {0, 0, 0};
    const double inv_sqrt_2pi = 0.39894228040143267794;
    for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
        const double a = cuts[c], b = cuts[c + 1];
        if (b <= a) continue;
        const int pieces = std::max(1, static_cast<int>(std::ceil((b - a) / 0.25)));
        for (int p = 0; p < pieces; ++p) {
            const double pa = a + (b - a) * p / pieces, pb = a + (b - a) * (p + 1) / pieces;
            const double mid = 0.5 * (pa + pb), half = 0.5 * (pb - pa);
            for (int g = 0; g < 10; ++g) {
                const double z = mid + (g < 5 ? -gx[g] : gx[g - 5]) * half;
                const double w = gw[g < 5 ? g : g - 5] * half * inv_sqrt_2pi * std::exp(-0.5 * z * z);
                const Rgb3 c3 = reference_map_value(m, v + sigma * z);
                for (int ch = 0; ch < 3; ++ch) acc[ch] += w * c3[ch];
            }
        }
    }
    return acc;
}

// The IEC 61966-2-1 sRGB decoding formula.
inline double srgb_to_linear(double e) { return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4); }

// The same curve made C1-continuous (the "moncurve" that OpenColorIO's
// ExponentWithLinearTransform {gamma: 2.4, offset: 0.055} implements, and so
// cmfilter's built-in sRGB space): the power segment ((e + o) / (1 + o))^g
// meets its tangent through the origin at e_b = o / (g - 1) = 0.0392857 instead
// of 0.04045. It differs from the IEC formula only in the toe, by < 7.6e-7.
inline double srgb_moncurve_to_linear(double e)
{
    const double g = 2.4, o = 0.055, eb = o / (g - 1);
    const double yb = std::pow((eb + o) / (1 + o), g);
    return e <= eb ? e * (yb / eb) : std::pow((e + o) / (1 + o), g);
}

}  // namespace cmfilter_test
