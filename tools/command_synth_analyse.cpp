// SPDX-License-Identifier: Apache-2.0
// cmfilter synth-analyse: a sample's analysis for synthesis (textons, their
// dot products, candidate sets, per pyramid level; docs/synthesis.md),
// written once and reused by every `synth` of that sample.
#include "command.h"

#include "cmfilter/synthesis/analysis_file.h"
#include "cmfilter/synthesis/sample_analysis.h"
#include "cmfilter/synthesis/synthesis_sample.h"
#include "cmfilter/util/atomic_output.h"
#include "cmfilter/util/stopwatch.h"

#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>

namespace cmfilter::cli {

namespace {

struct SynthAnalyseArgs {
    std::string sample;
    std::string output;
    SampleAnalysisArgs analysis;
    std::string ocio_config;
    int threads = 0;
    bool json = false;
    bool quiet = false;
};

Status run(const SynthAnalyseArgs& args)
{
    if (lowercase_extension(args.output) != ".exr")
        return bad_input("-o '" + args.output + "': an analysis is written as OpenEXR (.exr)");
    auto config = load_color_config(args.ocio_config);
    if (!config) return config.error();
    Stopwatch clock;
    auto analysis = analyse_sample_from_args(args.sample, args.analysis, *config, args.threads);
    if (!analysis) return analysis.error();
    if (auto st = write_analysis_exr(args.output, *analysis); !st) return st;
    const double seconds = clock.elapsed_ms() / 1000;
    if (args.json) {
        nlohmann::json j;
        j["output"] = args.output;
        j["sample"] = args.sample;
        j["sample_hash"] = analysis->sample_hash;
        j["images"] = analysis->sample_images;
        j["images_used"] = analysis->images_used;
        j["seconds"] = seconds;
        j["analysis_seconds"] = analysis->seconds;
        for (const LevelAnalysis& level : analysis->levels)
            j["levels"].push_back({{"size", {level.width, level.height}},
                                   {"textons", level.textons},
                                   {"candidates", level.candidates},
                                   {"inertia", level.inertia}});
        print_json("synth-analyse", std::move(j));
    } else if (!args.quiet) {
        std::cout << "wrote " << args.output << ": " << analysis->levels.size() << " level(s) of " << args.sample
                  << " (" << analysis->images_used << " of " << analysis->sample_images << " images), "
                  << analysis->levels[0].textons << " textons at " << analysis->levels[0].width << " x "
                  << analysis->levels[0].height << ", " << seconds << " s\n";
    }
    return ok();
}

}  // namespace

Command setup_synth_analyse(CLI::App& parent)
{
    auto args = std::make_shared<SynthAnalyseArgs>();
    CLI::App* app = parent.add_subcommand(
        "synth-analyse",
        "Analyse a sample for synthesis: textons, dot products and candidate sets per level (docs/synthesis.md)");
    app->add_option("SAMPLE", args->sample, "An image, an image stack (.lp) or a BTF manifest (.json)")->required();
    app->add_option("-o,--output", args->output, "The analysis to write (.exr)")->required();
    add_sample_analysis_options(*app, args->analysis);
    app->add_option("--ocio-config,--colorconfig", args->ocio_config,
                    "OpenColorIO config (default: $OCIO, else built in)");
    app->add_option("--threads", args->threads, "Threads (0: all cores)")->capture_default_str();
    app->add_flag("--json", args->json, "Print a machine-readable summary on stdout");
    app->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
    return {app, [args] { return run(*args); }, sample_analysis_flags()};
}

}  // namespace cmfilter::cli
