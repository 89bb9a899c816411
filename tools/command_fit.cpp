// SPDX-License-Identifier: Apache-2.0
// cmfilter fit: a linear relighting model (PTM RGB or LRGB, HSH of order 2
// or 3) fitted to every texel of an image stack in one solve, its images
// streamed one at a time (docs/stacks.md), written as cmfilter's float
// EXR, or as a .ptm or .rti that RTI viewers open; or per-texel Lafortune
// lobes (--model lafortune, lafortune-rgb) fitted to the stack held in
// memory, written as cmfilter's float EXR.
#include "command.h"

#include "cmfilter/stack/fit_file.h"
#include "cmfilter/stack/fit_loading.h"
#include "cmfilter/stack/image_stack.h"
#include "cmfilter/stack/lafortune_error.h"
#include "cmfilter/stack/lafortune_file.h"
#include "cmfilter/stack/lafortune_fit.h"
#include "cmfilter/stack/linear_fit.h"
#include "cmfilter/stack/ptm_file.h"
#include "cmfilter/stack/relight_error.h"
#include "cmfilter/stack/rti_file.h"
#include "cmfilter/stack/stack_fit.h"
#include "cmfilter/stack/streamed_fit.h"
#include "cmfilter/util/atomic_output.h"
#include "cmfilter/util/stopwatch.h"

#include <nlohmann/json.hpp>

#include <algorithm>
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
    // Lafortune lobes (LafortuneFitOptions).
    std::string lobes = "2";  // N or "auto"
    int max_lobes = 0;        // auto: the most (0: as many as the lights determine)
    double tolerance = LafortuneFitOptions{}.tolerance;
    double min_gain = LafortuneFitOptions{}.min_gain;
    std::string view;
    int slot = 0;
    int max_iterations = LafortuneFitOptions{}.max_iterations;
    double function_tolerance = LafortuneFitOptions{}.function_tolerance;
    double spacing_cap = LafortuneFitOptions{}.spacing_cap;
    double exponent_penalty = LafortuneFitOptions{}.exponent_penalty;
    double density_radius = LafortuneFitOptions{}.density_radius;
    double relative_epsilon = LafortuneFitOptions{}.relative_epsilon;
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

// The options only one kind of model takes, refused with the other.
constexpr const char* kLafortuneOnly[] = {
    "--lobes",           "--max-lobes",          "--tolerance",   "--min-gain",         "--view",
    "--max-iterations",  "--function-tolerance", "--spacing-cap", "--exponent-penalty", "--density-radius",
    "--relative-epsilon"};
constexpr const char* kLinearOnly[] = {"--singular-threshold"};

Status run_lafortune(const FitArgs& args, const CLI::App& app, LafortuneVariant variant);

