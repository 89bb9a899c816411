// SPDX-License-Identifier: Apache-2.0
// The analysis of a synthesis sample (sec. 4.1 and the candidate sets of
// sec. 4.2, Tong et al. 2002), made once and reused by every synthesis of
// that sample: per pyramid level, each texel's texton (k-means cluster of
// the feature vectors), the textons' dot-product matrix M, so that the
// squared distance of two texels is t_i.t_i - 2 t_i.t_j + t_j.t_j (the
// paper's dist(p_i, p_j)), and per texel the m texels of most similar
// (2n + 1)^2 neighbourhoods (itself excluded), nearest first.
#pragma once

#include "cmfilter/synthesis/synthesis_sample.h"
#include "cmfilter/util/error.h"

#include <cstdint>
#include <string>
#include <vector>

namespace cmfilter {

struct LevelAnalysis {
    int width = 0, height = 0;
    int textons = 0;
    std::vector<std::int32_t> texton;   // width * height texton indices
    std::vector<float> dot;             // textons * textons, M[i * textons + j] = v_i . v_j
    int candidates = 0;                 // m
    std::vector<std::int32_t> similar;  // width * height * m texel indices (y * width + x), nearest first
    double inertia = 0;                 // the k-means inertia (squared feature distance, summed)
    std::size_t texels() const { return static_cast<std::size_t>(width) * height; }
    // ||v_a - v_b||^2 from M.
    float distance(std::int32_t a, std::int32_t b) const
    {
        return dot[static_cast<std::size_t>(a) * textons + a] - 2 * dot[static_cast<std::size_t>(a) * textons + b] +
               dot[static_cast<std::size_t>(b) * textons + b];
    }
};

struct SampleAnalysis {
    std::string sample_path;
    std::string sample_hash;
    SampleKind sample_kind = SampleKind::Image;
    int sample_images = 0, images_used = 0, channels = 0;
    bool periodic = false;
    int neighbourhood = 2;              // n of the candidate sets' (2n + 1)^2 neighbourhoods
    std::vector<LevelAnalysis> levels;  // levels[0] full resolution
    double seconds = 0;                 // time the analysis took
    int width() const { return levels.empty() ? 0 : levels[0].width; }
    int height() const { return levels.empty() ? 0 : levels[0].height; }
};

struct AnalysisOptions {
    // Textons per level: 0 picks min(2000, texels / 4) (at least 1) for each
    // level; more than a level's texels is refused.
    int textons = 0;
    int candidates = 10;    // m, >= 1 and < the coarsest level's texels
    int neighbourhood = 2;  // n >= 1; (2n + 1) may not exceed the coarsest level's width or height
    int max_iterations = 30;
    std::uint64_t seed = 1;
    int threads = 0;
};

// BadInput naming the field and value: AnalysisOptions::textons more than a
// level's texels (naming both), AnalysisOptions::candidates < 1 or too many,
// AnalysisOptions::neighbourhood < 1 or larger than the sample allows
// (naming the sample's size), an empty sample.
Expected<SampleAnalysis> analyse_sample(const SynthesisSample& sample, const AnalysisOptions& options);

}  // namespace cmfilter
