// SPDX-License-Identifier: Apache-2.0
// cmfilter fit: a linear relighting model (PTM RGB or LRGB, HSH of order 2
// or 3) fitted to every texel of an image stack in one solve, its images
// streamed one at a time (docs/stacks.md), written as cmfilter's float
// EXR, or as a .ptm or .rti that RTI viewers open.
#include "command.h"

#include "cmfilter/stack/fit_file.h"
#include "cmfilter/stack/fit_loading.h"
#include "cmfilter/stack/image_stack.h"
#include "cmfilter/stack/linear_fit.h"
#include "cmfilter/stack/ptm_file.h"
#include "cmfilter/stack/relight_error.h"
#include "cmfilter/stack/rti_file.h"
#include "cmfilter/stack/streamed_fit.h"
#include "cmfilter/util/atomic_output.h"
#include "cmfilter/util/stopwatch.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

namespace cmfilter::cli {

namespace {

struct FitArgs {
    std::string stack;
    std::string model = "ptm-rgb";
    std::string output;
    std::string encoding;  // empty: by the output's format
    std::string colorspace;
    std::string held_out;
    double singular_threshold = 1e-6;
    std::string ocio_config;
    int threads = 0;
    bool no_error = false;
    bool json = false;
    bool quiet = false;
};

nlohmann::json error_json(const RelightError& e)
{
    return {{"lights", e.lights},
            {"rmse", e.rmse},
            {"delta_e_mean", e.delta_e.mean},
            {"delta_e_p95", e.delta_e.p95},
            {"delta_e_max", e.delta_e.max}};
}

void print_error(const char* what, const RelightError& e)
{
    std::cout << "  " << what << " (" << e.lights << " lights): RMSE " << e.rmse << ", CIEDE2000 mean "
              << e.delta_e.mean << ", p95 " << e.delta_e.p95 << ", max " << e.delta_e.max << "\n";
}

Status run(const FitArgs& args)
{
    const FitFileFormat format = fit_file_format(args.output);
    const std::string ext = lowercase_extension(args.output);
    if (ext != ".exr" && ext != ".ptm" && ext != ".rti")
        return bad_input("-o '" + args.output + "': expected a .exr, .ptm or .rti file");
    if (auto st = check_output_path(args.output, ext); !st) return st;
    auto model = parse_linear_model(args.model);
    if (!model)
        return bad_input("--model '" + args.model +
                         "' is not a linear model (expected ptm-rgb, ptm-lrgb, hsh2 or hsh3)");
    const bool ptm = *model == LinearModel::PtmRgb || *model == LinearModel::PtmLrgb;
    if (format == FitFileFormat::Ptm && !ptm)
        return bad_input("--model " + args.model + " cannot be written as a .ptm (expected ptm-rgb or ptm-lrgb; " +
                         "HSH fits go to .rti)");
    if (format == FitFileFormat::Rti && ptm)
        return bad_input("--model " + args.model + " cannot be written as a .rti (expected hsh2 or hsh3; " +
                         "PTM fits go to .ptm)");
    StackEncoding encoding = format == FitFileFormat::Exr ? StackEncoding::SceneLinear : StackEncoding::DisplayEncoded;
    if (args.encoding == "display") encoding = StackEncoding::DisplayEncoded;
    else if (args.encoding == "linear") {
        if (format != FitFileFormat::Exr)
            return bad_input("--encoding linear cannot be written to '" + args.output +
                             "': .ptm and .rti hold display-encoded 8-bit values (expected --encoding display "
                             "or an .exr output)");
        encoding = StackEncoding::SceneLinear;
    } else if (!args.encoding.empty())
        return bad_input("--encoding '" + args.encoding + "' is invalid (expected linear or display)");

    auto config = load_color_config(args.ocio_config);
    if (!config) return config.error();

    // The stack streamed: its images read and added to the fit one at a
    // time (streamed_fit.h), never all held.
    Stopwatch clock;
    StackLoadOptions load;
    load.light_file = args.stack;
    load.colorspace = args.colorspace;
    load.encoding = encoding;
    load.threads = args.threads;
    LinearFitOptions options;
    options.model = *model;
    options.singular_threshold = args.singular_threshold;
    options.threads = args.threads;
    auto fit = fit_linear_from_files(load, options, *config);
    if (!fit) return fit.error();
    const double fit_seconds = clock.elapsed_ms() / 1000;

    // The fit is written to a temporary file beside the output, measured
    // from that file (so the error includes the .ptm's or .rti's
    // quantisation), and moved into place only when every step succeeded:
    // a bad held-out stack leaves no output.
    auto staged = AtomicOutput::begin(args.output);
    if (!staged) return staged.error();
    const std::string written_path = staged->temp_path();
    PtmQuantisation quantisation;
    RtiQuantisation rti_quantisation;
    FitFileInfo info;
    info.source = args.stack;
    Status written = ok();
    if (format == FitFileFormat::Ptm) written = write_ptm(written_path, *fit, &quantisation);
    else if (format == FitFileFormat::Rti) written = write_rti(written_path, *fit, &rti_quantisation);
    else written = write_fit_exr(written_path, *fit, info);
    if (!written) return written;
    const double total_seconds = clock.elapsed_ms() / 1000;
    const auto bytes = std::filesystem::file_size(written_path);

    // The written file's own relighting error: at the training lights, and
    // at the held-out lights when given.
    std::optional<RelightError> training, held;
    auto stored = load_fit(written_path);
    if (!stored) return prefixed("reading back '" + args.output + "': ", stored.error());
    if (!args.no_error) {
        auto e = relight_error_from_files(*stored, load, *config, args.threads);
        if (!e) return e.error();
        training = *e;
    }
    if (!args.held_out.empty()) {
        StackLoadOptions h = load;
        h.light_file = args.held_out;
        auto e = relight_error_from_files(*stored, h, *config, args.threads);
        if (!e) return e.error();
        held = *e;
    }
    if (auto st = staged->commit(); !st) return st;

    const LightSetConditioning& cond = fit->conditioning;
    if (args.json) {
        nlohmann::json j;
        j["output"] = args.output;
        j["format"] = to_string(format);
        j["model"] = to_string(*model);
        j["size"] = {fit->width, fit->height};
        j["channels"] = fit->channels;
        j["lights"] = cond.lights;
        j["encoding"] = to_string(encoding);
        j["bytes"] = bytes;
        // "fit": the streamed pass that reads the images and fits them.
        j["seconds"] = {{"fit", fit_seconds}, {"total", total_seconds}};
        j["conditioning"] = {{"condition_number", cond.condition_number},
                             {"largest_singular", cond.largest_singular},
                             {"smallest_singular", cond.smallest_singular},
                             {"clamped", cond.clamped}};
        if (format == FitFileFormat::Ptm) j["quantisation_max_value_error"] = quantisation.max_value_error;
        if (format == FitFileFormat::Rti) j["quantisation_max_value_error"] = rti_quantisation.max_value_error;
        if (training) j["training_error"] = error_json(*training);
        if (held) j["held_out_error"] = error_json(*held);
        std::cout << j.dump(2) << "\n";
    } else if (!args.quiet) {
        std::cout << "wrote " << args.output << ": " << to_string(*model) << " fit, " << fit->width << " x "
                  << fit->height << ", " << fit->channels << " channels, " << bytes << " bytes\n"
                  << "  " << cond.lights << " lights, condition number " << cond.condition_number
                  << (cond.clamped ? " (" + std::to_string(cond.clamped) + " singular values clamped)" : "") << "\n"
                  << "  values " << to_string(encoding) << "\n"
                  << "  read and fit " << fit_seconds << " s, total " << total_seconds << " s\n";
        if (format == FitFileFormat::Ptm || format == FitFileFormat::Rti)
            std::cout << "  quantisation: relit values within "
                      << (format == FitFileFormat::Ptm ? quantisation.max_value_error
                                                       : rti_quantisation.max_value_error) *
                             255
                      << " display codes of the unquantised fit\n";
        if (training) print_error("training lights", *training);
        if (held) print_error("held-out lights", *held);
    }
    return ok();
}

}  // namespace

Command setup_fit(CLI::App& parent)
{
    auto args = std::make_shared<FitArgs>();
    CLI::App* app = parent.add_subcommand(
        "fit", "Fit a linear relighting model (PTM or HSH) to every texel of an image stack (docs/stacks.md)");
    app->add_option("STACK", args->stack, "The stack's light file (.lp), its images beside it")->required();
    app->add_option("--model", args->model, "ptm-rgb, ptm-lrgb, hsh2 or hsh3")->capture_default_str();
    app->add_option("-o,--output", args->output, "Fit to write: .exr (float), .ptm (PTM 1.2) or .rti (HSH)")
        ->required();
    app->add_option("--encoding", args->encoding,
                    "Values to fit: linear (scene-linear) or display (sRGB codes); default linear for .exr, "
                    "display for .ptm and .rti (which hold display-encoded 8-bit values)");
    app->add_option("--colorspace", args->colorspace,
                    "Colour space of the stack's integer images (default: each file's metadata, else sRGB)");
    app->add_option("--held-out", args->held_out,
                    "A stack of further lights (.lp) to report the fit's error at, such as make-stack renders");
    app->add_flag("--no-error", args->no_error,
                  "Skip the error at the training lights (relighting every light costs several times the fit)");
    app->add_option("--singular-threshold", args->singular_threshold,
                    "Singular values of the light matrix below this fraction of the largest are taken as zero")
        ->capture_default_str();
    app->add_option("--ocio-config", args->ocio_config, "OpenColorIO config (default: $OCIO, else built in)");
    app->add_option("--threads", args->threads, "Threads (0: all cores)")->capture_default_str();
    app->add_flag("--json", args->json, "Print a machine-readable summary on stdout");
    app->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
    return {app,
            [args] { return run(*args); },
            {{"LinearFitOptions::singular_threshold", "--singular-threshold"},
             {"LinearFitOptions::model", "--model"},
             {"StackLoadOptions::colorspace", "--colorspace"},
             {"StackLoadOptions::encoding", "--encoding"}}};
}

}  // namespace cmfilter::cli
