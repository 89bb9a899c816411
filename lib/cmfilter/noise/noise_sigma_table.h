// SPDX-License-Identifier: Apache-2.0
// The per-LOD standard deviation of a procedural noise (sec. 4.2: "we
// precompute the noise standard deviation for different levels of detail and
// store it in a 1D texture"): sigma(L), the standard deviation a footprint of
// LOD L leaves unresolved inside it, sampled at L_k = lod_first + k lod_step
// and interpolated linearly in L; beyond the ends it holds the end values.
// LOD = log2(footprint width / the noise's base period) (DESIGN.md).
#pragma once

#include "cmfilter/util/error.h"

#include <vector>

namespace cmfilter {

class NoiseSigmaTable {
public:
    NoiseSigmaTable() = default;

    // Checks lod_first finite, lod_step > 0 and finite, at least one sigma,
    // every sigma finite and >= 0; messages name the bad value.
    static Expected<NoiseSigmaTable> create(double lod_first, double lod_step, std::vector<double> sigmas);

    // Linear in LOD between nodes, clamped to the end nodes; NaN gives NaN.
    double sigma_at(double lod) const;

    double lod_first() const { return lod_first_; }
    double lod_step() const { return lod_step_; }
    double lod_last() const { return lod_first_ + lod_step_ * static_cast<double>(sigmas_.size() - 1); }
    const std::vector<double>& sigmas() const { return sigmas_; }

private:
    double lod_first_ = 0, lod_step_ = 1;
    std::vector<double> sigmas_{0.0};
};

}  // namespace cmfilter
