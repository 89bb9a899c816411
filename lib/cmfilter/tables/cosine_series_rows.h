// SPDX-License-Identifier: Apache-2.0
// Rows of the Gaussian table (eq. 10) of a clamp-wrapped colour map by the
// cosine series of its mirrored extension, evaluated at every value node at
// once with an FFT: the fast path for rows whose sigma spans a few value
// nodes or more.
//
// On a window [a, b] that holds the map's texel centres x_k and reaches far
// enough beyond the value nodes, C0 is replaced by its even, 2(b - a)-periodic
// extension f (mirrored at a and b). C0 is constant beyond its end texels, so
// f = C0 on [2a - x_0, 2b - x_{n-1}]; the window is chosen so that this covers
// every value node +- 9 sigma_max, where the Gaussian mass left out is
// Phi(-9) < 1.2e-19. f has the cosine series
//     f(x) = a_0 + sum_{m>=1} a_m cos(w_m (x - a)),  w_m = pi m / W,  W = b - a,
//     a_m = -2 / (W w_m^2) sum_k kappa_k cos(w_m (x_k - a))
// (integrate twice by parts: f'' is the map's slope changes kappa_k, once at
// x_k and once mirrored), and a Gaussian multiplies harmonic m by
// exp(-w_m^2 sigma^2 / 2). The window's grid has the value-node spacing h,
// W = K h (K a power of two), so the damped series at every grid point is a
// DCT-I of size K + 1, computed from a real FFT of size K (see evaluate()); two
// real sequences share one complex FFT, so two rows (six channels) cost three.
// Harmonics beyond K are dropped; error_bound() bounds their sum, and the
// bake uses this path only where that bound is negligible.
#pragma once

#include "cmfilter/colormap/color_map.h"
#include "cmfilter/math/fft.h"

#include <array>
#include <vector>

namespace cmfilter {

class CosineSeriesRows {
public:
    // Plans the window (cheap). map must use WrapMode::Clamp; value nodes
    // v_i = first + i step, i < count, step > 0; rows up to sigma_max.
    CosineSeriesRows(const ColorMap& map, double first, double step, int count, double sigma_max);

    // Upper bound on |series - T(v_i, sigma)| from the dropped harmonics, per
    // channel, before rounding. Infinite when sigma <= 0 or above sigma_max.
    double error_bound(double sigma) const;

    // Estimated cost of one row in closed-form ramp evaluations (the unit of
    // GaussianConvolution::estimated_cost), FFT included.
    double row_cost() const;

    // The series' coefficients: n kinks x K harmonics of work. Call once
    // before evaluate(); threads as for parallel_for.
    void compute_coefficients(int threads);

    // T(v_i, sigma) for i < count into out[3 i + c]; two rows at once
    // (out_b may be null).
    void evaluate(double sigma_a, float* out_a, double sigma_b, float* out_b) const;

    int harmonics() const { return K_; }

private:
    const ColorMap* map_;
    int count_;
    double sigma_max_;
    int J_ = 0;                                        // the value node v_0 sits at grid index J
    int K_ = 0;                                        // window grid points 0..K, W = K step
    double window_ = 0;                                // W
    double start_ = 0;                                 // a
    double kappa_sum_ = 0;                             // max over channels of sum |kappa_k|
    std::vector<Rgb> kappa_;                           // slope change at texel centre k
    std::array<std::vector<double>, 3> coefficients_;  // a_m, m = 0..K
    std::vector<double> cosines_, sines_;              // cos, sin (pi m / K), m = 0..K
    Fft fft_{1};
};

}  // namespace cmfilter
