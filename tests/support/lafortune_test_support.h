// SPDX-License-Identifier: Apache-2.0
// Lafortune tests' own model, written from the paper's formula (Lafortune
// et al. 1997; the second paper, sec. 3.2) and not from the library:
// value(u) = uz (rho_d + sum_i max(0, Cx ux vx + Cy uy vy + Cz uz vz)^n),
// light sets, and stacks made from known lobes.
#pragma once

#include "cmfilter/stack/image_stack.h"

#include <cmath>
#include <vector>

namespace cmfilter_test {

struct PaperLobe {
    double cx, cy, cz, n;
};

// The paper's f (not times uz) at light u, view v.
inline double paper_reflectance(double rho, const std::vector<PaperLobe>& lobes, const cmfilter::Vec3& u,
                                const cmfilter::Vec3& v)
{
    double f = rho;
    for (const PaperLobe& l : lobes) {
        const double d = l.cx * u.x * v.x + l.cy * u.y * v.y + l.cz * u.z * v.z;
        if (d > 0) f += std::pow(d, l.n);
    }
    return f;
}

// A lobe of scale s, exponent n and unit axis w at the view (0, 0, 1)
// written as the library's axis a = s^(1/n) w (the paper's C times v).
inline cmfilter::Vec3 scaled_axis(const cmfilter::Vec3& w, double s, double n)
{
    const double len = std::sqrt(w.x * w.x + w.y * w.y + w.z * w.z);
    const double m = std::pow(s, 1 / n) / len;
    return {w.x * m, w.y * m, w.z * m};
}

// max(0, a . u)^n, written out.
inline double axis_lobe(const cmfilter::Vec3& a, double n, const cmfilter::Vec3& u)
{
    const double d = a.x * u.x + a.y * u.y + a.z * u.z;
    return d > 0 ? std::pow(d, n) : 0.0;
}

// n lights on a Fibonacci spiral over the hemisphere above `min_z`, the
// spiral turned by `turn` radians (another turn: lights between these).
inline std::vector<cmfilter::Vec3> fibonacci_lights(int n, double min_z = 0.1, double turn = 0)
{
    std::vector<cmfilter::Vec3> lights;
    const double golden = 3.14159265358979323846 * (3 - std::sqrt(5.0));
    for (int k = 0; k < n; ++k) {
        const double z = 1 - (k + 0.5) / n * (1 - min_z);
        const double r = std::sqrt(1 - z * z);
        lights.push_back({r * std::cos(golden * k + turn), r * std::sin(golden * k + turn), z});
    }
    return lights;
}

// One texel's lobes at the view (0, 0, 1): rho_d and axes a with exponents.
struct AxisTexel {
    double rho;
    std::vector<cmfilter::Vec3> axes;
    std::vector<double> exponents;

    double value(const cmfilter::Vec3& u) const
    {
        double f = rho;
        for (std::size_t i = 0; i < axes.size(); ++i) f += axis_lobe(axes[i], exponents[i], u);
        return std::max(0.0, u.z) * f;
    }
};

// A width x 1 stack, texel i made from texels[i] times colour[i] (channels
// 1 or 3).
inline cmfilter::ImageStack stack_from_texels(const std::vector<AxisTexel>& texels,
                                              const std::vector<std::vector<double>>& colours,
                                              const std::vector<cmfilter::Vec3>& lights)
{
    cmfilter::ImageStack s;
    s.width = static_cast<int>(texels.size());
    s.height = 1;
    s.channels = static_cast<int>(colours.front().size());
    s.lights = lights;
    s.colorspace = "lin_rec709";
    s.pixels.assign(lights.size() * s.texels() * s.channels, 0.0f);
    for (std::size_t k = 0; k < lights.size(); ++k)
        for (std::size_t t = 0; t < texels.size(); ++t)
            for (int c = 0; c < s.channels; ++c)
                s.pixels[(k * s.texels() + t) * s.channels + c] =
                    static_cast<float>(colours[t][c] * texels[t].value(lights[k]));
    return s;
}

}  // namespace cmfilter_test
