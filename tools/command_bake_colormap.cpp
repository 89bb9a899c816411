// cmfilter bake-colormap: colour-map image -> prefiltered table T(v, sigma)
// (eq. 10), with its measured bilinear lookup error.
#include "command.h"

#include "cmfilter/atomic_output.h"
#include "cmfilter/color_map_loading.h"
#include "cmfilter/gaussian_color_table_file.h"
#include "cmfilter/table_lookup_error.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <iomanip>
#include <iostream>
#include <memory>

namespace cmfilter::cli {

namespace {

struct BakeColormapArgs {
    std::string map_path;
    std::string output;
    std::optional<int> row, column;
    std::string colorspace;
    std::string ocio_config;
    std::string domain = "0:1";
    std::string wrap = "clamp";
    std::optional<double> sigma_max;
    int values = 256;
    int sigmas = 256;
    std::string sigma_spacing = "sqrt";
    std::optional<double> margin;
    int error_samples = 20000;
    std::uint64_t seed = 1;
    int threads = 0;
    bool json = false;
    bool quiet = false;
};

Status run(const BakeColormapArgs& args)
{
    using Clock = std::chrono::steady_clock;
    if (auto st = check_output_path(args.output, ".exr"); !st) return st;
    auto domain = parse_range("--domain", args.domain);
    if (!domain) return domain.error();
    auto wrap = parse_wrap_mode(args.wrap);
    if (!wrap) return wrap.error();
    auto spacing = parse_sigma_spacing(args.sigma_spacing);
    if (!spacing) return spacing.error();
    if (args.error_samples < 0)
        return bad_input("--error-samples " + std::to_string(args.error_samples) +
                         " is negative (expected >= 0; 0 skips the measurement)");

    auto config = load_color_config(args.ocio_config);
    if (!config) return config.error();

    ColorMapLoadOptions load;
    load.path = args.map_path;
    load.row = args.row;
    load.column = args.column;
    load.colorspace = args.colorspace;
    load.vmin = domain->first;
    load.vmax = domain->second;
    load.wrap = *wrap;
    auto loaded = load_color_map(load, *config);
    if (!loaded) return loaded.error();

    GaussianColorTableOptions options;
    options.values = args.values;
    options.sigmas = args.sigmas;
    options.sigma_max = args.sigma_max;
    options.spacing = *spacing;
    options.margin = args.margin;
    options.threads = args.threads;
    const auto t0 = Clock::now();
    auto table = GaussianColorTable::bake(loaded->map, options);
    if (!table) return table.error();
    const double bake_ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();

    GaussianColorTableInfo info;
    info.source = loaded->provenance;
    if (args.error_samples > 0) {
        LookupErrorOptions measure;
        measure.samples = args.error_samples;
        measure.seed = args.seed;
        measure.threads = args.threads;
        info.lookup_error = measure_lookup_error(*table, loaded->map, measure);
        info.lookup_error_samples = args.error_samples;
    }
    if (auto st = write_gaussian_color_table(args.output, *table, info); !st) return st;

    const TableAxes& ax = table->axes();
    if (args.json) {
        nlohmann::json j;
        j["output"] = args.output;
        j["kind"] = kGaussianColorTableKind;
        j["values"] = ax.values;
        j["sigmas"] = ax.sigmas;
        j["domain"] = {ax.vmin, ax.vmax};
        j["wrap"] = to_string(ax.wrap);
        j["value_axis"] = {ax.value_first(), ax.value_last()};
        j["sigma_max"] = ax.sigma_max;
        j["sigma_spacing"] = to_string(ax.spacing);
        j["source"] = info.source.path;
        j["colorspace"] = info.source.colorspace;
        j["colorspace_rule"] = info.source.colorspace_rule;
        j["bake_ms"] = bake_ms;
        if (info.lookup_error) {
            j["lookup_error"] = {{"metric", "CIEDE2000"},
                                 {"samples", info.lookup_error_samples},
                                 {"mean", info.lookup_error->mean},
                                 {"p95", info.lookup_error->p95},
                                 {"max", info.lookup_error->max}};
        }
        std::cout << j.dump(2) << "\n";
    } else if (!args.quiet) {
        std::cout << "wrote " << args.output << ": gaussian colour table, " << ax.values
                  << " values x " << ax.sigmas << " sigmas\n"
                  << "  map      " << info.source.path << " (" << info.source.image_width << " x "
                  << info.source.image_height << ", " << info.source.selection << "), "
                  << info.source.colorspace << " -> " << info.source.linear_space << " ("
                  << info.source.colorspace_rule << ")\n"
                  << "  values   domain [" << ax.vmin << ", " << ax.vmax << "], wrap "
                  << to_string(ax.wrap) << ", axis [" << ax.value_first() << ", "
                  << ax.value_last() << "]\n"
                  << "  sigmas   0 .. " << ax.sigma_max << ", " << to_string(ax.spacing)
                  << " spacing\n";
        if (info.lookup_error)
            std::cout << std::setprecision(3) << "  lookup   CIEDE2000 mean " << info.lookup_error->mean
                      << ", p95 " << info.lookup_error->p95 << ", max " << info.lookup_error->max
                      << " over " << info.lookup_error_samples << " random (v, sigma)\n";
        std::cout << std::setprecision(3) << "  time     bake " << bake_ms << " ms\n";
    }
    return ok();
}

}  // namespace

Command setup_bake_colormap(CLI::App& parent)
{
    auto args = std::make_shared<BakeColormapArgs>();
    CLI::App* app = parent.add_subcommand(
        "bake-colormap",
        "Bake the prefiltered colour-map table T(v, sigma) = (C0 * N(0, sigma^2))(v) (eq. 10)");
    app->add_option("MAP_IMAGE", args->map_path,
                    "Colour map: any image OpenImageIO reads (W x 1, 1 x H, or pick --row/--column)")
        ->required();
    app->add_option("-o,--output", args->output, "Table to write (.exr)")->required();
    auto* row = app->add_option("--row", args->row, "Use this row of a taller image as the gradient");
    app->add_option("--column", args->column, "Use this column as the gradient (top = vmin)")
        ->excludes(row);
    app->add_option("--colorspace", args->colorspace,
                    "Colour space of the map image (default: the file's metadata, else sRGB for "
                    "integer and linear for float files)");
    app->add_option("--ocio-config", args->ocio_config,
                    "OpenColorIO config (default: $OCIO if set, else the built-in config)");
    app->add_option("--domain", args->domain, "Driver domain the map spans, MIN:MAX (use --domain=-1:1 for negatives)")
        ->capture_default_str();
    app->add_option("--wrap", args->wrap, "Map beyond the domain: clamp, repeat or mirror")
        ->capture_default_str();
    app->add_option("--sigma-max", args->sigma_max,
                    "Largest sigma in the table (default: a quarter of the domain width)");
    app->add_option("--values", args->values, "Samples on the value axis")->capture_default_str();
    app->add_option("--sigmas", args->sigmas, "Samples on the sigma axis")->capture_default_str();
    app->add_option("--sigma-spacing", args->sigma_spacing,
                    "Sigma axis: linear, or sqrt (uniform in sqrt(sigma), denser near 0)")
        ->capture_default_str();
    app->add_option("--margin", args->margin,
                    "clamp only: value axis extends this far beyond the domain (default 3 sigma-max)");
    app->add_option("--error-samples", args->error_samples,
                    "Random (v, sigma) at which to measure the lookup error (0: skip)")
        ->capture_default_str();
    app->add_option("--seed", args->seed, "Seed for the error measurement")->capture_default_str();
    app->add_option("--threads", args->threads, "Threads (0: all cores)")->capture_default_str();
    app->add_flag("--json", args->json, "Print a machine-readable summary on stdout");
    app->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
    return {app, [args] { return run(*args); }};
}

}  // namespace cmfilter::cli
