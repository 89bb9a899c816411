#include "cmfilter/masked_slope_table.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace cmfilter {

namespace {

constexpr int kChannelsPerLambda = 6;
constexpr int kLowestPower = -5;  // Lambda_1 = 2^-5; Lambda_0 = 0

double lambda_at(int j) { return j == 0 ? 0.0 : std::ldexp(1.0, kLowestPower + j - 1); }

}  // namespace

MaskedSlopeTable MaskedSlopeTable::build(
    const std::function<void(double, double, double&, double&, double&)>& surface, int n,
    const DisplacementMasking& masking)
{
    MaskedSlopeTable out;
    if (n < 1) return out;
    int m = n;  // cells per side
    while (m > kMaxCells && m % 2 == 0) m /= 2;
    const int points = std::max(1, 2 * n / m);  // per cell and axis: 2 per texel
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
                    const double f = masking.height_cdf(h);
                    const double values[kChannelsPerLambda] = {1, sx, sy, sx * sx, sy * sy, sx * sy};
                    for (int j = 0; j < kLambdas; ++j) {
                        const double w = weight * std::pow(f, lambda_at(j));  // G1 (eq. 2)
                        for (int k = 0; k < kChannelsPerLambda; ++k) c[j * kChannelsPerLambda + k] += w * values[k];
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
    for (int k = 1; k < kChannelsPerLambda; ++k) {
        const double l = lo[k] / lo[0], h = hi[k] / hi[0];
        // The mean squares geometrically (they shrink as a power of Lambda
        // as G1 picks out the highest points), the rest linearly.
        const bool square = k == 3 || k == 4;
        out[k] = out[0] * (square && l > 0 && h > 0 ? std::exp((1 - t) * std::log(l) + t * std::log(h))
                                                     : (1 - t) * l + t * h);
    }
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
