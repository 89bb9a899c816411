// SPDX-License-Identifier: Apache-2.0
// Fractal sums over any 2-D base noise n of base period p_0 (Musgrave,
// "Texturing and Modeling", ch. 16; Perlin 1985 for turbulence):
//     fBm:         f(x) = sum_{i<N} gain^i n(lacunarity^i x + s_i)
//     turbulence:  f(x) = sum_{i<N} gain^i |n(lacunarity^i x + s_i)|
// Octave i has period p_i = p_0 / lacunarity^i. Each octave's domain is shifted
// by s_i, drawn from the fractal's seed (uniform over 256 x 256 units), so the
// octaves sample unrelated parts of the base noise and decorrelate even when
// lacunarity is an integer and the base lattice repeats.
// Turbulence is not Gaussian (a folded, skewed sum): a stress case for the
// Gaussian filtering of sec. 4.2.
//
// Filtered evaluation over a square footprint of width w (docs/noise.md,
// "Filtered mean"): each octave's term t_i (n or |n|) is replaced by the
// least-squares prediction of its mean over the footprint from its value at
// the centre,
//     mean_w(x) = sum_i gain^i (mu + beta(w / p_i) (t_i(x) - mu)),
// mu the term's mean (the base mean for fBm, mean |n| for turbulence) and
// beta the term's box correlation (box_correlation.h): the mean of its
// normalised autocorrelation over the footprint. beta = 1 for a point, falls
// smoothly (C1 in w: no popping across LOD) as the footprint averages the
// octave away, and is exactly 0 past its cutoff, where the octave is not
// evaluated at all.
#pragma once

#include "cmfilter/noise/box_correlation.h"
#include "cmfilter/util/error.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace cmfilter {

// A base noise and the statistics the filtered evaluation fades to.
struct BaseNoise {
    std::function<double(double, double)> evaluate;
    double period = 1.0;    // p_0, in noise coordinates
    double mean = 0.0;      // E[n]: 0 for every built-in noise
    double mean_abs = 0.0;  // E[|n|]: turbulence octaves fade to it
    // Box correlations of n (fBm) and |n| (turbulence); FractalNoise::create
    // measures the one its sum needs when it is missing
    // (measure_box_correlation).
    std::optional<BoxCorrelation> correlation, correlation_abs;
};

// E[|n|] measured by jittered-stratified sampling: samples_per_axis^2 points,
// one per cell of a grid over the square [0, 256 period)^2 (one whole period of
// the lattice noises), from a fixed generator: deterministic.
double measure_mean_abs(const std::function<double(double, double)>& evaluate, double period,
                        int samples_per_axis = 256);

enum class FractalSum { Fbm, Turbulence };
const char* to_string(FractalSum sum);

struct FractalOptions {
    int octaves = 6;          // N >= 1
    double lacunarity = 2.0;  // > 1
    double gain = 0.5;        // > 0
    FractalSum sum = FractalSum::Fbm;
};

class FractalNoise {
public:
    // Validates the options and the base period, naming the bad value.
    static Expected<FractalNoise> create(BaseNoise base, const FractalOptions& options, std::uint64_t seed);

    double operator()(double x, double y) const;

    // The unweighted term of octave i: n or |n| at the octave's point.
    double octave(int i, double x, double y) const;
    double octave_period(int i) const { return periods_[static_cast<std::size_t>(i)]; }
    double octave_log2_period(int i) const { return log2_periods_[static_cast<std::size_t>(i)]; }
    double octave_amplitude(int i) const { return amplitudes_[static_cast<std::size_t>(i)]; }
    // What an octave fades to: the base mean (fBm) or mean |n| (turbulence).
    double octave_mean() const;
    // beta(w / p_i): the weight octave i's value at the centre keeps in the
    // mean over a footprint of width w.
    double resolved_fraction(int i, double w) const;
    // The box correlation of the octave term (n for fBm, |n| for turbulence).
    const BoxCorrelation& term_correlation() const { return *correlation_; }

    // The mean over a footprint of width w (noise units) centred at (x, y).
    double mean_over_footprint(double x, double y, double w) const;
    // The same from log2 w (-inf for a point), for callers that have it.
    double mean_over_footprint_log2(double x, double y, double log2_w) const;

    const BaseNoise& base() const { return base_; }
    const FractalOptions& options() const { return options_; }
    double base_period() const { return base_.period; }

private:
    FractalNoise() = default;

    BaseNoise base_;
    FractalOptions options_;
    std::optional<BoxCorrelation> correlation_;
    double log2_cutoff_ = 0;
    std::vector<double> periods_, log2_periods_, amplitudes_, scales_, shift_x_, shift_y_;
};

}  // namespace cmfilter
