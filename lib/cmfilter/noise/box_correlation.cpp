// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/noise/box_correlation.h"

#include "cmfilter/noise/noise_lattice.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace cmfilter {

Expected<BoxCorrelation> BoxCorrelation::from_grid(std::vector<double> beta, double tail)
{
    if (beta.size() != static_cast<std::size_t>(grid_count))
        return bad_input("box correlation needs " + std::to_string(grid_count) + " samples, got " +
                         std::to_string(beta.size()));
    for (std::size_t j = 0; j < beta.size(); ++j)
        if (!std::isfinite(beta[j]) || std::fabs(beta[j]) > 1.0 + 1e-9)
            return bad_input("box correlation sample " + std::to_string(j) + " must be finite and in [-1, 1], got " +
                             std::to_string(beta[j]));
    if (!(beta[0] > 0)) return bad_input("box correlation must start above 0, got " + std::to_string(beta[0]));

    BoxCorrelation c;
    c.beta_ = std::move(beta);
    // The taper starts at the first sample after which every sample is
    // negligible, and never later than half an octave before the last one.
    int last_large = 0;
    for (int j = 0; j < grid_count; ++j)
        if (std::fabs(c.beta_[static_cast<std::size_t>(j)]) >= std::max(tail, negligible)) last_large = j;
    c.taper_start_ = std::min(grid_log2(last_large + 1), grid_log2(grid_count - 1) - 0.5);
    c.end_log2_ = c.taper_start_ + 0.5;
    const int dense = static_cast<int>(std::ceil((c.end_log2_ - dense_first_log2) * dense_per_octave));
    c.dense_.resize(static_cast<std::size_t>(dense) + 2);  // the last two are past the end: 0
    for (std::size_t j = 0; j < c.dense_.size(); ++j)
        c.dense_[j] = c.tapered_spline(dense_first_log2 + static_cast<double>(j) / dense_per_octave);
    c.dense_last_ = static_cast<double>(c.dense_.size() - 2);
    return c;
}

double BoxCorrelation::spline(double t) const
{
    // Cubic Hermite through the samples, slopes by central differences
    // (one-sided at the ends): C1 in t.
    const int n = static_cast<int>(beta_.size());
    const int j = std::clamp(static_cast<int>(std::floor(t)), 0, n - 2);
    const double s = t - j;
    auto value = [&](int i) { return beta_[static_cast<std::size_t>(std::clamp(i, 0, n - 1))]; };
    auto slope = [&](int i) {
        if (i <= 0) return value(1) - value(0);
        if (i >= n - 1) return value(n - 1) - value(n - 2);
        return 0.5 * (value(i + 1) - value(i - 1));
    };
    const double p0 = value(j), p1 = value(j + 1), m0 = slope(j), m1 = slope(j + 1);
    const double s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * m1;
}

double BoxCorrelation::tapered_spline(double log2_k) const
{
    if (log2_k <= grid_first_log2) {
        // 1 - (1 - beta_0) (k / k_0)^2: continuous with the spline at k_0.
        return 1.0 - (1.0 - beta_[0]) * std::exp2(2.0 * (log2_k - grid_first_log2));
    }
    if (log2_k >= end_log2_) return 0.0;
    double beta = spline((log2_k - grid_first_log2) / grid_step);
    if (log2_k > taper_start_) {
        const double s = (log2_k - taper_start_) / 0.5;
        beta *= 1.0 - s * s * (3.0 - 2.0 * s);
    }
    return beta;
}

double BoxCorrelation::operator()(double k) const
{
    if (!(k > 0)) return 1.0;
    return at_log2(std::log2(k));
}

double BoxCorrelation::cutoff() const { return std::exp2(taper_start_ + 0.5); }

Expected<BoxCorrelation> measure_box_correlation(const std::function<double(double, double)>& term, double period,
                                                 const BoxCorrelationMeasureOptions& options)
{
    const int m = options.pairs_per_axis;
    if (m < 2) return bad_input("box correlation needs at least 2 pairs per axis, got " + std::to_string(m));
    const std::size_t pairs = static_cast<std::size_t>(m) * static_cast<std::size_t>(m);
    std::vector<double> x(pairs), y(pairs), ux(pairs), uy(pairs), t0(pairs);
    std::uint64_t state = options.seed;
    const double cell = 256.0 * period / m;
    double mean = 0;
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) {
            const std::size_t p = static_cast<std::size_t>(j) * static_cast<std::size_t>(m) +
                                  static_cast<std::size_t>(i);
            x[p] = (i + unit_interval(splitmix64(state))) * cell;
            y[p] = (j + unit_interval(splitmix64(state))) * cell;
            ux[p] = unit_interval(splitmix64(state)) - 0.5;
            uy[p] = unit_interval(splitmix64(state)) - 0.5;
            t0[p] = term(x[p], y[p]);
            mean += t0[p];
        }
    mean /= static_cast<double>(pairs);
    double variance = 0;
    for (double v : t0) variance += (v - mean) * (v - mean);
    variance /= static_cast<double>(pairs);
    if (!(variance > 0) || !std::isfinite(variance))
        return bad_input("box correlation: the noise term has no variance to correlate");

    std::vector<double> beta(BoxCorrelation::grid_count);
    for (int g = 0; g < BoxCorrelation::grid_count; ++g) {
        const double side = std::exp2(BoxCorrelation::grid_log2(g)) * period;
        double covariance = 0;
        for (std::size_t p = 0; p < pairs; ++p)
            covariance += (t0[p] - mean) * (term(x[p] + side * ux[p], y[p] + side * uy[p]) - mean);
        beta[static_cast<std::size_t>(g)] = std::clamp(covariance / static_cast<double>(pairs) / variance, -1.0, 1.0);
    }
    // Samples within three standard errors of 0 count as 0 for the tail too.
    return BoxCorrelation::from_grid(std::move(beta), 3.0 / std::sqrt(static_cast<double>(pairs)));
}

}  // namespace cmfilter
