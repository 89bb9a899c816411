// SPDX-License-Identifier: Apache-2.0
// cmfilter bake-colormap: colour-map image -> prefiltered table T(v, sigma)
// (eq. 10), with its measured bilinear lookup error; with --tolerance, the
// smallest table that meets a CIEDE2000 tolerance; with --for, sigma_max from
// the driver or scene the table is for.
#include "command.h"

#include "cmfilter/io/build_record.h"

#include "cmfilter/util/atomic_output.h"
#include "cmfilter/colormap/color_map_loading.h"
#include "cmfilter/scene/driver_sigma_range.h"
#include "cmfilter/tables/gaussian_color_table_file.h"
#include "cmfilter/tables/table_lookup_error.h"
#include "cmfilter/tables/table_size_search.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace cmfilter::cli {

namespace {

// The flags of the fields bake-colormap's library calls may name.
FieldFlags bake_colormap_flags()
{
    FieldFlags flags = color_map_flags();
    for (auto& f : exr_output_flags()) flags.push_back(f);
    flags.insert(flags.end(), {{"ColorMapLoadOptions::colorspace", "--colorspace"},
                               {"GaussianColorTableOptions::values", "--values"},
                               {"GaussianColorTableOptions::sigmas", "--sigmas"},
                               {"GaussianColorTableOptions::sigma_max", "--sigma-max"},
                               {"GaussianColorTableOptions::margin", "--margin"},
                               {"TableSizeSearchOptions::tolerance", "--tolerance"}});
    return flags;
}

struct BakeColormapArgs {
    std::string map_path;
    std::string output;
    std::optional<int> row, column;
    std::string colorspace;
    std::string ocio_config;
    std::string domain = "0:1";
    std::string wrap = "clamp";
    std::optional<double> sigma_max;
    std::string for_path;
    std::optional<double> tolerance;
    double tolerance_percentile = 99.9;
    int values = 256;
    int sigmas = 256;
    std::string sigma_spacing = "sqrt";
    std::optional<double> margin;
    int error_samples = 20000;
    std::uint64_t seed = 1;
    int threads = 0;
    ExrOutputArgs storage;
    bool json = false;
    bool quiet = false;
    bool update = false;
};

Status run(const BakeColormapArgs& args, const CLI::App& app)
{
    using Clock = std::chrono::steady_clock;
    if (auto st = check_output_path(args.output, ".exr"); !st) return st;
    auto domain = parse_range("--domain", args.domain);
    if (!domain) return domain.error();
    auto wrap = parse_wrap_mode(args.wrap);
    if (!wrap) return wrap.error();
    auto spacing = parse_sigma_spacing(args.sigma_spacing);
    if (!spacing) return spacing.error();
    auto storage = exr_output_options_from_args(args.storage);
    if (!storage) return storage.error();
    if (args.error_samples < 0)
        return bad_input("--error-samples " + std::to_string(args.error_samples) +
                         " is negative (expected >= 0; 0 skips the measurement)");
    if (args.tolerance && !(std::isfinite(*args.tolerance) && *args.tolerance > 0)) {
        std::ostringstream msg;
        msg << "--tolerance " << *args.tolerance << " is invalid (expected a CIEDE2000 difference > 0)";
        return bad_input(msg.str());
    }
    if (!(args.tolerance_percentile > 0 && args.tolerance_percentile <= 100)) {
        std::ostringstream msg;
        msg << "--tolerance-percentile " << args.tolerance_percentile
            << " is invalid (expected 0 < P <= 100; 100 is the maximum)";
        return bad_input(msg.str());
    }

    auto digest = build_digest(app, {}, color_config_for_record(args.ocio_config));
    if (!digest) return digest.error();
    if (args.update && outputs_record_build({args.output}, *digest)) {
        report_up_to_date("bake-colormap", {args.output}, *digest, args.json, args.quiet);
        return ok();
    }
    storage->attributes.emplace_back(kBuildRecordAttribute, *digest);

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

    GaussianColorTableInfo info;
    info.source = loaded->provenance;
    std::optional<double> sigma_max = args.sigma_max;
    info.sigma_max_source = sigma_max ? "--sigma-max" : "default: a quarter of the domain width";
    if (!args.for_path.empty()) {
        DriverSigmaOptions range_options;
        range_options.map_path = args.map_path;
        range_options.threads = args.threads;
        auto range = largest_driver_sigma(args.for_path, range_options);
        if (!range) return range.error();
        sigma_max = range->sigma_max;
        info.sigma_max_source = "--for: " + range->how;
    }

    std::optional<TableSizeSearchResult> search;
    std::optional<GaussianColorTable> table;
    const auto t0 = Clock::now();
    if (args.tolerance) {
        TableSizeSearchOptions search_options;
        search_options.tolerance = *args.tolerance;
        search_options.quantile = args.tolerance_percentile / 100.0;
        search_options.sigma_max = sigma_max;
        search_options.margin = args.margin;
        search_options.seed = args.seed;
        search_options.threads = args.threads;
        auto found = find_smallest_table(loaded->map, search_options);
        if (!found) return found.error();
        search = std::move(*found);
        table = std::move(search->table);
        std::ostringstream grid;
        grid << "values " << search_options.value_counts.front() << ".." << search_options.value_counts.back()
             << " x sigmas " << search_options.sigma_counts.front() << ".." << search_options.sigma_counts.back()
             << " (powers of two and 1.5x between), sqrt and linear spacing; " << search->trials.size()
             << " candidates measured at " << search_options.search_samples << " points (seed " << args.seed << "), "
             << search->rejected << " rejected at verification (seed " << args.seed + 1 << ")";
        info.tolerance = TableToleranceRecord{*args.tolerance, quantile_name(search_options.quantile), search->error,
                                              search_options.verify_samples, grid.str()};
    } else {
        GaussianColorTableOptions options;
        options.values = args.values;
        options.sigmas = args.sigmas;
        options.sigma_max = sigma_max;
        options.spacing = *spacing;
        options.margin = args.margin;
        options.threads = args.threads;
        auto baked = GaussianColorTable::bake(loaded->map, options);
        if (!baked) return baked.error();
        table = std::move(*baked);
    }
    const double bake_ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();

    if (args.error_samples > 0) {
        LookupErrorOptions measure;
        measure.samples = args.error_samples;
        measure.seed = args.seed;
        measure.threads = args.threads;
        info.lookup_error = measure_lookup_error(*table, loaded->map, measure);
        info.lookup_error_samples = args.error_samples;
    }
    if (auto st = write_gaussian_color_table(args.output, *table, info, *storage); !st) return st;

    const TableAxes& ax = table->axes();
    const std::size_t table_bytes = TableSize{ax.values, ax.sigmas, ax.spacing}.bytes();
    const GaussianColorTableOptions defaults;
    const std::size_t default_bytes = TableSize{defaults.values, defaults.sigmas, defaults.spacing}.bytes();
    if (args.json) {
        nlohmann::json j;
        j["output"] = args.output;
        j["storage"] = storage_json(*storage);
        j["up_to_date"] = false;
        j["build"] = *digest;
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
        j["colorspace_rule"] = name_flags(info.source.colorspace_rule, bake_colormap_flags());
        j["bake_ms"] = bake_ms;
        j["bytes"] = table_bytes;
        j["sigma_max_source"] = info.sigma_max_source;
        if (search) {
            nlohmann::json candidates = nlohmann::json::array();
            for (const TableSizeTrial& t : search->trials)
                candidates.push_back({{"values", t.size.values},
                                      {"sigmas", t.size.sigmas},
                                      {"sigma_spacing", to_string(t.size.spacing)},
                                      {"bytes", t.size.bytes()},
                                      {"error", t.error},
                                      {"verified", t.verified},
                                      {"verify_error", t.verified ? nlohmann::json(t.verify_error) : nullptr}});
            j["tolerance"] = {{"de2000", info.tolerance->tolerance},
                              {"statistic", info.tolerance->statistic},
                              {"error", search->error},
                              {"samples", info.tolerance->samples},
                              {"search_error", search->search_error},
                              {"verify_mean", search->verify_summary.mean},
                              {"verify_max", search->verify_summary.max},
                              {"default_bytes", default_bytes},
                              {"rejected", search->rejected},
                              {"search", info.tolerance->search},
                              {"candidates", candidates}};
        }
        if (info.lookup_error) {
            j["lookup_error"] = {{"metric", "CIEDE2000"},
                                 {"samples", info.lookup_error_samples},
                                 {"mean", info.lookup_error->mean},
                                 {"p95", info.lookup_error->p95},
                                 {"max", info.lookup_error->max}};
        }
        print_json("bake-colormap", std::move(j));
    } else if (!args.quiet) {
        std::cout << "wrote " << args.output << ": gaussian colour table, " << ax.values << " values x " << ax.sigmas
                  << " sigmas\n"
                  << "  map      " << info.source.path << " (" << info.source.image_width << " x "
                  << info.source.image_height << ", " << info.source.selection << "), " << info.source.colorspace
                  << " -> " << info.source.linear_space << " ("
                  << name_flags(info.source.colorspace_rule, bake_colormap_flags()) << ")\n"
                  << "  values   domain [" << ax.vmin << ", " << ax.vmax << "], wrap " << to_string(ax.wrap)
                  << ", axis [" << ax.value_first() << ", " << ax.value_last() << "]\n"
                  << "  sigmas   0 .. " << ax.sigma_max << ", " << to_string(ax.spacing)
                  << " spacing; sigma_max: " << info.sigma_max_source << "\n";
        if (search)
            std::cout << std::setprecision(3) << "  size     chose " << ax.values << " values x " << ax.sigmas
                      << " sigmas (" << to_string(ax.spacing) << "): " << table_bytes << " bytes, "
                      << 100.0 * static_cast<double>(table_bytes) / static_cast<double>(default_bytes)
                      << "% of the default " << defaults.values << " x " << defaults.sigmas << " (" << default_bytes
                      << " bytes)\n"
                      << "  tolerance CIEDE2000 " << info.tolerance->statistic << " <= " << info.tolerance->tolerance
                      << ": reached " << search->error << " at " << info.tolerance->samples << " random (v, sigma) ("
                      << search->search_error << " at the search points); " << search->trials.size()
                      << " candidates measured, " << search->rejected << " rejected at verification\n";
        if (info.lookup_error)
            std::cout << std::setprecision(3) << "  lookup   CIEDE2000 mean " << info.lookup_error->mean << ", p95 "
                      << info.lookup_error->p95 << ", max " << info.lookup_error->max << " over "
                      << info.lookup_error_samples << " random (v, sigma)\n";
        std::cout << "  storage  " << exr_output_text(*storage, "scanlines") << "\n";
        std::cout << std::fixed << std::setprecision(1) << "  time     " << (search ? "search and bake " : "bake ")
                  << bake_ms << " ms\n";
    }
    return ok();
}

}  // namespace

