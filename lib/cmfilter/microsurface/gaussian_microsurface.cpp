// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/microsurface/gaussian_microsurface.h"

#include "cmfilter/noise/noise_lattice.h"

#include <cmath>
#include <string>

namespace cmfilter {

namespace {
constexpr double kTwoPi = 6.28318530717958647692;
}

Expected<GaussianMicrosurface> GaussianMicrosurface::create(const GaussianMicrosurfaceOptions& o)
{
    if (o.cosines < 1)
        return bad_input("microsurface cosines " + std::to_string(o.cosines) + " is out of range (expected >= 1)");
    if (!(o.sigma_h >= 0) || !std::isfinite(o.sigma_h))
        return bad_input("microsurface sigma_h " + std::to_string(o.sigma_h) +
                         " is out of range (expected finite, >= 0)");
    if (!(o.min_wavelength > 0) || !std::isfinite(o.max_wavelength) || !(o.max_wavelength >= o.min_wavelength))
        return bad_input("microsurface wavelengths [" + std::to_string(o.min_wavelength) + ", " +
                         std::to_string(o.max_wavelength) + "] are out of range (expected 0 < min <= max, finite)");
    if (!(o.tile >= 0) || !std::isfinite(o.tile) || (o.tile > 0 && o.tile < o.max_wavelength))
        return bad_input("microsurface tile " + std::to_string(o.tile) +
                         " is out of range (expected 0, not periodic, or a period >= max_wavelength " +
                         std::to_string(o.max_wavelength) + ")");
    GaussianMicrosurface s;
    s.tile_ = o.tile;
    std::uint64_t state = o.seed;
    splitmix64(state);
    const double lo = std::log(1.0 / o.max_wavelength), hi = std::log(1.0 / o.min_wavelength);
    // Equal amplitudes: sigma_h^2 = n a^2 / 2.
    const double amplitude = o.sigma_h * std::sqrt(2.0 / o.cosines);
    for (int k = 0; k < o.cosines; ++k) {
        const double f = std::exp(lo + (hi - lo) * unit_interval(splitmix64(state)));
        const double angle = kTwoPi * unit_interval(splitmix64(state));
        const double phase = kTwoPi * unit_interval(splitmix64(state));
        double fx = f * std::cos(angle), fy = f * std::sin(angle);
        if (o.tile > 0) {
            // The nearest lattice frequency (i, j) / tile other than 0.
            fx = std::round(fx * o.tile) / o.tile;
            fy = std::round(fy * o.tile) / o.tile;
            if (fx == 0 && fy == 0) (std::abs(std::cos(angle)) >= std::abs(std::sin(angle)) ? fx : fy) = 1.0 / o.tile;
        }
        s.cosines_.push_back({amplitude, fx, fy, phase});
    }
    s.sigma_h_ = o.sigma_h;
    return s;
}

double GaussianMicrosurface::height(double x, double y) const
{
    double h = 0;
    for (const Cosine& c : cosines_) h += c.amplitude * std::cos(kTwoPi * (c.fx * x + c.fy * y) + c.phase);
    return h;
}

void GaussianMicrosurface::gradient(double x, double y, double& dx, double& dy) const
{
    dx = dy = 0;
    for (const Cosine& c : cosines_) {
        const double s = -c.amplitude * kTwoPi * std::sin(kTwoPi * (c.fx * x + c.fy * y) + c.phase);
        dx += s * c.fx;
        dy += s * c.fy;
    }
}

double GaussianMicrosurface::sigma_s(double azimuth) const
{
    const double dx = std::cos(azimuth), dy = std::sin(azimuth);
    double v = 0;
    for (const Cosine& c : cosines_) {
        const double along = kTwoPi * (c.fx * dx + c.fy * dy);
        v += 0.5 * c.amplitude * c.amplitude * along * along;
    }
    return std::sqrt(v);
}

}  // namespace cmfilter
