// SPDX-License-Identifier: Apache-2.0
// cmfilter apply: the filtered colour image of a colour-mapped driver at a
// level of detail, by one of the methods naive, gaussian (Heitz et al. 2013,
// eq. 10 with the moments of sec. 4.2), exact (sec. 4.1) or reference (the box
// mean of C0(f)); EXR in scene-linear, PNG/JPEG in sRGB.
#include "command.h"

#include "cmfilter/util/stopwatch.h"

#include "cmfilter/ops/filtered_image.h"
#include "cmfilter/ops/filtered_image_file.h"
#include "cmfilter/ops/method_choice.h"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <chrono>
#include <iomanip>
#include <iostream>
#include <memory>

namespace cmfilter::cli {

namespace {

// The fields apply_filter's errors and warnings name, as apply's flags.
FieldFlags apply_flags()
{
    FieldFlags flags = color_map_flags();
    flags.insert(flags.end(), {{"ApplyOptions::lod", "--lod"},
                               {"ApplyOptions::method", "--method"},
                               {"ApplyOptions::histograms_path", "--histograms H.exr"},
                               {"ApplyOptions::moments_path", "--moments"},
                               {"MomentBakeOptions::order 4", "bake-moments --order 4"},
                               {"ApplyOptions::driver_path", "--driver"},
                               {"MethodChoiceOptions::tolerance", "--tolerance"},
                               {"MethodChoiceOptions::lods", "--measure-lods"},
                               {"MethodChoiceOptions::color_pyramid_path", "--color-pyramid P.exr"},
                               {"MethodChoiceOptions::segment_pyramid_path", "--segment-pyramid S.exr"}});
    return flags;
}

struct ApplyArgs {
    ApplyOptions options;  // paths, lod and threads bind straight to its fields
    std::string output;
    std::string method = "gaussian";
    std::string size;
    std::string ocio_config;
    std::optional<double> tolerance;
    std::vector<double> measure_lods;
    std::string color_pyramid;    // --tolerance's candidate color-pyramid
    std::string segment_pyramid;  // --tolerance's candidate segments
    bool json = false;
    bool quiet = false;
};

Status run(ApplyArgs args)
{
    if (auto st = check_filtered_image_output(args.output); !st) return st;
    auto method = parse_filter_method(args.method);
    if (!method) return method.error();
    args.options.method = *method;
    if (!args.size.empty()) {
        auto size = parse_size("--size", args.size);
        if (!size) return size.error();
        args.options.width = size->first;
        args.options.height = size->second;
    }
    auto config = load_color_config(args.ocio_config);
    if (!config) return config.error();

    const bool progress = !args.quiet && !args.json && isatty(STDERR_FILENO);
    if (progress)
        args.options.progress = [last = -1](double f) mutable {
            const int percent = static_cast<int>(f * 100);
            if (percent == last) return;
            last = percent;
            std::cerr << "\rapply: " << percent << "%" << (percent == 100 ? "\n" : "") << std::flush;
        };
    const Stopwatch t0;
    // With a tolerance, the cheapest method that meets it (method_choice.h).
    std::optional<MethodChoice> choice;
    if (args.tolerance) {
        MethodChoiceOptions co;
        co.tolerance = *args.tolerance;
        co.lods = args.measure_lods;
        co.color_pyramid_path = args.color_pyramid;
        co.segment_pyramid_path = args.segment_pyramid;
        if (progress) co.progress = terminal_progress("apply: measuring the methods");
        auto chosen = choose_filter_method(args.options, *config, co);
        if (!chosen) return chosen.error();
        if (!chosen->choice())
            return no_method_meets(*chosen,
                                   "'" + args.options.moments_path + "' through '" + args.options.table_path + "'");
        choice = std::move(*chosen);
        for (std::string& why : choice->skipped) why = name_flags(why, apply_flags());
        args.options.method = choice->choice()->method;
        if (args.options.method == FilterMethod::ColorPyramid) args.options.moments_path = args.color_pyramid;
        if (args.options.method == FilterMethod::Segments) args.options.moments_path = args.segment_pyramid;
    } else if (!args.color_pyramid.empty()) {
        return bad_input("--color-pyramid is a candidate of --tolerance; with --method color-pyramid, name the colour "
                         "pyramid with --moments");
    } else if (!args.segment_pyramid.empty()) {
        return bad_input("--segment-pyramid is a candidate of --tolerance; with --method segments, name the segment "
                         "pyramid with --moments");
    }
    auto image = apply_filter(args.options, *config);
    if (!image) {
        if (progress) std::cerr << "\n";
        return image.error();
    }
    if (choice)
        image->method_choice = MethodToleranceRecord{to_string(choice->choice()->method), choice->tolerance,
                                                     choice->choice()->worst, lod_list_text(choice->lods),
                                                     args.options.table_path};
    if (auto st = write_filtered_image(args.output, *image, *config); !st) return st;
    const double total_ms = t0.elapsed_ms();
    for (std::string& w : image->warnings) {
        w = name_flags(w, apply_flags());
        std::cerr << "cmfilter apply: warning: " << w << "\n";
    }

    const FilteredImage& r = *image;
    if (args.json) {
        nlohmann::json j;
        j["output"] = args.output;
        j["method"] = to_string(r.method);
        j["size"] = {r.width, r.height};
        j["lod"] = r.lod;
        j["lod_requested"] = r.lod_requested;
        j["lod_clamped"] = r.lod_clamped;
        j["top_level"] = r.top_level;
        j["moments"] = r.moments_path;
        j["table"] = r.table_path;
        j["map"] = r.map_path;
        j["driver"] = r.driver_path;
        j["histograms"] = r.histograms_path;
        j["linear_space"] = r.linear_space;
        j["table_lookups"] = {{"lookups", r.table_counters.lookups},
                              {"sigma_clamped", r.table_counters.sigma_clamped},
                              {"value_clamped", r.table_counters.value_clamped},
                              {"invalid", r.table_counters.invalid}};
        j["failed_lookups"] = r.failed_lookups;
        j["texels_outside_domain"] = r.texels_outside_domain;
        j["fraction_outside_domain"] = r.fraction_outside_domain;
        if (r.method == FilterMethod::Segments) {
            j["segment_fit_de"] = r.segment_fit_de;
            j["segment_mean_fit_de"] = r.segment_mean_fit_de;
        }
        j["warnings"] = r.warnings;
        if (choice) j["choice"] = method_choice_json(*choice);
        j["time_ms"] = total_ms;
        print_json("apply", std::move(j));
    } else if (!args.quiet) {
        std::cout << std::setprecision(6) << "wrote " << args.output << ": " << to_string(r.method) << ", " << r.width
                  << " x " << r.height << " at lod " << r.lod;
        if (r.lod_clamped) std::cout << " (asked " << r.lod_requested << ")";
        const bool baked = r.method == FilterMethod::ColorPyramid || r.method == FilterMethod::Segments;
        std::cout << (baked ? "\n  pyramid    " : "\n  moments    ") << r.moments_path << " (" << r.moments.width
                  << " x " << r.moments.height << ", levels 0.." << r.top_level << " reachable)\n"
                  << "  table      " << r.table_path << "\n";
        if (!r.map_path.empty()) std::cout << "  map        " << r.map_path << "\n";
        if (r.method == FilterMethod::Segments) {
            std::cout << "  fit        the map through the pyramid's breakpoints: CIEDE2000 " << r.segment_fit_de
                      << " at most";
            if (r.segment_mean_fit_de > 0)
                std::cout << ", " << r.segment_mean_fit_de << " mean over the driver's values";
            std::cout << "\n";
        }
        if (!r.driver_path.empty()) std::cout << "  driver     " << r.driver_path << "\n";
        if (!r.histograms_path.empty()) std::cout << "  histograms " << r.histograms_path << "\n";
        if (r.method == FilterMethod::Gaussian || r.method == FilterMethod::Mixture)
            std::cout << "  lookups    " << r.table_counters.lookups << ", sigma clamped "
                      << r.table_counters.sigma_clamped << ", value clamped " << r.table_counters.value_clamped << "\n";
        if (r.texels_outside_domain > 0)
            std::cout << "  outside    " << r.texels_outside_domain << " driver texels ("
                      << 100 * r.fraction_outside_domain << "%) outside the table's domain\n";
        if (choice) print_method_choice(std::cout, *choice);
        std::cout << std::setprecision(3) << "  time       " << total_ms << " ms\n";
    }
    return ok();
}

}  // namespace

Command setup_apply(CLI::App& parent)
{
    auto args = std::make_shared<ApplyArgs>();
    CLI::App* app = parent.add_subcommand("apply",
                                          "Filtered colour image of a colour-mapped driver at a level of detail "
                                          "(naive, gaussian eq. 10, exact sec. 4.1, reference)");
    app->add_option("--moments", args->options.moments_path,
                    "Moment pyramid of the driver (bake-moments); with --method color-pyramid, its colour pyramid "
                    "(bake-moments --method color-pyramid); with --method segments, its segment pyramid "
                    "(bake-moments --segments)")
        ->required();
    app->add_option("--table", args->options.table_path, "Gaussian colour table (bake-colormap)")->required();
    app->add_option("--lod", args->options.lod,
                    "Level of detail: log2 of the footprint width in level-0 texels; fractional "
                    "values blend two levels")
        ->required();
    app->add_option("-o,--output", args->output, "Image to write: .exr (scene-linear float) or .png/.jpg (sRGB, 8-bit)")
        ->required();
    CLI::Option* method =
        app->add_option("--method", args->method,
                        "naive, gaussian, mixture (moments of bake-moments --order 4), exact, color-pyramid (--moments "
                        "names a colour pyramid of the table's map), segments (--moments names a segment pyramid the "
                        "table's map fits) or reference")
            ->capture_default_str();
    app->add_option("--tolerance", args->tolerance,
                    "Choose the cheapest method whose mean CIEDE2000 against the box reference is at most DE at "
                    "every measured LOD (naive, gaussian, color-pyramid with --color-pyramid, mixture with order-4 "
                    "moments, exact with --histograms)")
        ->excludes(method);
    add_measure_lods_option(*app, args->measure_lods);
    app->add_option("--color-pyramid", args->color_pyramid,
                    "Colour pyramid of the same driver through the table's map (bake-moments --method "
                    "color-pyramid): --tolerance measures color-pyramid too, and reads it when chosen");
    app->add_option("--segment-pyramid", args->segment_pyramid,
                    "Segment pyramid of the same driver (bake-moments --segments): --tolerance measures segments "
                    "too, and reads it when chosen");
    app->add_option("--size", args->size, "Output size WxH (default: the size of level floor(lod))");
    app->add_option("--map", args->options.map_path,
                    "Colour map image (default: the table's cmfilter:source, hash-checked)");
    app->add_option("--driver", args->options.driver_path,
                    "Driver image for reference (default: the moments' cmfilter:source, hash-checked)");
    app->add_option("--histograms", args->options.histograms_path,
                    "Histogram pyramid of the driver (required by --method exact)");
    app->add_option("--ocio-config,--colorconfig", args->ocio_config,
                    "OpenColorIO config (default: $OCIO if set, else the built-in config)");
    app->add_option("--threads", args->options.threads, "Threads (0: all cores)")->capture_default_str();
    app->add_flag("--json", args->json, "Print a machine-readable summary on stdout");
    app->add_flag("-q,--quiet", args->quiet, "Print nothing on success but warnings (and no progress)");
    return {app, [args] { return run(*args); }, apply_flags()};
}

}  // namespace cmfilter::cli
