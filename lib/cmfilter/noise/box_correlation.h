// SPDX-License-Identifier: Apache-2.0
// The box correlation of a stationary noise term t (n, or |n| for turbulence):
// the mean of its normalised autocorrelation rho(d) = Cov(t(x), t(x + d)) / Var t
// over the offsets d of a square of side k periods p centred at 0,
//     beta(k) = (1 / (k p)^2) integral over [-k p / 2, k p / 2]^2 of rho(d) dd
//             = Cov(mean of t over the square of side k p centred at x, t(x)) / Var t.
// It is the least-squares regression weight of a footprint's mean on the value
// at the footprint's centre: the best prediction of the mean of t over a
// square footprint of width w from t(x) alone is
//     E[t] + beta(w / p) (t(x) - E[t])
// (docs/noise.md, "Filtered mean"). beta(0) = 1; beta falls to 0 as the
// footprint averages the term to its mean.
//
// A BoxCorrelation holds beta sampled at log2 k = first + j step, joins the
// samples with a C1 cubic Hermite spline in log2 k, and tabulates that spline
// every 1/64 octave for linear interpolation (within 1e-4 of the spline; a
// broken line this fine never pops across LOD). Below the first sample,
// beta = 1 - (1 - beta_0)(k / k_0)^2 (the quadratic start of every smooth
// autocorrelation), tabulated down to k = 2^-12 and held below (there
// 1 - beta < 1e-6 for every built-in noise); k = 0 gives 1 exactly. Once every later sample is below `tail`, beta is tapered
// to exactly 0 over half an octave (smoothstep in log2 k) and is 0 from then
// on, so far footprints need not evaluate the term at all; cutoff() is where
// that starts. The default tail, 0.1, drops octaves whose centre value would
// explain about beta^2 / (Var T / Var t) ~ beta <= 10% of their footprint
// mean's variance (Var T ~ beta Var t once the footprint spans the
// correlation length).
#pragma once

#include "cmfilter/util/error.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <vector>

namespace cmfilter {

class BoxCorrelation {
public:
    // The sample grid every built-in noise uses: log2 k = -4, -3.75, ..., 5.
    static constexpr double grid_first_log2 = -4.0;
    static constexpr double grid_step = 0.25;
    static constexpr int grid_count = 37;
    static constexpr double negligible = 0.1;
    static constexpr int dense_per_octave = 64;
    static constexpr double dense_first_log2 = -12.0;

    // log2 k of grid sample j.
    static double grid_log2(int j) { return grid_first_log2 + grid_step * j; }

    // beta sampled at grid_log2(j), j = 0 .. grid_count - 1; every value finite
    // and in [-1, 1], the first above 0. Samples below `tail` (at least
    // `negligible`; a measured beta passes its noise level) end it: the taper
    // starts at the first sample after which every one is below tail.
    static Expected<BoxCorrelation> from_grid(std::vector<double> beta, double tail = negligible);

    // beta(k) for a square of side k periods; 1 for k <= 0.
    double operator()(double k) const;
    // The same from log2 k (not NaN), without a branch, a log or an
    // exponential: the fractal sum's inner loop has log2 k for a subtraction.
    double at_log2(double log2_k) const
    {
        const double t = std::clamp((log2_k - dense_first_log2) * dense_per_octave, 0.0, dense_last_);
        const auto j = static_cast<std::size_t>(t);
        const double s = t - static_cast<double>(j);
        return dense_[j] + s * (dense_[j + 1] - dense_[j]);
    }
    // beta = 0 for every k >= cutoff().
    double cutoff() const;

    const std::vector<double>& samples() const { return beta_; }

private:
    BoxCorrelation() = default;
    double spline(double t) const;
    double tapered_spline(double log2_k) const;

    std::vector<double> beta_;
    double taper_start_ = 0;     // log2 k where the taper begins; it ends half an octave later
    double end_log2_ = 0;        // taper_start_ + 0.5: beta = 0 from here
    double dense_last_ = 0;      // the last interpolation index: dense_.size() - 2
    std::vector<double> dense_;  // beta every 1/64 octave from dense_first_log2 to past end_log2_
};

// beta of an arbitrary stationary term by Monte-Carlo (for turbulence's |n|
// and for bases without a closed form): the covariance of t(x) and t(x + k p u)
// over pairs, x jittered-stratified over [0, 256 p)^2 and u uniform in
// [-1/2, 1/2]^2, the same pairs for every k (so the estimate is smooth in k),
// divided by the variance of t(x). Fixed generator: deterministic. The
// standard error of each sample is about 1 / sqrt(pairs).
struct BoxCorrelationMeasureOptions {
    int pairs_per_axis = 96;  // 96^2 = 9216 pairs
    std::uint64_t seed = 0xB0C5C0AAull;
};
Expected<BoxCorrelation> measure_box_correlation(const std::function<double(double, double)>& term, double period,
                                                 const BoxCorrelationMeasureOptions& options = {});

}  // namespace cmfilter
