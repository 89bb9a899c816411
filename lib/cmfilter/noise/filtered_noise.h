// SPDX-License-Identifier: Apache-2.0
// A procedural noise filtered over a footprint of width w (sec. 4.2): the two
// parameters of the Gaussian filtering distribution N(mean, sigma^2) that the
// colour-map table T(mean, sigma) is looked up with:
//   mean  = FractalNoise::mean_over_footprint(x, y, w): each octave's
//           least-squares prediction of its footprint mean (fractal_noise.h);
//   sigma = the plugged-in NoiseSigmaTable at LOD log2(w / base period): the
//           standard deviation the footprint leaves unresolved.
#pragma once

#include "cmfilter/noise/fractal_noise.h"
#include "cmfilter/noise/noise_sigma_table.h"

#include <cmath>
#include <limits>
#include <utility>

namespace cmfilter {

class FilteredNoise {
public:
    FilteredNoise(FractalNoise noise, NoiseSigmaTable table)
        : noise_(std::move(noise)), table_(std::move(table)), log2_base_period_(std::log2(noise_.base_period()))
    {
    }

    struct Parameters {
        double mean = 0, sigma = 0;
    };
    // Both parameters with one log2 of the width: what a renderer calls per footprint.
    Parameters filter(double x, double y, double w) const
    {
        if (!(w > 0)) return {noise_(x, y), table_.sigma_at(-std::numeric_limits<double>::infinity())};
        const double log2_w = std::log2(w);
        return {noise_.mean_over_footprint_log2(x, y, log2_w), table_.sigma_at(log2_w - log2_base_period_)};
    }

    double mean_over_footprint(double x, double y, double w) const { return noise_.mean_over_footprint(x, y, w); }
    double unresolved_sigma(double w) const { return table_.sigma_at(lod(w)); }
    // LOD of a footprint of width w: log2(w / base period); -inf for w = 0.
    double lod(double w) const { return std::log2(w / noise_.base_period()); }

    const FractalNoise& noise() const { return noise_; }
    const NoiseSigmaTable& table() const { return table_; }

private:
    FractalNoise noise_;
    NoiseSigmaTable table_;
    double log2_base_period_ = 0;
};

}  // namespace cmfilter
