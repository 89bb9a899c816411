// SPDX-License-Identifier: Apache-2.0
// k-coherence synthesis speed at the settings of Bosserhoff & Nicoll's
// table 1 (3 levels; 1.9 s to 13.6 s on a 2.4 GHz Pentium 4): the sample is
// loaded with a 3-level pyramid and analysed once per neighbourhood size
// (timed), each setting synthesised (the fastest of 3), and the time of
// naive tiling at 512 x 512 measured in the same process as the baseline.
// Prints a markdown table with each row's coherence (synthesis_quality.h).
//   cmfilter-bench-synthesis-speed SAMPLE [--threads N]
#include "bench_timing.h"

#include "cmfilter/color/color_config.h"
#include "cmfilter/synthesis/kcoherence_synthesis.h"
#include "cmfilter/synthesis/sample_analysis.h"
#include "cmfilter/synthesis/synthesis_quality.h"
#include "cmfilter/synthesis/synthesis_sample.h"
#include "cmfilter/util/parallel_for.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <vector>

using namespace cmfilter;

namespace {

struct Setting {
    int size, k, neighbourhood;
    double paper_seconds;  // table 1
};

const Setting kTable1[] = {
    {256, 1, 2, 1.9}, {256, 3, 2, 2.7}, {256, 6, 2, 3.7}, {256, 6, 3, 13.6}, {512, 6, 2, 13.4},
};

constexpr int kLevels = 3;
constexpr int kRuns = 3;

}  // namespace

int main(int argc, char** argv)
{
    std::string sample_path;
    int threads = 0;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--threads") == 0 && i + 1 < argc) threads = std::atoi(argv[++i]);
        else if (sample_path.empty() && argv[i][0] != '-') sample_path = argv[i];
        else {
            std::fprintf(stderr, "usage: cmfilter-bench-synthesis-speed SAMPLE [--threads N]\n");
            return 2;
        }
    }
    if (sample_path.empty()) {
        std::fprintf(stderr, "usage: cmfilter-bench-synthesis-speed SAMPLE [--threads N]\n");
        return 2;
    }
    auto config = ColorConfig::load("");
    if (!config) {
        std::fprintf(stderr, "%s\n", config.error().message.c_str());
        return 1;
    }
    SampleOptions sample_options;
    sample_options.path = sample_path;
    sample_options.levels = kLevels;
    sample_options.threads = threads;
    auto sample = load_synthesis_sample(sample_options, *config);
    if (!sample) {
        std::fprintf(stderr, "%s\n", sample.error().message.c_str());
        return 1;
    }
    std::printf("# k-coherence synthesis speed (Bosserhoff & Nicoll table 1)\n\n");
    std::printf("CPU: %s, threads: %d; sample %s: %d x %d, %d images, %d feature dimensions, %d levels\n\n",
                cmfilter_bench::cpu_name().c_str(), resolve_thread_count(threads), sample_path.c_str(), sample->width(),
                sample->height(), sample->images, sample->dims, kLevels);

    // One analysis per neighbourhood size, timed once (the paper: about 10
    // minutes for a 64 x 64 sample of 150 images).
    std::map<int, SampleAnalysis> analyses;
    for (int n : {2, 3}) {
        AnalysisOptions options;
        options.neighbourhood = n;
        options.candidates = 10;
        options.threads = threads;
        Expected<SampleAnalysis> analysis = bad_input("not analysed");
        const double ms = cmfilter_bench::time_ms([&] { analysis = analyse_sample(*sample, options); });
        if (!analysis) {
            std::fprintf(stderr, "%s\n", analysis.error().message.c_str());
            return 1;
        }
        std::printf("analysis, neighbourhood %d: %.2f s (%d textons at level 0)\n", n, ms / 1000,
                    analysis->levels[0].textons);
        analyses.emplace(n, std::move(*analysis));
    }

    // The baseline: naive tiling at 512 x 512.
    CoordinateMap tiled;
    const double tiled_ms = cmfilter_bench::fastest_ms(
        kRuns, [&] { tiled = tiled_coordinate_map(512, 512, sample->width(), sample->height()); });
    QualityOptions tiled_quality;
    tiled_quality.neighbourhood = 2;
    tiled_quality.threads = threads;
    auto tiled_measure = measure_synthesis(tiled, analyses.at(2), tiled_quality);
    if (!tiled_measure) {
        std::fprintf(stderr, "%s\n", tiled_measure.error().message.c_str());
        return 1;
    }

    std::printf("\n| setting | paper s | ours s | speed-up | coherence |\n|---|---:|---:|---:|---:|\n");
    std::printf("| tiling 512x512 (baseline) | - | %.4f | - | %.3f |\n", tiled_ms / 1000, tiled_measure->coherence);
    for (const Setting& s : kTable1) {
        SynthesisOptions options;
        options.width = options.height = s.size;
        options.k = s.k;
        options.neighbourhood = s.neighbourhood;
        options.levels = kLevels;
        options.seed = 1;
        options.threads = threads;
        const SampleAnalysis& analysis = analyses.at(s.neighbourhood);
        Expected<CoordinateMap> map = bad_input("not synthesised");
        const double ms = cmfilter_bench::fastest_ms(kRuns, [&] { map = synthesise(analysis, options); });
        if (!map) {
            std::fprintf(stderr, "%s\n", map.error().message.c_str());
            return 1;
        }
        QualityOptions quality;
        quality.neighbourhood = s.neighbourhood;
        quality.threads = threads;
        auto measured = measure_synthesis(*map, analysis, quality);
        if (!measured) {
            std::fprintf(stderr, "%s\n", measured.error().message.c_str());
            return 1;
        }
        std::printf("| %dx%d k=%d n=%d | %.1f | %.3f | %.1fx | %.3f |\n", s.size, s.size, s.k, s.neighbourhood,
                    s.paper_seconds, ms / 1000, s.paper_seconds / (ms / 1000), measured->coherence);
    }
    return 0;
}
