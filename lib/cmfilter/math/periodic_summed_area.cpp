// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/math/periodic_summed_area.h"

#include <algorithm>
#include <cmath>

namespace cmfilter {

PeriodicSummedArea::PeriodicSummedArea(const std::vector<double>& cells, int n, int channels)
{
    if (n < 1 || channels < 1 || channels > kMaxChannels) return;  // an empty table: box means of nothing
    n_ = n, channels_ = channels;
    means_.assign(static_cast<std::size_t>(channels), 0.0);
    const std::size_t count = static_cast<std::size_t>(n) * n;
    for (std::size_t i = 0; i < count; ++i)
        for (int c = 0; c < channels; ++c) means_[c] += cells[i * channels + c];
    for (double& m : means_) m /= static_cast<double>(count);
    const std::size_t stride = static_cast<std::size_t>(n) + 1;
    table_.assign(stride * stride * channels, 0.0);
    std::vector<double> run(static_cast<std::size_t>(channels));
    for (int y = 0; y < n; ++y) {
        std::fill(run.begin(), run.end(), 0.0);
        for (int x = 0; x < n; ++x) {
            const double* values = cells.data() + (static_cast<std::size_t>(y) * n + x) * channels;
            double* below = table_.data() + ((y + 1) * stride + x + 1) * channels;
            const double* above = below - stride * channels;
            for (int c = 0; c < channels; ++c) {
                run[c] += values[c] - means_[c];
                below[c] = above[c] + run[c];
            }
        }
    }
}

// The table at (x, y), 0 <= x, y <= N: the integral over [0, x] x [0, y],
// bilinear between its integer corners (exact: within a cell the integral is
// linear in x and in y).
void PeriodicSummedArea::at(double x, double y, double* out) const
{
    const int i = std::min(static_cast<int>(x), n_ - 1), j = std::min(static_cast<int>(y), n_ - 1);
    const double a = x - i, b = y - j;
    const std::size_t stride = static_cast<std::size_t>(n_) + 1;
    const double* s00 = table_.data() + (j * stride + i) * channels_;
    const double* s10 = s00 + channels_;
    const double* s01 = s00 + stride * channels_;
    const double* s11 = s01 + channels_;
    for (int c = 0; c < channels_; ++c)
        out[c] = (1 - b) * ((1 - a) * s00[c] + a * s10[c]) + b * ((1 - a) * s01[c] + a * s11[c]);
}

// The integral over [0, X] x [0, Y] (any reals, signed): with X = qx N + rx,
// Y = qy N + ry, qx qy S(N, N) + qx S(N, ry) + qy S(rx, N) + S(rx, ry), where
// S(N, N) = 0 (centred channels).
void PeriodicSummedArea::integral(double X, double Y, double* out) const
{
    const double qx = std::floor(X / n_), qy = std::floor(Y / n_);
    const double rx = std::clamp(X - qx * n_, 0.0, double(n_)), ry = std::clamp(Y - qy * n_, 0.0, double(n_));
    double row[kMaxChannels], column[kMaxChannels];
    at(rx, ry, out);
    at(n_, ry, row);
    at(rx, n_, column);
    for (int c = 0; c < channels_; ++c) out[c] += qx * row[c] + qy * column[c];
}

void PeriodicSummedArea::box_mean(double x0, double y0, double wx, double wy, double* out) const
{
    if (n_ == 0) return;
    const std::size_t k = static_cast<std::size_t>(channels_);
    double f[4 * kMaxChannels];
    integral(x0, y0, f);
    integral(x0 + wx, y0, f + k);
    integral(x0, y0 + wy, f + 2 * k);
    integral(x0 + wx, y0 + wy, f + 3 * k);
    for (std::size_t c = 0; c < k; ++c)
        out[c] = (f[3 * k + c] - f[k + c] - f[2 * k + c] + f[c]) / (wx * wy) + means_[c];
}

}  // namespace cmfilter