Command setup_bake_colormap(CLI::App& parent)
{
    auto args = std::make_shared<BakeColormapArgs>();
    CLI::App* app = parent.add_subcommand(
        "bake-colormap", "Bake the prefiltered colour-map table T(v, sigma) = (C0 * N(0, sigma^2))(v) (eq. 10)");
    app->add_option("MAP_IMAGE", args->map_path,
                    "Colour map: any image OpenImageIO reads (W x 1, 1 x H, or pick --row/--column)")
        ->required();
    app->add_option("-o,--output", args->output, "Table to write (.exr)")->required();
    auto* row = app->add_option("--row", args->row, "Use this row of a taller image as the gradient");
    app->add_option("--column", args->column, "Use this column as the gradient (top = vmin)")->excludes(row);
    app->add_option("--colorspace", args->colorspace,
                    "Colour space of the map image (default: the file's metadata, else sRGB for "
                    "integer and linear for float files)");
    app->add_option("--ocio-config,--colorconfig", args->ocio_config,
                    "OpenColorIO config (default: $OCIO if set, else the built-in config)");
    app->add_option("--domain", args->domain, "Driver domain the map spans, MIN:MAX (use --domain=-1:1 for negatives)")
        ->capture_default_str();
    app->add_option("--wrap", args->wrap, "Map beyond the domain: clamp, repeat or mirror")->capture_default_str();
    auto* sigma_max = app->add_option("--sigma-max", args->sigma_max,
                                      "Largest sigma in the table (default: a quarter of the domain width)");
    app->add_option("--for", args->for_path,
                    "Take sigma-max from what the table is for: the largest sigma of a noise sigma table "
                    "(bake-noise), a moment pyramid (bake-moments) or a scene (.json)")
        ->excludes(sigma_max);
    auto* values = app->add_option("--values", args->values, "Samples on the value axis")->capture_default_str();
    auto* sigmas = app->add_option("--sigmas", args->sigmas, "Samples on the sigma axis")->capture_default_str();
    auto* spacing = app->add_option("--sigma-spacing", args->sigma_spacing,
                                    "Sigma axis: linear, or sqrt (uniform in sqrt(sigma), denser near 0)")
                        ->capture_default_str();
    auto* tolerance =
        app->add_option("--tolerance", args->tolerance,
                        "Choose the smallest table (values, sigmas, spacing) whose lookup error is at most "
                        "this CIEDE2000 difference")
            ->excludes(values)
            ->excludes(sigmas)
            ->excludes(spacing);
    app->add_option("--tolerance-percentile", args->tolerance_percentile,
                    "Which lookup error --tolerance bounds: this percentile of the CIEDE2000 at random "
                    "(v, sigma) (100: the maximum)")
        ->capture_default_str()
        ->needs(tolerance);
    app->add_option("--margin", args->margin,
                    "clamp only: value axis extends this far beyond the domain (default 3 sigma-max)");
    app->add_option("--error-samples", args->error_samples,
                    "Random (v, sigma) at which to measure the lookup error (0: skip)")
        ->capture_default_str();
    app->add_option("--seed", args->seed, "Seed for the error measurement")->capture_default_str();
    app->add_option("--threads", args->threads, "Threads (0: all cores)")->capture_default_str();
    add_exr_output_options(*app, args->storage, "scanlines");
    app->add_flag("--json", args->json, "Print a machine-readable summary on stdout");
    app->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
    add_update_option(*app, args->update);
    return {app, [args, app] { return run(*args, *app); }, bake_colormap_flags()};
}

}  // namespace cmfilter::cli
