// SPDX-License-Identifier: Apache-2.0
// 2-D Gabor noise (Lagae, Lefebvre, Drettakis, Dutre 2009, "Procedural noise
// using sparse Gabor convolution"): a sparse convolution
//     n(x) = sum_i w_i g(x - x_i; omega_i)
// of Gabor kernels
//     g(x; omega) = K exp(-pi a^2 |x|^2) cos(2 pi F0 <x, omega>)
// with the impulses x_i a Poisson process of density lambda (impulses per unit
// area), weights w_i independent and uniform in [-1, 1] (E[w] = 0,
// E[w^2] = 1/3), and omega_i the unit vector at a fixed angle (anisotropic) or
// at an angle uniform in [0, 2 pi) per impulse (isotropic).
//
// Variance (Lagae et al. 2009, sec. 3.3; derivation in docs/noise.md): by
// Campbell's theorem Var n = lambda E[w^2] integral g^2, and
//     integral g^2 = K^2 / (4 a^2) (1 + exp(-2 pi F0^2 / a^2)),
// the same for every omega, so isotropic and anisotropic noise share
//     Var n = lambda K^2 / (12 a^2) (1 + exp(-2 pi F0^2 / a^2)).
// The mean is 0. n is unbounded (a sum of Poisson many kernels) and close to
// Gaussian when many kernels overlap (lambda / a^2 large).
//
// Evaluation: the plane is cut into square cells of side r = truncation_radius
// = 1.5 / a; each cell draws its impulses from a generator seeded by the
// noise's seed and the cell's coordinates; a point sums the kernels of its 3 x 3
// cells, each truncated at radius r. The truncated tail holds at most
// 2 exp(-2 pi a^2 r^2) = 1.4e-6 of integral g^2: the analytic variance is that
// of the evaluated noise to that relative accuracy.
//
// Base period: 1 / F0 (the kernel's wavelength); 1 / a when F0 = 0.
#pragma once

#include "cmfilter/util/error.h"

#include <cstdint>
#include <optional>

namespace cmfilter {

struct GaborNoiseOptions {
    double amplitude = 1.0;             // K
    double bandwidth = 0.8;             // a: Gaussian envelope exp(-pi a^2 |x|^2)
    double frequency = 1.0;             // F0: cycles per unit length
    std::optional<double> orientation;  // radians; empty: isotropic
    double impulse_density = 8.0;       // lambda: impulses per unit area
};

class GaborNoise {
public:
    // Checks every option, naming the bad one: amplitude finite, bandwidth > 0,
    // frequency >= 0, orientation finite, impulse density > 0 and no more than
    // 10000 impulses per cell on average.
    static Expected<GaborNoise> create(const GaborNoiseOptions& options, std::uint64_t seed);

    double operator()(double x, double y) const;

    const GaborNoiseOptions& options() const { return options_; }
    double variance() const { return analytic_variance(options_); }
    double period() const;
    double truncation_radius() const { return 1.5 / options_.bandwidth; }

    static double analytic_variance(const GaborNoiseOptions& options);

private:
    GaborNoise(const GaborNoiseOptions& options, std::uint64_t seed) : options_(options), seed_(seed) {}

    GaborNoiseOptions options_;
    std::uint64_t seed_ = 0;
};

}  // namespace cmfilter
