// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/synthesis/sample_analysis.h"

#include "cmfilter/synthesis/candidate_search.h"
#include "cmfilter/synthesis/kmeans.h"
#include "cmfilter/util/stopwatch.h"

#include <Eigen/Dense>

#include <algorithm>

namespace cmfilter {

namespace {

std::string size_text(int width, int height) { return std::to_string(width) + " x " + std::to_string(height); }

// Textons of one level: AnalysisOptions::textons, or 0: min(2000, texels / 4), at least 1.
int level_textons(const AnalysisOptions& options, std::size_t texels)
{
    if (options.textons > 0) return options.textons;
    return static_cast<int>(std::max<std::size_t>(1, std::min<std::size_t>(2000, texels / 4)));
}

}  // namespace

Expected<SampleAnalysis> analyse_sample(const SynthesisSample& sample, const AnalysisOptions& options)
{
    const Stopwatch clock;
    if (sample.levels.empty() || sample.dims < 1 || sample.levels[0].texels() == 0)
        return bad_input("sample '" + sample.path + "' is empty; expected texels to analyse");
    const SampleLevel& coarsest = sample.levels.back();
    const std::string where = sample.path.empty() ? std::string("the sample") : "sample '" + sample.path + "'";
    if (options.textons < 0)
        return bad_input("AnalysisOptions::textons " + std::to_string(options.textons) +
                             " is invalid: expected >= 0 (0: min(2000, texels / 4) per level)",
                         "AnalysisOptions::textons");
    for (std::size_t l = 0; l < sample.levels.size(); ++l) {
        const SampleLevel& level = sample.levels[l];
        if (static_cast<std::size_t>(options.textons) > level.texels())
            return bad_input("AnalysisOptions::textons " + std::to_string(options.textons) + " is more than the " +
                                 std::to_string(level.texels()) + " texels of level " + std::to_string(l) + " of " +
                                 where + " (" + size_text(level.width, level.height) + ")",
                             "AnalysisOptions::textons");
    }
    if (options.candidates < 1 || static_cast<std::size_t>(options.candidates) >= coarsest.texels())
        return bad_input("AnalysisOptions::candidates " + std::to_string(options.candidates) +
                             " is invalid: expected between 1 and " + std::to_string(coarsest.texels() - 1) +
                             " (fewer than the texels of the coarsest level of " + where + ", " +
                             size_text(coarsest.width, coarsest.height) + ")",
                         "AnalysisOptions::candidates");
    if (options.neighbourhood < 1 || 2 * options.neighbourhood + 1 > std::min(coarsest.width, coarsest.height))
        return bad_input(
            "AnalysisOptions::neighbourhood " + std::to_string(options.neighbourhood) +
                " is invalid: expected >= 1 with a (2n + 1)^2 window no larger than the coarsest level of " + where +
                " (" + size_text(coarsest.width, coarsest.height) + ")",
            "AnalysisOptions::neighbourhood");
    if (options.max_iterations < 0)
        return bad_input("AnalysisOptions::max_iterations " + std::to_string(options.max_iterations) +
                             " is invalid: expected >= 0",
                         "AnalysisOptions::max_iterations");

    SampleAnalysis analysis;
    analysis.sample_path = sample.path;
    analysis.sample_hash = sample.hash;
    analysis.sample_kind = sample.kind;
    analysis.sample_images = sample.images;
    analysis.images_used = static_cast<int>(sample.used.size());
    analysis.channels = sample.channels;
    analysis.periodic = sample.periodic;
    analysis.neighbourhood = options.neighbourhood;
    for (std::size_t l = 0; l < sample.levels.size(); ++l) {
        const SampleLevel& level = sample.levels[l];
        // Textons: k-means of the feature vectors (sec. 4.1), each level with
        // its own seed.
        KMeansOptions km;
        km.clusters = level_textons(options, level.texels());
        km.max_iterations = options.max_iterations;
        km.seed = options.seed + l;
        km.threads = options.threads;
        auto clusters = kmeans(level.features.data(), level.texels(), sample.dims, km);
        if (!clusters) return prefixed("level " + std::to_string(l) + " of " + where + ": ", clusters.error());

        LevelAnalysis out;
        out.width = level.width;
        out.height = level.height;
        out.textons = clusters->clusters;
        out.texton.assign(clusters->labels.begin(), clusters->labels.end());
        out.inertia = clusters->inertia;
        // M = V V^T, the appearance vectors' dot products (Tong et al. 2002;
        // sec. 4.1), made exactly symmetric.
        using RowMatrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
        const Eigen::Map<const RowMatrix> v(clusters->centres.data(), out.textons, sample.dims);
        RowMatrix m = v * v.transpose();
        const int k = out.textons;
        out.dot.resize(static_cast<std::size_t>(k) * k);
        for (int i = 0; i < k; ++i)
            for (int j = 0; j < k; ++j) out.dot[static_cast<std::size_t>(i) * k + j] = i <= j ? m(i, j) : m(j, i);

        // The texton distances the candidate search looks up, from M as the
        // paper's dist(p_i, p_j), kept >= 0 (rounding can make a tiny
        // distance negative).
        std::vector<float> distance(static_cast<std::size_t>(k) * k);
        for (int i = 0; i < k; ++i)
            for (int j = 0; j < k; ++j)
                distance[static_cast<std::size_t>(i) * k + j] = std::max(0.0f, out.distance(i, j));
        CandidateSearch search;
        search.width = level.width;
        search.height = level.height;
        search.texton = out.texton.data();
        search.textons = k;
        search.distance = distance.data();
        search.neighbourhood = options.neighbourhood;
        search.candidates = options.candidates;
        search.periodic = sample.periodic;
        search.threads = options.threads;
        out.candidates = options.candidates;
        out.similar = find_candidate_sets(search);
        analysis.levels.push_back(std::move(out));
    }
    analysis.seconds = clock.elapsed_ms() / 1000.0;
    return analysis;
}

}  // namespace cmfilter
