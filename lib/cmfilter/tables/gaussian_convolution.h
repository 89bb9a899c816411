// SPDX-License-Identifier: Apache-2.0
// Exact Gaussian convolution of a piecewise-linear colour map (eq. 10 of the
// paper):  T(v, sigma) = (C0 * N(0, sigma^2))(v) = <C0, N(v, sigma^2)>.
//
// C0 is written as a sum of unit linear steps between adjacent nodes,
//     C0(x) = C(k_lo) + sum_k [C(k+1) - C(k)] S(x - k),  S(y) = clamp(y, 0, 1),
// in node coordinates (node k at x = k, spacing one texel). The convolution of
// S with a Gaussian of standard deviation s (in texels) is closed form:
//     (S * N(0, s^2))(d) = R(d) - R(d - 1),  R(d) = d Phi(d/s) + s phi(d/s),
// where R = max(0, .) * N(0, s^2). Steps further than 9 s from v are folded
// into the constant term; the Gaussian mass they miss is Phi(-9) < 1.2e-19 per
// side, so the result is exact to double rounding (no truncated or
// unnormalised kernel). For s >= 1 texel, where it is cheaper, the same sum is
// regrouped: C0 is written with its slope changes kappa_k
// (C0 = C(lo) + sum kappa_k max(0, x - k)), kinks are grouped in blocks of at
// most 3 s nodes, and R(x - k) is Taylor-expanded about each block's centre
// (33 terms, remainder below 2.9e-15 s |kappa| per kink), so a block costs one
// erfc and one exp instead of one per node. For repeat/mirror maps and s of the order of the
// period, the Fourier series of the periodic map is used instead: the hat
// basis transforms to sinc^2 and the Gaussian multiplies harmonic m by
// exp(-2 pi^2 m^2 s^2 / p^2); harmonics below 1e-18 are dropped.
#pragma once

#include "cmfilter/colormap/color_map.h"

#include <complex>
#include <vector>

namespace cmfilter {

// Evaluates T(., sigma) for one sigma; construct once per table row.
class GaussianConvolution {
public:
    GaussianConvolution(const ColorMap& map, double sigma);

    Rgb operator()(double v) const;

    // Estimated cost of one evaluation in closed-form ramp evaluations (one
    // erfc and one exp each), without building anything: lets a caller choose
    // between this and a cheaper route for a whole row (gaussian_color_table.cpp).
    static double estimated_cost(const ColorMap& map, double sigma);

    // Sigma (in texels) from which the kink-block expansion replaces the step sum.
    static constexpr double kBlockMinSigma = 1.0;
    // Block width in sigmas, and Taylor terms per block (remainder bound below).
    static constexpr double kBlockWidth = 3.0;
    static constexpr int kTaylorTerms = 33;

private:
    void build_fourier_series();
    void build_kink_blocks();
    Rgb sum_of_steps(double x) const;
    Rgb sum_of_kink_blocks(double x) const;
    Rgb fourier_series(double x) const;

    struct Step {
        long k;     // between nodes k and k + 1
        Rgb delta;  // C(k+1) - C(k), never all zero
    };

    // Up to s consecutive nodes' slope changes, as Taylor moments about their
    // centre: moments[p] = sum_k kappa_k ((centre - k) / s)^p / p!.
    struct KinkBlock {
        double centre = 0;
        Rgb moments[kTaylorTerms];
    };

    const ColorMap* map_;
    std::vector<Step> steps_;
    bool use_blocks_ = false;
    Rgb blocks_base_;
    std::vector<KinkBlock> blocks_;  // sorted by centre
    // Sums over blocks [0, b) of M_0, M_1 and centre * M_0.
    struct LinearPrefix {
        Rgb m0, m1, centre_m0;
    };
    std::vector<LinearPrefix> prefix_;
    double s_;  // sigma in texels
    bool use_fourier_ = false;
    double period_ = 0;  // in nodes
    Rgb mean_;
    std::vector<std::complex<double>> harmonics_[3];  // m = 1..M, damped, per channel
};

// Convenience for single evaluations.
inline Rgb gaussian_convolution(const ColorMap& map, double v, double sigma)
{
    return GaussianConvolution(map, sigma)(v);
}

}  // namespace cmfilter
