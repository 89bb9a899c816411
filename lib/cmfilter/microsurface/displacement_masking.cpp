// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/microsurface/displacement_masking.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cmfilter {

namespace {
constexpr double kTwoPi = 6.283185307179586;
}

DisplacementMasking DisplacementMasking::from_texels(const std::vector<double>& heights,
                                                     const std::vector<double>& slopes_x,
                                                     const std::vector<double>& slopes_y, int n,
                                                     const DisplacementMaskingOptions& options)
{
    DisplacementMasking out;
    if (n < 1) return out;
    // Every step-th texel along both axes.
    const double count = static_cast<double>(n) * n;
    const int step = std::max(1, static_cast<int>(std::ceil(std::sqrt(count / std::max(1, options.max_texels)))));
    std::vector<std::size_t> texels;
    for (int j = 0; j < n; j += step)
        for (int i = 0; i < n; i += step) texels.push_back(static_cast<std::size_t>(j) * n + i);
    for (std::size_t k : texels) out.heights_.push_back(heights[k]);
    std::sort(out.heights_.begin(), out.heights_.end());
    const int azimuths = std::max(1, options.azimuths);
    out.projected_.resize(azimuths);
    out.tail_.resize(azimuths);
    for (int a = 0; a < azimuths; ++a) {
        const double phi = kTwoPi * a / azimuths, dx = std::cos(phi), dy = std::sin(phi);
        std::vector<double>& q = out.projected_[a];
        for (std::size_t k : texels) q.push_back(slopes_x[k] * dx + slopes_y[k] * dy);
        std::sort(q.begin(), q.end());
        std::vector<double>& tail = out.tail_[a];
        tail.assign(q.size() + 1, 0.0);
        for (std::size_t k = q.size(); k-- > 0;) tail[k] = tail[k + 1] + q[k];
    }
    return out;
}

double DisplacementMasking::height_cdf(double h) const
{
    const std::vector<double>& s = heights_;
    if (s.empty() || !std::isfinite(h)) return 0.5;
    const double n = static_cast<double>(s.size());
    const auto lo = std::lower_bound(s.begin(), s.end(), h), hi = std::upper_bound(s.begin(), s.end(), h);
    const double below = static_cast<double>(lo - s.begin());
    if (lo != hi) return (below + 0.5 * static_cast<double>(hi - lo)) / n;  // ties: their mid rank
    // Between s[below - 1] (rank below - 1/2) and s[below] (rank below + 1/2).
    if (lo == s.begin()) return 0.5 / n;
    if (lo == s.end()) return 1 - 0.5 / n;
    const double t = (h - *(lo - 1)) / (*lo - *(lo - 1));
    return (below - 0.5 + t) / n;
}

double DisplacementMasking::lambda_at(int a, double mu) const
{
    const std::vector<double>& q = projected_[a];
    const auto first = std::upper_bound(q.begin(), q.end(), mu);  // the slopes steeper than the ray
    const std::size_t k = static_cast<std::size_t>(first - q.begin());
    const double above = static_cast<double>(q.size() - k);
    if (above == 0) return 0;
    if (mu <= 0) return std::numeric_limits<double>::infinity();
    return (tail_[a][k] - mu * above) / (static_cast<double>(q.size()) * mu);  // eq. 3
}

double DisplacementMasking::lambda(const ViewAngles& direction) const
{
    if (projected_.empty()) return 0;
    const SlopeViewFrame f = slope_view_frame({}, direction);
    if (f.sin_theta <= 0) return 0;
    const double mu = f.cos_theta / f.sin_theta;
    const int azimuths = static_cast<int>(projected_.size());
    double phi = std::atan2(f.dy, f.dx);
    if (phi < 0) phi += kTwoPi;
    const double x = phi / kTwoPi * azimuths;
    const int a0 = std::min(azimuths - 1, static_cast<int>(std::floor(x)));
    const double t = x - a0;
    const double l0 = lambda_at(a0, mu), l1 = lambda_at((a0 + 1) % azimuths, mu);
    if (t <= 0) return l0;
    if (std::isinf(l0) || std::isinf(l1)) return std::numeric_limits<double>::infinity();
    return (1 - t) * l0 + t * l1;
}

}  // namespace cmfilter