Status run(const FitArgs& args, const CLI::App& app)
{
    const FitFileFormat format = fit_file_format(args.output);
    const std::string ext = lowercase_extension(args.output);
    if (ext != ".exr" && ext != ".ptm" && ext != ".rti")
        return bad_input("-o '" + args.output + "': expected a .exr, .ptm or .rti file");
    if (auto st = check_output_path(args.output, ext); !st) return st;
    if (args.model == "lafortune" || args.model == "lafortune-rgb")
        return run_lafortune(args, app,
                             args.model == "lafortune" ? LafortuneVariant::Luminance : LafortuneVariant::Rgb);
    auto model = parse_linear_model(args.model);
    if (!model)
        return bad_input(
            "--model '" + args.model +
            "' is not a model cmfilter fits (expected ptm-rgb, ptm-lrgb, hsh2, hsh3, lafortune or lafortune-rgb)");
    for (const char* flag : kLafortuneOnly)
        if (app.count(flag))
            return bad_input(std::string(flag) + " is an option of the Lafortune models (--model lafortune or " +
                             "lafortune-rgb), not of " + args.model);
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

    auto slot = resolve_stack_slot(args.stack, app.count("--slot") ? std::optional<int>(args.slot) : std::nullopt);
    if (!slot) return slot.error();

    // The stack streamed: its images read and added to the fit one at a
    // time (streamed_fit.h), never all held.
    Stopwatch clock;
    StackLoadOptions load;
    load.light_file = slot->light_file;
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
    info.source = slot->light_file;
    Status written = ok();
    if (format == FitFileFormat::Ptm) written = write_ptm(written_path, *fit, &quantisation);
    else if (format == FitFileFormat::Rti) written = write_rti(written_path, *fit, &rti_quantisation);
    else written = write_fit_exr(written_path, *fit, info);
    if (!written) return written;
    const double total_seconds = clock.elapsed_ms() / 1000;
    const auto bytes = std::filesystem::file_size(written_path);

    // The written file's own relighting error: at the training lights, and
    // at the held-out lights when given.
    // A .ptm or .rti is read back, so its quantisation is measured; the EXR
    // holds the fit's floats exactly. Nothing is read back when nothing is
    // measured.
    std::optional<RelightError> training, held;
    std::optional<LinearFit> quantised;
    if (format != FitFileFormat::Exr && (!args.no_error || !args.held_out.empty())) {
        auto stored = load_fit(written_path);
        if (!stored) return prefixed("reading back '" + args.output + "': ", stored.error());
        quantised = std::move(*stored);
    }
    const LinearFit& measured = quantised ? *quantised : *fit;
    if (!args.no_error) {
        auto e = relight_error_from_files(measured, load, *config, args.threads);
        if (!e) return e.error();
        training = *e;
    }
    if (!args.held_out.empty()) {
        StackLoadOptions h = load;
        h.light_file = args.held_out;
        auto e = relight_error_from_files(measured, h, *config, args.threads);
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
        print_json("fit", std::move(j));
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

// --lobes: a count, or "auto" (-1).
constexpr int kAutoLobes = -1;
Expected<int> parse_lobes(const std::string& text)
{
    if (text == "auto") return kAutoLobes;
    if (text.empty() || text.size() > 3 || text.find_first_not_of("0123456789") != std::string::npos)
        return bad_input("--lobes '" + text + "' is invalid (expected a lobe count or auto)");
    return std::stoi(text);
}

std::string histogram_text(const std::vector<long long>& histogram)
{
    std::string text;
    for (std::size_t n = 0; n < histogram.size(); ++n)
        text += (n ? ", " : "") + std::to_string(n) + ": " + std::to_string(histogram[n]);
    return text;
}

// Lafortune lobes (lafortune_fit.h): the stack loaded whole (the fit
// refines every texel against all its lights), fitted, written to a
// temporary file, measured from that file and moved into place last.
Status run_lafortune(const FitArgs& args, const CLI::App& app, LafortuneVariant variant)
{
    const std::string ext = lowercase_extension(args.output);
    if (ext != ".exr")
        return bad_input("--model " + args.model + " cannot be written as a " + ext +
                         ": Lafortune lobes go to an .exr (a .ptm holds PTMs, a .rti HSH)");
    for (const char* flag : kLinearOnly)
        if (app.count(flag))
            return bad_input(std::string(flag) + " is an option of the linear models, not of " + args.model);
    StackEncoding encoding = StackEncoding::SceneLinear;
    if (args.encoding == "display") encoding = StackEncoding::DisplayEncoded;
    else if (!args.encoding.empty() && args.encoding != "linear")
        return bad_input("--encoding '" + args.encoding + "' is invalid (expected linear or display)");
    auto lobes = parse_lobes(args.lobes);
    if (!lobes) return lobes.error();
    const bool auto_lobes = *lobes == kAutoLobes;
    if (!auto_lobes)
        for (const char* flag : {"--max-lobes", "--tolerance", "--min-gain"})
            if (app.count(flag))
                return bad_input(std::string(flag) + " chooses the lobe count per texel: it needs --lobes auto");

    auto slot = resolve_stack_slot(args.stack, app.count("--slot") ? std::optional<int>(args.slot) : std::nullopt);
    if (!slot) return slot.error();
    Vec3 view{0, 0, 1};
    if (slot->view) {
        if (!args.view.empty())
            return bad_input("--view cannot be given with the BTF manifest '" + args.stack +
                             "': its view slot's direction is the fit's view (pick the slot with --slot K)");
        view = *slot->view;
    } else if (!args.view.empty()) {
        auto parsed = parse_direction("--view", args.view);
        if (!parsed) return parsed.error();
        view = *parsed;
    }

    auto config = load_color_config(args.ocio_config);
    if (!config) return config.error();
    Stopwatch clock;
    StackLoadOptions load;
    load.light_file = slot->light_file;
    load.colorspace = args.colorspace;
    load.encoding = encoding;
    load.threads = args.threads;
    auto stack = load_image_stack(load, *config);
    if (!stack) return stack.error();
    const double read_seconds = clock.elapsed_ms() / 1000;

    LafortuneFitOptions options;
    options.variant = variant;
    options.auto_lobes = auto_lobes;
    // Auto without --max-lobes: as many as the lights determine (each lobe
    // takes 4 parameters, rho_d one), at most the variant's.
    const int most = max_lafortune_lobes(variant);
    options.lobes = *lobes;
    if (auto_lobes && !app.count("--max-lobes")) options.lobes = std::clamp((stack->count() - 1) / 4, 1, most);
    else if (auto_lobes) {
        if (args.max_lobes < 1 || args.max_lobes > most)
            return bad_input("--max-lobes " + std::to_string(args.max_lobes) + " is invalid: a " + to_string(variant) +
                             " fit takes 1 to " + std::to_string(most) + " lobes");
        if (stack->count() < lafortune_scalar_parameters(args.max_lobes))
            return bad_input("--max-lobes " + std::to_string(args.max_lobes) + " needs at least " +
                             std::to_string(lafortune_scalar_parameters(args.max_lobes)) + " lights, but '" +
                             load.light_file + "' has " + std::to_string(stack->count()));
        options.lobes = args.max_lobes;
    }
    options.tolerance = args.tolerance;
    options.min_gain = args.min_gain;
    options.view = view;
    options.max_iterations = args.max_iterations;
    options.function_tolerance = args.function_tolerance;
    options.spacing_cap = args.spacing_cap;
    options.exponent_penalty = args.exponent_penalty;
    options.density_radius = args.density_radius;
    options.relative_epsilon = args.relative_epsilon;
    options.threads = args.threads;
    Stopwatch fit_clock;
    auto fit = fit_lafortune(*stack, options);
    if (!fit) return fit.error();
    const double fit_seconds = fit_clock.elapsed_ms() / 1000;

    auto staged = AtomicOutput::begin(args.output);
    if (!staged) return staged.error();
    const std::string written_path = staged->temp_path();
    if (auto st = write_lafortune_exr(written_path, *fit, slot->light_file); !st) return st;
    const double total_seconds = clock.elapsed_ms() / 1000;
    const auto bytes = std::filesystem::file_size(written_path);

    // The relighting error at the fitted view (the EXR holds the fit's
    // floats exactly, so the fit in memory is the file's).
    std::optional<RelightError> training, held;
    if (!args.no_error) {
        auto e = lafortune_relight_error(*fit, *stack, *config, args.threads);
        if (!e) return e.error();
        training = *e;
    }
    if (!args.held_out.empty()) {
        StackLoadOptions h = load;
        h.light_file = args.held_out;
        auto e = stack_fit_error(StackFit{*fit}, h, *config, args.threads);
        if (!e) return e.error();
        held = *e;
    }
    if (auto st = staged->commit(); !st) return st;

    const std::vector<long long> histogram = fit->lobe_histogram();
    if (args.json) {
        nlohmann::json j;
        j["output"] = args.output;
        j["format"] = "exr";
        j["model"] = args.model;
        j["variant"] = to_string(variant);
        j["size"] = {fit->width, fit->height};
        j["channels"] = fit->channels;
        j["lights"] = stack->count();
        if (slot->slot) j["slot"] = *slot->slot;
        j["view"] = {fit->view.x, fit->view.y, fit->view.z};
        j["encoding"] = to_string(encoding);
        j["bytes"] = bytes;
        j["seconds"] = {{"read", read_seconds}, {"fit", fit_seconds}, {"total", total_seconds}};
        j["lobes"] = fit->lobes;
        j["auto_lobes"] = fit->auto_lobes;
        j["lobe_histogram"] = histogram;
        j["fallbacks"] = fit->fallbacks;
        if (training) j["training_error"] = error_json(*training);
        if (held) j["held_out_error"] = error_json(*held);
        print_json("fit", std::move(j));
    } else if (!args.quiet) {
        std::cout << "wrote " << args.output << ": " << args.model << " fit, " << fit->width << " x " << fit->height
                  << ", " << fit->channels << " channels, " << bytes << " bytes\n"
                  << "  " << stack->count() << " lights, view (" << fit->view.x << ", " << fit->view.y << ", "
                  << fit->view.z << ")" << (slot->slot ? ", slot " + std::to_string(*slot->slot) : "") << "\n"
                  << "  " << (fit->auto_lobes ? "auto lobes, at most " : "") << fit->lobes << " lobe"
                  << (fit->lobes == 1 ? "" : "s")
                  << (variant == LafortuneVariant::Rgb ? " per channel" : " (luminance, times a base colour)") << "\n"
                  << "  " << (variant == LafortuneVariant::Rgb ? "texel channels" : "texels")
                  << " by lobe count: " << histogram_text(histogram) << "\n"
                  << "  fallbacks " << fit->fallbacks << "\n"
                  << "  values " << to_string(encoding) << "\n"
                  << "  read " << read_seconds << " s, fit " << fit_seconds << " s, total " << total_seconds << " s\n";
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
        "fit",
        "Fit a relighting model (PTM, HSH or Lafortune lobes) to every texel of an image stack (docs/stacks.md)");
    app->add_option("STACK", args->stack,
                    "The stack's light file (.lp), its images beside it; or a BTF manifest (.json) and --slot")
        ->required();
    app->add_option("--model", args->model, "ptm-rgb, ptm-lrgb, hsh2, hsh3, lafortune (luminance) or lafortune-rgb")
        ->capture_default_str();
    app->add_option("-o,--output", args->output,
                    "Fit to write: .exr (float), .ptm (PTM 1.2) or .rti (HSH); Lafortune fits .exr only")
        ->required();
    app->add_option("--slot", args->slot, "With a BTF manifest: the view slot to fit (its lights and view)")
        ->capture_default_str();
    app->add_option("--lobes", args->lobes,
                    "Lafortune: lobes per texel (luminance 1-7, rgb 1-2 per channel), or auto: per texel while "
                    "they cut the error (--tolerance, --min-gain)")
        ->capture_default_str();
    app->add_option("--max-lobes", args->max_lobes,
                    "Lafortune --lobes auto: the most lobes (default: as many as the lights determine, at most the "
                    "variant's)");
    app->add_option("--tolerance", args->tolerance,
                    "Lafortune --lobes auto: the RMS at or below which no lobe is added (the stack's values)")
        ->capture_default_str();
    app->add_option("--min-gain", args->min_gain,
                    "Lafortune --lobes auto: the least fraction of the RMS a lobe must cut to be kept")
        ->capture_default_str();
    app->add_option("--view", args->view,
                    "Lafortune: the images' view direction x,y,z (default 0,0,1; a BTF manifest's slot gives it)");
    app->add_option("--max-iterations", args->max_iterations,
                    "Lafortune: Levenberg-Marquardt iterations per refinement")
        ->capture_default_str();
    app->add_option("--function-tolerance", args->function_tolerance,
                    "Lafortune: Levenberg-Marquardt stops when a step changes the squared error by less than this "
                    "fraction of it")
        ->capture_default_str();
    app->add_option("--spacing-cap", args->spacing_cap,
                    "Lafortune: no lobe narrower (full width at half maximum) than this many times the lights' mean "
                    "spacing (docs/lafortune-artefacts.md); 0: no cap")
        ->capture_default_str();
    app->add_option("--exponent-penalty", args->exponent_penalty,
                    "Lafortune: a prior towards broad lobes, the weight of the log-exponent penalty; 0: none")
        ->capture_default_str();
    app->add_option("--density-radius", args->density_radius,
                    "Lafortune: weight each light by 1 / (lights within this many degrees), so an uneven dome "
                    "counts like an even one; 0: every light alike")
        ->capture_default_str();
    app->add_option("--relative-epsilon", args->relative_epsilon,
                    "Lafortune: weight each value by 1 / (value + this)^2, fitting dark texels relatively; 0: none")
        ->capture_default_str();
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
    app->add_option("--ocio-config,--colorconfig", args->ocio_config,
                    "OpenColorIO config (default: $OCIO, else built in)");
    app->add_option("--threads", args->threads, "Threads (0: all cores)")->capture_default_str();
    app->add_flag("--json", args->json, "Print a machine-readable summary on stdout");
    app->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
    return {app,
            [args, app] { return run(*args, *app); },
            {{"LinearFitOptions::singular_threshold", "--singular-threshold"},
             {"LinearFitOptions::model", "--model"},
             {"LafortuneFitOptions::variant", "--model"},
             {"LafortuneFitOptions::lobes", "--lobes"},
             {"LafortuneFitOptions::auto_lobes", "--lobes auto"},
             {"LafortuneFitOptions::tolerance", "--tolerance"},
             {"LafortuneFitOptions::min_gain", "--min-gain"},
             {"LafortuneFitOptions::view", "--view"},
             {"LafortuneFitOptions::max_iterations", "--max-iterations"},
             {"LafortuneFitOptions::function_tolerance", "--function-tolerance"},
             {"LafortuneFitOptions::threads", "--threads"},
             {"LafortuneFitOptions::spacing_cap", "--spacing-cap"},
             {"LafortuneFitOptions::exponent_penalty", "--exponent-penalty"},
             {"LafortuneFitOptions::density_radius", "--density-radius"},
             {"LafortuneFitOptions::relative_epsilon", "--relative-epsilon"},
             {"StackLoadOptions::colorspace", "--colorspace"},
             {"StackLoadOptions::encoding", "--encoding"}}};
}

}  // namespace cmfilter::cli
