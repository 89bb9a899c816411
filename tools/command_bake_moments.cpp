// SPDX-License-Identifier: Apache-2.0
// cmfilter bake-moments: driver texture -> moment pyramid, per level the box
// means of (f - c) and (f - c)^2 (Heitz et al. 2013, sec. 4.2) in a tiled,
// MIP-mapped EXR that OpenImageIO's TextureSystem reads.
#include "command.h"

#include "cmfilter/io/build_record.h"

#include "cmfilter/util/stopwatch.h"

#include "cmfilter/util/atomic_output.h"
#include "cmfilter/ops/table_color_pyramid.h"
#include "cmfilter/ops/table_segment_pyramid.h"
#include "cmfilter/texture/histogram_pyramid.h"
#include "cmfilter/texture/moment_pyramid.h"
#include "cmfilter/util/temporary_file.h"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <optional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace cmfilter::cli {

namespace {

struct BakeMomentsArgs {
    std::string driver_path;
    std::string output;
    std::string histograms;
    std::string channel;
    std::string wrap = "clamp";
    std::string nan = "error";
    int threads = 0;
    int order = 2;
    std::string method;  // what the baked file is for: naive, gaussian, mixture or color-pyramid
    std::optional<double> tolerance;
    std::vector<std::string> segments;  // tables whose maps' breakpoints a segment pyramid holds
    int max_channels = 0;
    std::string table;
    std::string map;
    std::string ocio_config;
    std::vector<double> measure_lods;
    ExrOutputArgs storage;
    bool json = false;
    bool quiet = false;
    bool update = false;
};

// The colour pyramid of the driver through the table's map, as --method
// color-pyramid writes it (with the moments' driver, wrap and storage).
TableColorPyramidOptions color_pyramid_options(const BakeMomentsArgs& args, const MomentBakeOptions& options)
{
    TableColorPyramidOptions o;
    static_cast<PyramidBakeOptions&>(o.bake) = options;
    o.bake.progress = options.progress;
    o.table_path = args.table;
    o.map_path = args.map;
    return o;
}

// The segment pyramid of the driver for the breakpoints of --segments' maps
// (with the moments' driver, wrap and storage).
TableSegmentPyramidOptions segment_pyramid_options(const BakeMomentsArgs& args, const MomentBakeOptions& options)
{
    TableSegmentPyramidOptions o;
    static_cast<PyramidBakeOptions&>(o.bake) = options;
    o.bake.progress = options.progress;
    o.bake.tolerance_de = args.tolerance.value_or(0.0);
    o.bake.max_channels = args.max_channels;
    o.table_paths = args.segments;
    return o;
}

// The most channels of the segment pyramid --tolerance measures.
constexpr int kToleranceSegmentChannels = 64;

// The cheapest method for --tolerance, measured on order-4 moments and a
// colour pyramid baked to temporary files (and the histograms just written,
// when asked for).
Expected<MethodChoice> choose_moment_order(const BakeMomentsArgs& args, const MomentBakeOptions& options,
                                           bool histograms, bool progress)
{
    auto config = load_color_config(args.ocio_config);
    if (!config) return config.error();
    auto aside = TemporaryFile::create("cmfilter-moments", ".exr");
    if (!aside) return aside.error();
    MomentBakeOptions four = options;
    four.order = 4;
    four.output_path = aside->path();
    four.progress = nullptr;
    four.storage.attributes.clear();
    if (auto baked = bake_moment_pyramid(four); !baked) return baked.error();
    auto colors = TemporaryFile::create("cmfilter-color-pyramid", ".exr");
    if (!colors) return colors.error();
    TableColorPyramidOptions cp = color_pyramid_options(args, four);
    cp.bake.output_path = colors->path();
    if (auto baked = bake_table_color_pyramid(cp, *config); !baked) return baked.error();
    // A segment pyramid for the table's map at the same tolerance, where at
    // most 64 channels meet it (else it is no candidate: said in skipped).
    auto segments = TemporaryFile::create("cmfilter-segments", ".exr");
    if (!segments) return segments.error();
    TableSegmentPyramidOptions sp = segment_pyramid_options(args, four);
    sp.bake.output_path = segments->path();
    sp.bake.tolerance_de = *args.tolerance;
    sp.bake.max_channels = kToleranceSegmentChannels;
    sp.table_paths = {args.table};
    const bool have_segments = args.map.empty() && bake_table_segment_pyramid(sp, *config).has_value();
    ApplyOptions measured;
    measured.moments_path = aside->path();
    measured.table_path = args.table;
    measured.map_path = args.map;
    measured.driver_path = args.driver_path;
    if (histograms) measured.histograms_path = args.histograms;
    measured.threads = args.threads;
    MethodChoiceOptions co;
    co.tolerance = *args.tolerance;
    co.lods = args.measure_lods;
    co.color_pyramid_path = colors->path();
    if (have_segments) co.segment_pyramid_path = segments->path();
    if (progress) co.progress = terminal_progress("bake-moments: measuring the methods");
    auto choice = choose_filter_method(measured, *config, co);
    if (!choice) return choice.error();
    if (!have_segments)
        for (std::string& why : choice->skipped)
            if (why.rfind("segments:", 0) == 0)
                why = "segments: the table's map needs more than " + std::to_string(kToleranceSegmentChannels) +
                      " channels at this tolerance" + (args.map.empty() ? std::string() : " (or --map overrides it)");
    if (!choice->choice()) return no_method_meets(*choice, "'" + args.driver_path + "' through '" + args.table + "'");
    for (std::string& why : choice->skipped)
        why = name_flags(why, {{"ApplyOptions::histograms_path", "--histograms H.exr"}});
    return choice;
}

// What --method color-pyramid (or a tolerance that chose it) wrote.
void report_color_pyramid(const BakeMomentsArgs& args, const ExrOutputOptions& storage, const std::string& digest,
                          const TableColorPyramid& baked, const std::optional<HistogramPyramidInfo>& histograms,
                          const std::optional<MethodChoice>& choice, double total_ms)
{
    const ColorPyramidInfo& info = baked.result.info;
    if (args.json) {
        nlohmann::json j;
        j["output"] = args.output;
        j["storage"] = storage_json(storage);
        j["up_to_date"] = false;
        j["build"] = digest;
        j["kind"] = kColorPyramidKind;
        j["size"] = {info.width, info.height};
        j["levels"] = info.levels;
        j["channel"] = info.channel;
        j["driver_range"] = {info.driver_min, info.driver_max};
        j["wrap"] = to_string(info.wrap);
        j["nonfinite_replaced"] = info.nonfinite_replaced;
        j["source"] = info.source;
        j["source_sha256"] = info.source_sha256;
        j["map"] = baked.map_path;
        j["map_sha256"] = info.map_sha256;
        j["linear_space"] = info.linear_space;
        j["bytes_per_texel"] = info.bytes_per_texel();
        if (histograms) j["histograms"] = {{"output", args.histograms}, {"values", histograms->values}};
        if (choice) j["choice"] = method_choice_json(*choice);
        j["time_ms"] = {{"read", baked.result.read_ms},
                        {"build", baked.result.build_ms},
                        {"write", baked.result.write_ms},
                        {"total", total_ms}};
        print_json("bake-moments", std::move(j));
        return;
    }
    if (args.quiet) return;
    std::cout << std::setprecision(9) << "wrote " << args.output << ": colour pyramid, " << info.width << " x "
              << info.height << ", " << info.levels << " levels\n"
              << "  driver     " << info.source << " (channel " << info.channel << "), range [" << info.driver_min
              << ", " << info.driver_max << "]\n"
              << "  map        " << baked.map_path << " (digest " << info.map_sha256.substr(0, 12)
              << "; apply refuses another)\n"
              << "  channels   R, G, B = box mean of C0(f) per texel, " << info.linear_space << "\n"
              << "  wrap       " << to_string(info.wrap) << "\n"
              << "  storage    " << exr_output_text(storage, "64 x 64 tiles") << ", " << info.bytes_per_texel()
              << " bytes per texel\n";
    if (histograms)
        std::cout << "  histograms " << args.histograms << ": " << histograms->values.size()
                  << " distinct values (exact method)\n";
    if (choice) print_method_choice(std::cout, *choice);
    if (info.nonfinite_replaced > 0)
        std::cout << "  non-finite " << info.nonfinite_replaced << " texels replaced by 0\n";
    std::cout << std::setprecision(3) << "  time       read " << baked.result.read_ms << " ms, build "
              << baked.result.build_ms << " ms, write " << baked.result.write_ms << " ms\n";
}

std::string short_text(double v)
{
    std::ostringstream s;
    s << std::setprecision(6) << v;
    return s.str();
}

// What --segments wrote.
void report_segment_pyramid(const BakeMomentsArgs& args, const ExrOutputOptions& storage, const std::string& digest,
                            const TableSegmentPyramid& baked, const std::optional<MethodChoice>& choice,
                            double total_ms)
{
    const SegmentPyramidInfo& info = baked.result.info;
    const BreakpointSelection& sel = baked.result.selection;
    if (args.json) {
        nlohmann::json j;
        j["output"] = args.output;
        j["storage"] = storage_json(storage);
        j["up_to_date"] = false;
        j["build"] = digest;
        j["kind"] = kSegmentPyramidKind;
        j["size"] = {info.width, info.height};
        j["levels"] = info.levels;
        j["channel"] = info.channel;
        j["driver_range"] = {info.driver_min, info.driver_max};
        j["wrap"] = to_string(info.wrap);
        j["nonfinite_replaced"] = info.nonfinite_replaced;
        j["source"] = info.source;
        j["source_sha256"] = info.source_sha256;
        j["breakpoints"] = info.breakpoints;
        j["channels"] = info.channels();
        j["candidates"] = sel.candidates;
        j["tolerance"] = info.tolerance_de;
        j["filtered_de"] = info.filtered_fit_de;
        nlohmann::json maps = nlohmann::json::array();
        for (std::size_t m = 0; m < baked.map_paths.size(); ++m)
            maps.push_back({{"table", args.segments[m]},
                            {"map", baked.map_paths[m]},
                            {"fit_de", sel.fits[m].max_de},
                            {"mean_de", sel.mean_de[m]},
                            {"worst_f", sel.fits[m].worst_f}});
        j["maps"] = std::move(maps);
        j["bytes_per_texel"] = info.bytes_per_texel();
        if (choice) j["choice"] = method_choice_json(*choice);
        j["time_ms"] = {{"read", baked.result.read_ms},
                        {"select", baked.result.select_ms},
                        {"build", baked.result.build_ms},
                        {"write", baked.result.write_ms},
                        {"total", total_ms}};
        print_json("bake-moments", std::move(j));
        return;
    }
    if (args.quiet) return;
    std::cout << std::setprecision(9) << "wrote " << args.output << ": segment pyramid, " << info.width << " x "
              << info.height << ", " << info.levels << " levels\n"
              << "  driver     " << info.source << " (channel " << info.channel << "), range [" << info.driver_min
              << ", " << info.driver_max << "]\n"
              << std::setprecision(6) << "  segments   " << info.breakpoints.size() << " breakpoints of "
              << sel.candidates << " ("
              << (info.tolerance_de > 0 ? "the fewest within a mean CIEDE2000 of " + short_text(info.tolerance_de)
                                        : std::string("every exact breakpoint"))
              << "): " << info.channels() << " channels s001.. = box means of the ramps r_k(f)\n";
    for (std::size_t m = 0; m < baked.map_paths.size(); ++m)
        std::cout << "  map        " << baked.map_paths[m] << ": through the breakpoints, mean CIEDE2000 "
                  << sel.mean_de[m] << " over the driver, largest " << sel.fits[m].max_de
                  << " (at f = " << sel.fits[m].worst_f << ")\n";
    if (info.tolerance_de > 0)
        std::cout << "  levels     1..8: mean CIEDE2000 of the box means against C0's at most " << info.filtered_fit_de
                  << "\n";
    std::cout << "  recolour   apply --method segments takes any map that fits these breakpoints\n"
              << "  wrap       " << to_string(info.wrap) << "\n"
              << "  storage    " << exr_output_text(storage, "64 x 64 tiles") << ", " << info.bytes_per_texel()
              << " bytes per texel\n";
    if (choice) print_method_choice(std::cout, *choice);
    if (info.nonfinite_replaced > 0)
        std::cout << "  non-finite " << info.nonfinite_replaced << " texels replaced by 0\n";
    std::cout << std::setprecision(3) << "  time       read " << baked.result.read_ms << " ms, select "
              << baked.result.select_ms << " ms, build " << baked.result.build_ms << " ms, write "
              << baked.result.write_ms << " ms\n";
}

Status run(const BakeMomentsArgs& args, const CLI::App& app)
{
    if (auto st = check_output_path(args.output, ".exr"); !st) return st;
    if (!args.histograms.empty())
        if (auto st = check_output_path(args.histograms, ".exr"); !st) return st;
    auto wrap = parse_texture_wrap(args.wrap);
    if (!wrap) return wrap.error();
    auto nan = parse_non_finite_policy(args.nan);
    if (!nan) return nan.error();
    auto storage = exr_output_options_from_args(args.storage);
    if (!storage) return storage.error();
    // The histogram pyramid is an output: its path is not a parameter.
    auto digest = build_digest(app, {"--histograms"}, "");
    if (!digest) return digest.error();
    std::vector<std::string> outputs = {args.output};
    if (!args.histograms.empty()) outputs.push_back(args.histograms);
    if (args.update && outputs_record_build(outputs, *digest)) {
        report_up_to_date("bake-moments", outputs, *digest, args.json, args.quiet);
        return ok();
    }
    // Either output made alone (with or without --histograms) records the same build.
    storage->attributes.emplace_back(kBuildRecordAttribute, *digest);

    MomentBakeOptions options;
    options.driver_path = args.driver_path;
    options.output_path = args.output;
    options.channel = args.channel;
    options.wrap = *wrap;
    options.nonfinite = *nan;
    options.threads = args.threads;
    options.order = args.order;
    options.storage = *storage;
    const bool progress = !args.quiet && !args.json && isatty(STDERR_FILENO);
    if (progress) options.progress = terminal_progress("bake-moments");
    if (args.tolerance && !args.method.empty() && args.method != "segments")
        return bad_input("--tolerance chooses the method itself (expected --tolerance or --method " + args.method +
                         ", not both; with --segments it chooses breakpoints)");
    if (!args.segments.empty() || args.method == "segments") {
        if (args.segments.empty())
            return bad_input("--method segments bakes the breakpoints of colour maps: give their tables with "
                             "--segments T.exr[,T2.exr,...] (bake-colormap)");
        auto config = load_color_config(args.ocio_config);
        if (!config) return config.error();
        const TableSegmentPyramidOptions sp = segment_pyramid_options(args, options);
        const Stopwatch t0;
        auto baked = bake_table_segment_pyramid(sp, *config);
        if (!baked) {
            if (progress) std::cerr << "\n";
            return baked.error();
        }
        for (const std::string& w : baked->warnings) std::cerr << "cmfilter bake-moments: warning: " << w << "\n";
        report_segment_pyramid(args, *storage, *digest, *baked, std::nullopt, t0.elapsed_ms());
        return ok();
    }
    if (args.tolerance && args.table.empty())
        return bad_input("MethodChoiceOptions::tolerance needs the colour table to measure against "
                         "(ApplyOptions::table_path)",
                         "ApplyOptions::table_path");
    bool color_pyramid = false;
    if (!args.method.empty()) {
        auto method = parse_filter_method(args.method);
        if (!method) return method.error();
        if (*method == FilterMethod::Exact || *method == FilterMethod::Reference)
            return bad_input("--method " + args.method +
                             " reads no baked pyramid of its own (expected naive, gaussian, mixture or color-pyramid; "
                             "exact reads --histograms H.exr)");
        options.order = *method == FilterMethod::Mixture ? 4 : 2;
        color_pyramid = *method == FilterMethod::ColorPyramid;
        if (color_pyramid && args.table.empty())
            return bad_input("--method color-pyramid bakes C0(f) through a colour map: give its table with --table "
                             "T.exr (bake-colormap)");
    }
    const Stopwatch t0;
    // The histogram pyramid first: it is the one refused for a driver with
    // too many distinct values, and then neither file is written.
    std::optional<HistogramPyramidInfo> histograms;
    if (!args.histograms.empty()) {
        HistogramBakeOptions h;
        static_cast<PyramidBakeOptions&>(h) = options;  // the same driver, wrap and threads
        h.output_path = args.histograms;
        auto baked = bake_histogram_pyramid(h);
        if (!baked) return baked.error();
        histograms = std::move(*baked);
    }
    // With a tolerance: order-4 moments baked aside, every method measured
    // against the box reference (ops/method_choice.h), and the pyramid the
    // cheapest that meets it needs written (order 4 for mixture, else 2).
    std::optional<MethodChoice> choice;
    if (args.tolerance) {
        auto chosen = choose_moment_order(args, options, histograms.has_value(), progress);
        if (!chosen) {
            if (histograms) std::remove(args.histograms.c_str());
            return chosen.error();
        }
        choice = std::move(*chosen);
        const MethodTrial& c = *choice->choice();
        options.order = c.method == FilterMethod::Mixture ? 4 : 2;
        options.method_choice = MethodToleranceRecord{to_string(c.method), choice->tolerance, c.worst,
                                                      lod_list_text(choice->lods), args.table};
    }
    if (choice && choice->choice()->method == FilterMethod::Segments) {
        auto config = load_color_config(args.ocio_config);
        if (!config) return config.error();
        TableSegmentPyramidOptions sp = segment_pyramid_options(args, options);
        sp.bake.max_channels = kToleranceSegmentChannels;
        sp.table_paths = {args.table};
        sp.bake.method_choice = options.method_choice;
        auto baked = bake_table_segment_pyramid(sp, *config);
        if (!baked) {
            if (histograms) std::remove(args.histograms.c_str());  // all or nothing
            return baked.error();
        }
        BakeMomentsArgs shown = args;
        shown.segments = {args.table};
        report_segment_pyramid(shown, *storage, *digest, *baked, choice, t0.elapsed_ms());
        return ok();
    }
    if (choice && choice->choice()->method == FilterMethod::ColorPyramid) color_pyramid = true;
    if (color_pyramid) {
        auto config = load_color_config(args.ocio_config);
        if (!config) return config.error();
        TableColorPyramidOptions cp = color_pyramid_options(args, options);
        if (choice) cp.bake.method_choice = options.method_choice;
        auto baked = bake_table_color_pyramid(cp, *config);
        if (!baked) {
            if (progress) std::cerr << "\n";
            if (histograms) std::remove(args.histograms.c_str());  // all or nothing
            return baked.error();
        }
        for (const std::string& w : baked->warnings) std::cerr << "cmfilter bake-moments: warning: " << w << "\n";
        report_color_pyramid(args, *storage, *digest, *baked, histograms, choice, t0.elapsed_ms());
        return ok();
    }
    auto baked = bake_moment_pyramid(options);
    if (!baked) {
        if (progress) std::cerr << "\n";
        if (histograms) std::remove(args.histograms.c_str());  // all or nothing
        return baked.error();
    }
    const double total_ms = t0.elapsed_ms();
    const MomentPyramidInfo& info = baked->info;

    if (args.json) {
        nlohmann::json j;
        j["output"] = args.output;
        j["storage"] = storage_json(*storage);
        j["up_to_date"] = false;
        j["build"] = *digest;
        j["kind"] = kMomentPyramidKind;
        j["size"] = {info.width, info.height};
        j["levels"] = info.levels;
        j["order"] = info.order;
        j["channel"] = info.channel;
        j["reference"] = info.reference;
        j["driver_range"] = {info.driver_min, info.driver_max};
        j["wrap"] = to_string(info.wrap);
        j["nonfinite_replaced"] = info.nonfinite_replaced;
        j["source"] = info.source;
        j["source_sha256"] = info.source_sha256;
        if (histograms) j["histograms"] = {{"output", args.histograms}, {"values", histograms->values}};
        if (choice) j["choice"] = method_choice_json(*choice);
        j["time_ms"] = {
            {"read", baked->read_ms}, {"build", baked->build_ms}, {"write", baked->write_ms}, {"total", total_ms}};
        print_json("bake-moments", std::move(j));
    } else if (!args.quiet) {
        std::cout << std::setprecision(9) << "wrote " << args.output << ": moment pyramid, " << info.width << " x "
                  << info.height << ", " << info.levels << " levels\n"
                  << "  driver     " << info.source << " (channel " << info.channel << ", " << info.source_pixel_type
                  << "), range [" << info.driver_min << ", " << info.driver_max << "]\n"
                  << "  reference  c = " << info.reference
                  << (info.order == 4 ? " (channels: means of (f - c)^k, k = 1..4)\n"
                                      : " (channels: mean of f - c, mean of (f - c)^2)\n")
                  << "  wrap       " << to_string(info.wrap) << "\n"
                  << "  storage    " << exr_output_text(*storage, "64 x 64 tiles") << "\n";
        if (storage->pixel_type == ExrPixelType::Half)
            std::cout << "             half moments lose sigma at fine LODs: see docs/storage.md\n";
        if (histograms)
            std::cout << "  histograms " << args.histograms << ": " << histograms->values.size()
                      << " distinct values (exact method)\n";
        if (choice) print_method_choice(std::cout, *choice);
        if (info.nonfinite_replaced > 0)
            std::cout << "  non-finite " << info.nonfinite_replaced << " texels replaced by 0\n";
        std::cout << std::setprecision(3) << "  time       read " << baked->read_ms << " ms, build " << baked->build_ms
                  << " ms, write " << baked->write_ms << " ms\n";
    }
    return ok();
}

}  // namespace

