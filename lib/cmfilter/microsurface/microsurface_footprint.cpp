// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/microsurface/microsurface_footprint.h"

#include <algorithm>
#include <cmath>

namespace cmfilter {

namespace {

constexpr double kPi = 3.14159265358979323846;

double sinc(double x) { return std::fabs(x) < 1e-6 ? 1.0 - x * x / 6.0 : std::sin(x) / x; }

// The box filter's damping of one cosine over the parallelogram.
double damping(const GaussianMicrosurface::Cosine& k, double e1u, double e1v, double e2u, double e2v)
{
    return sinc(kPi * (k.fx * e1u + k.fy * e1v)) * sinc(kPi * (k.fx * e2u + k.fy * e2v));
}

double along(double azimuth, double xx, double xy, double yy)
{
    const double c = std::cos(azimuth), s = std::sin(azimuth);
    return std::sqrt(std::max(0.0, c * c * xx + 2 * c * s * xy + s * s * yy));
}

}  // namespace

double MicrosurfaceFootprint::sigma_s(double azimuth) const { return along(azimuth, slope_xx, slope_xy, slope_yy); }

double MicrosurfaceFootprint::resolved_sigma_s(double azimuth) const
{
    return along(azimuth, resolved_xx, resolved_xy, resolved_yy);
}

MicrosurfaceFootprint filter_microsurface(const GaussianMicrosurface& surface, double u, double v, double e1u,
                                          double e1v, double e2u, double e2v)
{
    MicrosurfaceFootprint out;
    double variance = 0, resolved = 0;
    for (const GaussianMicrosurface::Cosine& k : surface.cosines()) {
        const double s = damping(k, e1u, e1v, e2u, e2v);
        out.mean_height += s * k.amplitude * std::cos(2 * kPi * (k.fx * u + k.fy * v) + k.phase);
        const double unresolved = 0.5 * k.amplitude * k.amplitude * (1 - s * s);
        variance += unresolved;
        const double w = unresolved * 4 * kPi * kPi;
        out.slope_xx += w * k.fx * k.fx;
        out.slope_xy += w * k.fx * k.fy;
        out.slope_yy += w * k.fy * k.fy;
        const double kept = 0.5 * k.amplitude * k.amplitude * s * s;
        resolved += kept;
        const double r = kept * 4 * kPi * kPi;
        out.resolved_xx += r * k.fx * k.fx;
        out.resolved_xy += r * k.fx * k.fy;
        out.resolved_yy += r * k.fy * k.fy;
    }
    out.sigma_h = std::sqrt(std::max(0.0, variance));
    out.resolved_sigma_h = std::sqrt(std::max(0.0, resolved));
    return out;
}

ResolvedSlope resolved_slope(const GaussianMicrosurface& surface, double u, double v, double e1u, double e1v,
                             double e2u, double e2v)
{
    ResolvedSlope out;
    for (const GaussianMicrosurface::Cosine& k : surface.cosines()) {
        const double along = -2 * kPi * damping(k, e1u, e1v, e2u, e2v) * k.amplitude *
                             std::sin(2 * kPi * (k.fx * u + k.fy * v) + k.phase);
        out.x += along * k.fx;
        out.y += along * k.fy;
    }
    return out;
}

}  // namespace cmfilter
