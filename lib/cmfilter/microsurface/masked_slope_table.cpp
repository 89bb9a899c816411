// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/microsurface/masked_slope_table.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace cmfilter {

namespace {

constexpr int kChannelsPerLambda = 6;
constexpr int kLowestPower = -5;  // Lambda_1 = 2^-5; Lambda_0 = 0

double lambda_at(int j) { return j == 0 ? 0.0 : std::ldexp(1.0, kLowestPower + j - 1); }

}  // namespace

MaskedSlopeTable MaskedSlopeTable::build(const std::function<void(double, double, double&, double&, double&)>& surface,
                                         int n, const DisplacementMasking& masking)
{
    MaskedSlopeTable out;
    if (n < 1) return out;
    const int m = std::min(n, kMaxCells);  // cells per side
    // Per cell and axis: 2 points per texel, at most kMaxPoints.
    const int points = std::clamp((2 * n + m - 1) / m, 1, kMaxPoints);
    const int channels = kLambdas * kChannelsPerLambda;
    std::vector<double> cells(static_cast<std::size_t>(m) * m * channels, 0.0);
    const double weight = 1.0 / (static_cast<double>(points) * points);
    for (int cy = 0; cy < m; ++cy)
        for (int cx = 0; cx < m; ++cx) {
            double* c = cells.data() + (static_cast<std::size_t>(cy) * m + cx) * channels;
            for (int py = 0; py < points; ++py)
                for (int px = 0; px < points; ++px) {
                    const double u = (cx + (px + 0.5) / points) / m, v = (cy + (py + 0.5) / points) / m;
                    double h = 0, sx = 0, sy = 0;
                    surface(u, v, h, sx, sy);
                    const double values[kChannelsPerLambda] = {1, sx, sy, sx * sx, sy * sy, sx * sy};
                    // G1 = F^Lambda (eq. 2): F^0, then F^(2^-5) squared up to F^(2^(kLambdas - 2 - 5)).
                    double g = std::pow(masking.height_cdf(h), lambda_at(1));
                    for (int j = 0; j < kLambdas; ++j) {
                        const double w = weight * (j == 0 ? 1.0 : g);
                        for (int k = 0; k < kChannelsPerLambda; ++k) c[j * kChannelsPerLambda + k] += w * values[k];
                        if (j > 0) g *= g;
                    }
                }
        }
    out.table_ = PeriodicSummedArea(cells, m, channels);
    return out;
}

MaskedMoments MaskedSlopeTable::blend(const double* channels, double lambda) const
{
    if (!(lambda > 0)) lambda = 0;
    // The two tabulated Lambdas about it and the share of the upper one.
    int j = 0;
    double t = 0;
    if (lambda >= lambda_at(kLambdas - 1)) {
        j = kLambdas - 2, t = 1;
    } else if (lambda < lambda_at(1)) {
        j = 0, t = lambda / lambda_at(1);
    } else {
        const double x = std::log2(lambda) - kLowestPower;  // 0 at Lambda_1
        j = std::min(kLambdas - 2, 1 + static_cast<int>(std::floor(x)));
        t = x - (j - 1);
    }
    // The weight by its reciprocal, linearly in Lambda (1 / E[F^Lambda] =
    // 1 + Lambda for a uniform F), the weighted means in log2 Lambda.
    const double* lo = channels + j * kChannelsPerLambda;
    const double* hi = lo + kChannelsPerLambda;
    MaskedMoments out;
    if (!(lo[0] > 0) || !(hi[0] > 0)) {
        for (int k = 0; k < kChannelsPerLambda; ++k) out[k] = (1 - t) * lo[k] + t * hi[k];
        return out;
    }
    const double a = lambda_at(j), b = lambda_at(j + 1);
    const double s = std::clamp((lambda - a) / (b - a), 0.0, 1.0);
    out[0] = 1 / ((1 - s) / lo[0] + s / hi[0]);
    // Means linearly, variances geometrically (they shrink as a power of
    // Lambda as G1 picks out the highest points), the covariance's
    // correlation linearly: a positive semi-definite result from two.
    const auto lerp = [t](double x, double y) { return (1 - t) * x + t * y; };
    const auto central = [](const double* c) {
        const double mx = c[1] / c[0], my = c[2] / c[0];
        const double xx = std::max(0.0, c[3] / c[0] - mx * mx), yy = std::max(0.0, c[4] / c[0] - my * my);
        const double bound = std::sqrt(xx * yy);
        return std::array<double, 5>{mx, my, xx, yy,
                                     bound > 0 ? std::clamp((c[5] / c[0] - mx * my) / bound, -1.0, 1.0) : 0.0};
    };
    const std::array<double, 5> l = central(lo), h = central(hi);
    const auto geometric = [&](double x, double y) {
        return x > 0 && y > 0 ? std::exp(lerp(std::log(x), std::log(y))) : lerp(x, y);
    };
    const double mx = lerp(l[0], h[0]), my = lerp(l[1], h[1]);
    const double xx = geometric(l[2], h[2]), yy = geometric(l[3], h[3]);
    const double xy = lerp(l[4], h[4]) * std::sqrt(xx * yy);
    out[1] = out[0] * mx;
    out[2] = out[0] * my;
    out[3] = out[0] * (xx + mx * mx);
    out[4] = out[0] * (yy + my * my);
    out[5] = out[0] * (xy + mx * my);
    return out;
}

MaskedMoments MaskedSlopeTable::box(double u0, double v0, double wu, double wv, double lambda) const
{
    const int m = table_.size();
    if (m == 0) return {1, 0, 0, 0, 0, 0};
    double channels[kLambdas * kChannelsPerLambda];
    table_.box_mean(u0 * m, v0 * m, wu * m, wv * m, channels);
    return blend(channels, lambda);
}

MaskedMoments MaskedSlopeTable::repeat(double lambda) const
{
    if (table_.size() == 0) return {1, 0, 0, 0, 0, 0};
    return blend(table_.means().data(), lambda);
}

}  // namespace cmfilter
