// SPDX-License-Identifier: Apache-2.0
// cmfilter synth: k-coherence synthesis of a large surface from a sample
// (one level or hierarchical), written as a coordinate map into the sample
// (docs/synthesis.md). The sample's analysis is read from --analysis when
// that file exists (checked against the sample's hash), else made and,
// with --analysis, kept there for the next synthesis.
#include "command.h"

#include "cmfilter/io/recorded_path.h"
#include "cmfilter/io/rgb_image_file.h"
#include "cmfilter/synthesis/analysis_file.h"
#include "cmfilter/synthesis/coordinate_lookup.h"
#include "cmfilter/synthesis/coordinate_map_file.h"
#include "cmfilter/synthesis/kcoherence_synthesis.h"
#include "cmfilter/synthesis/synthesis_quality.h"
#include "cmfilter/synthesis/synthesis_sample.h"
#include "cmfilter/synthesis/synthesis_source.h"
#include "cmfilter/util/atomic_output.h"
#include "cmfilter/util/stopwatch.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <iostream>
#include <memory>

namespace cmfilter::cli {

namespace {

struct SynthArgs {
    std::string sample;
    std::string output;
    std::string analysis_path;
    std::string size = "256x256";
    int k = 3;
    int synthesis_neighbourhood = 0;  // 0: the analysis's
    bool toroidal = false;
    std::string preview;
    bool quality = false;
    SampleAnalysisArgs analysis;
    std::string ocio_config;
    int threads = 0;
    bool json = false;
    bool quiet = false;
};

nlohmann::json quality_json(const SynthesisQuality& q)
{
    return {{"coherence", q.coherence},
            {"coverage", q.coverage},
            {"uniform_coverage", q.uniform_coverage},
            {"seam_share", q.seam_share},
            {"seam_contrast", q.seam_contrast}};
}

// The analysis: read from `path` when it exists (and made from this
// sample), else made (and written to `path` when one is named).
Expected<SampleAnalysis> obtain_analysis(const SynthArgs& args, const CLI::App& app, const ColorConfig& config,
                                         bool& reused)
{
    reused = false;
    if (!args.analysis_path.empty() && std::filesystem::exists(args.analysis_path)) {
        const auto given = given_sample_analysis_options(app);
        for (const std::string& flag : given)
            if (flag != "--seed" && flag != "--colorspace" && flag != "--levels")
                return bad_input(flag + " sets how an analysis is made, but the analysis '" + args.analysis_path +
                                 "' exists and is reused as it was made (remove the file to analyse again)");
        auto analysis = read_analysis_exr(args.analysis_path);
        if (!analysis) return analysis.error();
        auto files = sample_image_files(args.sample);
        if (!files) return files.error();
        auto hash = sample_content_hash(*files);
        if (!hash) return hash.error();
        if (*hash != analysis->sample_hash)
            return bad_input("the analysis '" + args.analysis_path + "' was made from another sample ('" +
                             analysis->sample_path + "', hash " + analysis->sample_hash.substr(0, 16) + "...), not '" +
                             args.sample + "' (hash " + hash->substr(0, 16) + "...)");
        reused = true;
        return analysis;
    }
    SampleAnalysisArgs analysis_args = args.analysis;
    if (!app.count("--neighbourhood") && args.synthesis_neighbourhood > 0)
        analysis_args.neighbourhood = args.synthesis_neighbourhood;
    auto analysis = analyse_sample_from_args(args.sample, analysis_args, config, args.threads);
    if (!analysis) return analysis.error();
    if (!args.analysis_path.empty())
        if (auto st = write_analysis_exr(args.analysis_path, *analysis); !st) return st.error();
    return analysis;
}

Status run(const SynthArgs& args, const CLI::App& app)
{
    if (lowercase_extension(args.output) != ".exr")
        return bad_input("-o '" + args.output + "': a coordinate map is written as OpenEXR (.exr)");
    if (!args.analysis_path.empty() && lowercase_extension(args.analysis_path) != ".exr")
        return bad_input("--analysis '" + args.analysis_path + "': an analysis is an OpenEXR file (.exr)");
    if (!args.preview.empty())
        if (auto st = check_rgb_image_output(args.preview); !st) return st;
    auto size = parse_size("--size", args.size);
    if (!size) return size.error();
    auto config = load_color_config(args.ocio_config);
    if (!config) return config.error();

    Stopwatch clock;
    bool reused = false;
    auto analysis = obtain_analysis(args, app, *config, reused);
    if (!analysis) return analysis.error();
    const double analysis_seconds = clock.elapsed_ms() / 1000;

    SynthesisOptions options;
    options.width = size->first;
    options.height = size->second;
    options.k = args.k;
    options.neighbourhood = args.synthesis_neighbourhood > 0 ? args.synthesis_neighbourhood : analysis->neighbourhood;
    // The levels synthesised: --levels, else every level of a reused analysis.
    options.levels = reused && !app.count("--levels") ? static_cast<int>(analysis->levels.size())
                                                      : args.analysis.levels;
    options.toroidal = args.toroidal;
    options.seed = args.analysis.seed;
    options.threads = args.threads;
    auto map = synthesise(*analysis, options);
    if (!map) return map.error();

    std::optional<SynthesisQuality> quality, tiled;
    if (args.quality) {
        QualityOptions q;
        q.neighbourhood = options.neighbourhood;
        q.threads = args.threads;
        auto measured = measure_synthesis(*map, *analysis, q);
        if (!measured) return measured.error();
        auto baseline = measure_synthesis(
            tiled_coordinate_map(options.width, options.height, analysis->width(), analysis->height()), *analysis, q);
        if (!baseline) return baseline.error();
        quality = *measured;
        tiled = *baseline;
    }
    // The preview first: a failed preview leaves no coordinate map.
    if (!args.preview.empty()) {
        SourceOptions source;
        source.path = args.sample;
        source.colorspace = args.analysis.colorspace;
        source.periodic = analysis->periodic;
        source.threads = args.threads;
        auto image = load_source_image(source, *config);
        if (!image) return image.error();
        auto out = render_through_map(*map, image->image, args.threads);
        if (!out) return out.error();
        ImageAttributes attributes;
        attributes.text = {{"cmfilter:kind", "synthesised-image"},
                           {"cmfilter:coordinate_map", path_for_record(args.output, args.preview)}};
        if (auto st = write_output_image(args.preview, out->width, out->height, out->channels, std::move(out->pixels),
                                         image->colorspace, attributes, *config);
            !st)
            return st;
    }
    if (auto st = write_coordinate_map_exr(args.output, *map); !st) return st;

    if (args.json) {
        nlohmann::json j;
        j["output"] = args.output;
        j["sample"] = args.sample;
        j["sample_hash"] = analysis->sample_hash;
        j["size"] = {options.width, options.height};
        j["k"] = options.k;
        j["neighbourhood"] = options.neighbourhood;
        j["levels"] = options.levels;
        j["toroidal"] = options.toroidal;
        j["seed"] = options.seed;
        j["analysis"] = args.analysis_path.empty() ? nlohmann::json() : nlohmann::json(args.analysis_path);
        j["analysis_reused"] = reused;
        j["analysis_seconds"] = reused ? 0.0 : analysis->seconds;
        j["analysis_read_seconds"] = reused ? analysis_seconds : 0.0;
        j["synthesis_seconds"] = map->info.seconds;
        if (quality) {
            j["quality"] = quality_json(*quality);
            j["tiled_quality"] = quality_json(*tiled);
        }
        if (!args.preview.empty()) j["preview"] = args.preview;
        print_json("synth", std::move(j));
    } else if (!args.quiet) {
        std::cout << "wrote " << args.output << ": " << options.width << " x " << options.height << " from "
                  << args.sample << " (" << analysis->width() << " x " << analysis->height() << "), k " << options.k
                  << ", neighbourhood " << options.neighbourhood << ", " << options.levels << " level(s)"
                  << (options.toroidal ? ", toroidal" : "") << "; synthesis " << map->info.seconds << " s, analysis "
                  << (reused ? "reused from " + args.analysis_path : std::to_string(analysis->seconds) + " s") << "\n";
        if (quality)
            std::cout << "  coherence " << quality->coherence << " (tiling " << tiled->coherence << "), coverage "
                      << quality->coverage << " (tiling " << tiled->coverage << "), seams " << quality->seam_share
                      << " of pairs at contrast " << quality->seam_contrast << " (tiling " << tiled->seam_share
                      << " at " << tiled->seam_contrast << ")\n";
    }
    return ok();
}

}  // namespace

Command setup_synth(CLI::App& parent)
{
    auto args = std::make_shared<SynthArgs>();
    CLI::App* app = parent.add_subcommand(
        "synth", "Synthesise a large surface from a sample by k-coherence synthesis, as a coordinate map "
                 "(docs/synthesis.md)");
    app->add_option("SAMPLE", args->sample, "An image, an image stack (.lp) or a BTF manifest (.json)")->required();
    app->add_option("-o,--output", args->output, "The coordinate map to write (.exr)")->required();
    app->add_option("--analysis", args->analysis_path,
                    "The sample's analysis (.exr): read when it exists (made from this sample), else made and kept "
                    "there");
    app->add_option("--size", args->size, "Output size WxH")->capture_default_str();
    app->add_option("-k", args->k, "k: candidates per neighbour (1: Ashikhmin's coherence alone)")
        ->capture_default_str();
    app->add_option("--synthesis-neighbourhood", args->synthesis_neighbourhood,
                    "n of the (2n + 1) x (2n + 1) window synthesis matches (0: the analysis's --neighbourhood)")
        ->capture_default_str();
    app->add_flag("--toroidal", args->toroidal, "Make the output tile seamlessly");
    app->add_option("--preview", args->preview,
                    "Also write the sample's first image through the map (.exr scene-linear, .png/.jpg sRGB)");
    app->add_flag("--quality", args->quality,
                  "Measure coherence, coverage and seams, and the same for naive tiling of the sample");
    add_sample_analysis_options(*app, args->analysis);
    app->add_option("--ocio-config,--colorconfig", args->ocio_config,
                    "OpenColorIO config (default: $OCIO, else built in)");
    app->add_option("--threads", args->threads, "Threads (0: all cores; the result is the same for any)")
        ->capture_default_str();
    app->add_flag("--json", args->json, "Print a machine-readable summary on stdout");
    app->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
    FieldFlags flags = sample_analysis_flags();
    flags.insert(flags.end(), {{"SynthesisOptions::width", "--size"},
                               {"SynthesisOptions::height", "--size"},
                               {"SynthesisOptions::k", "-k"},
                               {"SynthesisOptions::neighbourhood", "--synthesis-neighbourhood"},
                               {"SynthesisOptions::levels", "--levels"},
                               {"SourceOptions::colorspace", "--colorspace"}});
    return {app, [args, app] { return run(*args, *app); }, flags};
}

}  // namespace cmfilter::cli
