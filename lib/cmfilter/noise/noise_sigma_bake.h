// SPDX-License-Identifier: Apache-2.0
// Baking a procedural noise's NoiseSigmaTable by Monte-Carlo (sec. 4.2: "we
// precompute the noise standard deviation for different levels of detail and
// store it in a 1D texture"; docs/bake-noise.md).
//
// At LOD L the footprint width is w = p_0 2^L (p_0 the noise's base period).
// Two footprints of width w centred at c:
//   box:      the square [c - w/2, c + w/2]^2, sampled by stratified jitter
//             (an n x n grid of cells, one uniform point in each, S = n^2,
//             n even);
//   Gaussian: the isotropic normal N(c, (w/2)^2 I): width = 2 x its standard
//             deviation, sampled by S independent Gaussian offsets.
// For F footprint centres uniform over [0, 256 p_0)^2, each footprint j gives
// an unbiased within-footprint variance v_j: sum (f - mean_j)^2 / (S - 1) for
// the Gaussian's independent samples; for the box's stratified samples
// (1/S) sum (f - mean_j)^2 + an estimate of Var(mean_j) (collapsed strata,
// noise_sigma_bake.cpp), since S/(S-1) assumes independent samples;
// sigma = sqrt(mean_j v_j). The 95% confidence interval of the mean variance
// is V +- 1.96 sd(v) / sqrt(F) (central limit theorem over independent
// footprints), mapped through sqrt to [sigma_lo, sigma_hi]; the reported
// half-width is (sigma_hi - sigma_lo) / 2. F grows until the half-width is at
// most `relative_half_width` of sigma, or reaches `max_footprints`.
//
// Everything is drawn from SplitMix64 streams keyed by (seed, LOD index,
// footprint shape, footprint index): the result does not depend on the
// thread count or on how F grew.
#pragma once

#include "cmfilter/util/error.h"
#include "cmfilter/noise/fractal_noise.h"
#include "cmfilter/noise/noise_sigma_table.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace cmfilter {

enum class FootprintShape { Box, Gaussian };
const char* to_string(FootprintShape shape);

// One footprint's S samples, summarised.
struct FootprintMoments {
    double mean = 0;      // sample mean
    double variance = 0;  // unbiased within-footprint variance (see above)
};

// Footprints first .. first + count - 1 of the stream `stream` (any 64-bit
// key: the bake uses the LOD index and shape), width w, S samples each (for
// the box S is rounded down to the square of an even number, at least 4).
std::vector<FootprintMoments> sample_footprints(const FractalNoise& noise, FootprintShape shape, double width,
                                                int samples_per_footprint, std::uint64_t seed, std::uint64_t stream,
                                                int first, int count, int threads);

struct SigmaEstimate {
    double sigma = 0;                // sqrt(mean within-footprint variance)
    double half_width = 0;           // of sigma's 95% confidence interval
    double mean_variance = 0;        // V
    double variance_half_width = 0;  // 1.96 sd(v) / sqrt(F)
    int footprints = 0;              // F
    int samples_per_footprint = 0;   // S
};

// The estimate and its confidence interval from per-footprint variances.
SigmaEstimate estimate_sigma(const std::vector<FootprintMoments>& footprints, int samples_per_footprint);

struct NoiseSigmaBakeOptions {
    double lod_step = 0.25;                // > 0; docs/bake-noise.md for why 0.25
    double lod_last = 2.0;                 // footprints up to 4 base periods
    double finest_fraction = 1.0 / 16;     // first LOD: 1/16 of the finest octave's period
    int samples_per_footprint = 64;        // S (box: 8 x 8 strata)
    int initial_footprints = 1024;         // F to start with
    int max_footprints = 1 << 16;          // cap on F
    double relative_half_width = 0.005;    // target: CI half-width <= 0.5% of sigma
    int global_samples = 1 << 20;          // independent samples for the global statistics
    std::uint64_t seed = 1;                // sampling seed (the noise has its own)
    int threads = 0;                       // 0: all cores
    std::function<void(double)> progress;  // fraction done, may be empty
};

struct NoiseSigmaBakeRow {
    double lod = 0;
    SigmaEstimate box, gaussian;
};

// Statistics of the noise itself over uniform points of [0, 256 p_0)^2.
struct NoiseGlobalStats {
    int samples = 0;
    double mean = 0, sigma = 0, skewness = 0, excess_kurtosis = 0;
    double variance = 0;
    double variance_half_width = 0;  // 95%: 1.96 sqrt((m4 - m2^2) / N)
};

NoiseGlobalStats measure_global_stats(const FractalNoise& noise, int samples, std::uint64_t seed, int threads);

struct NoiseSigmaBake {
    double lod_first = 0, lod_step = 0.25;
    std::vector<NoiseSigmaBakeRow> rows;
    NoiseGlobalStats global;

    Expected<NoiseSigmaTable> table(FootprintShape shape) const;
};

// The LOD grid: lod_first = log2(finest_fraction p_{N-1} / p_0), nodes
// lod_first + k lod_step up to the first node >= lod_last.
Expected<std::vector<double>> noise_sigma_lods(const FractalNoise& noise, const NoiseSigmaBakeOptions& options);

Expected<NoiseSigmaBake> bake_noise_sigma(const FractalNoise& noise, const NoiseSigmaBakeOptions& options);

}  // namespace cmfilter
