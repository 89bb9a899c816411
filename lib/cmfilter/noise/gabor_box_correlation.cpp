// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/noise/gabor_box_correlation.h"

#include "cmfilter/math/gauss_legendre.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace cmfilter {

BoxCorrelation gabor_noise_box_correlation(const GaborNoiseOptions& options)
{
    constexpr double pi = 3.14159265358979323846;
    const double a = options.bandwidth, f0 = options.frequency;
    const double period = f0 > 0 ? 1.0 / f0 : 1.0 / a;
    const double e = std::exp(-2.0 * pi * f0 * f0 / (a * a));
    const double reach = 7.0 / a;  // exp(-pi a^2 t^2 / 2) < e^-75 beyond
    const double panel = std::min(f0 > 0 ? 0.25 / f0 : 1.0, 0.5 / a);

    // I(theta) over [-h, h], by symmetry twice the integral over [0, h].
    auto envelope_cosine = [&](double theta, double h) {
        const double end = std::min(h, reach);
        const int panels = std::max(1, static_cast<int>(std::ceil(end / panel)));
        return 2.0 *
               gauss_legendre_8([&](double t) { return std::exp(-0.5 * pi * a * a * t * t) * std::cos(theta * t); },
                                0.0, end, panels);
    };

    std::vector<double> samples(BoxCorrelation::grid_count);
    for (int j = 0; j < BoxCorrelation::grid_count; ++j) {
        const double h = 0.5 * std::exp2(BoxCorrelation::grid_log2(j)) * period;
        const double theta = 2.0 * pi * f0;
        double oscillating;
        if (options.orientation) {
            oscillating = envelope_cosine(theta * std::cos(*options.orientation), h) *
                          envelope_cosine(theta * std::sin(*options.orientation), h);
        } else {
            oscillating = gauss_legendre_8(
                              [&](double phi) {
                return envelope_cosine(theta * std::cos(phi), h) * envelope_cosine(theta * std::sin(phi), h);
                              },
                              0.0, 0.5 * pi, 4) /
                (0.5 * pi);
        }
        const double flat = envelope_cosine(0.0, h);
        const double area = 4.0 * h * h;
        samples[static_cast<std::size_t>(j)] =
            std::clamp((oscillating + e * flat * flat) / ((1.0 + e) * area), -1.0, 1.0);
    }
    return *BoxCorrelation::from_grid(std::move(samples));
}

}  // namespace cmfilter
