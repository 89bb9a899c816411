// SPDX-License-Identifier: Apache-2.0
// The analysis options synth-analyse and synth share.
#include "command.h"

#include "cmfilter/synthesis/synthesis_sample.h"

namespace cmfilter::cli {

namespace {
const char* const kAnalysisFlags[] = {"--levels", "--textons",  "--candidates", "--neighbourhood",
                                      "--select", "--periodic", "--seed",       "--colorspace"};
}

void add_sample_analysis_options(CLI::App& app, SampleAnalysisArgs& args)
{
    app.add_option(
           "--levels", args.levels,
           "Pyramid levels analysed and synthesised (synth reusing an analysis: all of its levels unless given)")
        ->capture_default_str();
    app.add_option("--textons", args.textons,
                   "k-means textons per level (0: min(2000, texels / 4), as the paper's 1000-2000 for 64 x 64)")
        ->capture_default_str();
    app.add_option("--candidates", args.candidates,
                   "Most similar texels kept per texel (m): synthesis may use k up to m + 1")
        ->capture_default_str();
    app.add_option("--neighbourhood", args.neighbourhood,
                   "n of the (2n + 1) x (2n + 1) neighbourhoods compared for the candidate sets")
        ->capture_default_str();
    app.add_option("--select", args.select_images,
                   "Representative images kept for the features (0: all; the paper keeps about 150)")
        ->capture_default_str();
    app.add_flag(
        "--periodic", args.periodic,
        "The sample tiles (a synthetic tile): neighbourhoods and copies wrap around its edges (synthesis then reproduces a tiling; docs/synthesis.md)");
    app.add_option("--seed", args.seed, "Seed of the k-means start (and, for synth, of the synthesis)")
        ->capture_default_str();
    app.add_option("--colorspace", args.colorspace,
                   "Colour space of the sample's integer images (default: their metadata, else sRGB)");
}

FieldFlags sample_analysis_flags()
{
    return {{"SampleOptions::levels", "--levels"},
            {"SampleOptions::select_images", "--select"},
            {"SampleOptions::colorspace", "--colorspace"},
            {"StackLoadOptions::colorspace", "--colorspace"},
            {"AnalysisOptions::textons", "--textons"},
            {"AnalysisOptions::candidates", "--candidates"},
            {"AnalysisOptions::neighbourhood", "--neighbourhood"},
            {"AnalysisOptions::seed", "--seed"}};
}

std::vector<std::string> given_sample_analysis_options(const CLI::App& app)
{
    std::vector<std::string> given;
    for (const char* flag : kAnalysisFlags)
        if (app.count(flag)) given.emplace_back(flag);
    return given;
}

Expected<SampleAnalysis> analyse_sample_from_args(const std::string& path, const SampleAnalysisArgs& args,
                                                  const ColorConfig& config, int threads)
{
    SampleOptions load;
    load.path = path;
    load.colorspace = args.colorspace;
    load.select_images = args.select_images;
    load.levels = args.levels;
    load.periodic = args.periodic;
    load.threads = threads;
    auto sample = load_synthesis_sample(load, config);
    if (!sample) return sample.error();
    AnalysisOptions options;
    options.textons = args.textons;
    options.candidates = args.candidates;
    options.neighbourhood = args.neighbourhood;
    options.seed = args.seed;
    options.threads = threads;
    return analyse_sample(*sample, options);
}

}  // namespace cmfilter::cli