Command setup_bake_moments(CLI::App& parent)
{
    auto args = std::make_shared<BakeMomentsArgs>();
    CLI::App* app = parent.add_subcommand(
        "bake-moments", "Bake a driver's moment pyramid: per MIP level the box means of f and f^2 (sec. 4.2)");
    app->add_option("DRIVER", args->driver_path,
                    "Driver texture: any image OpenImageIO reads, used as data (no colour conversion)")
        ->required();
    app->add_option("-o,--output", args->output, "Moment pyramid to write (.exr)")->required();
    app->add_option("--histograms", args->histograms,
                    "Also write the driver's histogram pyramid (.exr) for apply --method exact "
                    "(at most 256 distinct values)");
    app->add_option("--channel", args->channel,
                    "Driver channel, by name or 0-based index (required for multi-channel images)");
    app->add_option("--wrap", args->wrap, "Lookups beyond the edges: black, clamp or periodic")->capture_default_str();
    app->add_option("--nan", args->nan, "NaN/Inf texels: error (refuse the driver) or zero (replace by 0 and count)")
        ->capture_default_str();
    app->add_option("--threads", args->threads, "Threads (0: all cores)")->capture_default_str();
    CLI::Option* order =
        app->add_option("--order", args->order,
                        "Moments per texel: 2 (f, f^2: gaussian) or 4 (also f^3, f^4: apply --method mixture)")
            ->capture_default_str();
    app->add_option("--method", args->method,
                    "Bake what this apply method reads: naive or gaussian (2 moments), mixture (4), or "
                    "color-pyramid (C0(f) box-mipped through --table's map: exact, 3 channels, that map only), "
                    "or segments (with --segments)")
        ->excludes(order);
    app->add_option("--tolerance", args->tolerance,
                    "Bake what the cheapest method meeting this mean CIEDE2000 against the box reference through "
                    "--table at every measured LOD reads (naive, gaussian: 2 moments; color-pyramid; mixture: 4; "
                    "exact with --histograms)")
        ->excludes(order);
    CLI::Option* segments =
        app->add_option("--segments", args->segments,
                        "Bake a segment pyramid (apply --method segments) for the breakpoints of these tables' maps "
                        "(T.exr[,T2.exr,...]): exact for any colours on them; with --tolerance DE, the fewest "
                        "breakpoints keeping every map within DE (CIEDE2000) of itself")
            ->delimiter(',')
            ->excludes(order)
            ->excludes("--histograms");
    app->add_option("--max-channels", args->max_channels,
                    "With --segments: at most this many channels (breakpoints - 1); refused, naming the tolerance "
                    "that fits, when the maps need more (0: no limit)")
        ->needs(segments);
    app->add_option("--table", args->table, "Gaussian colour table --tolerance measures through (bake-colormap)")
        ->excludes(segments);
    app->add_option("--map", args->map, "Colour map image for --tolerance (default: the table's cmfilter:source)");
    add_measure_lods_option(*app, args->measure_lods);
    app->add_option("--ocio-config,--colorconfig", args->ocio_config,
                    "OpenColorIO config for --tolerance's colour map (default: $OCIO if set, else built-in)");
    add_exr_output_options(*app, args->storage, "64 64");
    app->add_flag("--json", args->json, "Print a machine-readable summary on stdout");
    app->add_flag("-q,--quiet", args->quiet, "Print nothing on success (and no progress)");
    add_update_option(*app, args->update);
    FieldFlags flags = exr_output_flags();
    const FieldFlags map_flags = color_map_flags();
    flags.insert(flags.end(), map_flags.begin(), map_flags.end());
    flags.insert(flags.end(), {{"DriverReadOptions::channel", "--channel"},
                               {"DriverReadOptions::nonfinite", "--nan"},
                               {"MomentBakeOptions::order", "--order"},
                               {"MethodChoiceOptions::tolerance", "--tolerance"},
                               {"SegmentPyramidBakeOptions::max_channels", "--max-channels"},
                               {"SegmentPyramidBakeOptions::tolerance_de", "--tolerance"},
                               {"MethodChoiceOptions::lods", "--measure-lods"},
                               {"ApplyOptions::table_path", "--table"},
                               {"ApplyOptions::histograms_path", "--histograms H.exr"}});
    return {app, [args, app] { return run(*args, *app); }, flags};
}

}  // namespace cmfilter::cli
