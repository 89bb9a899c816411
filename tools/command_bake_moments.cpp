// SPDX-License-Identifier: Apache-2.0
// cmfilter bake-moments: driver texture -> moment pyramid, per level the box
// means of (f - c) and (f - c)^2 (Heitz et al. 2013, sec. 4.2) in a tiled,
// MIP-mapped EXR that OpenImageIO's TextureSystem reads.
#include "command.h"

#include "cmfilter/io/build_record.h"

#include "cmfilter/util/stopwatch.h"

#include "cmfilter/util/atomic_output.h"
#include "cmfilter/texture/histogram_pyramid.h"
#include "cmfilter/texture/moment_pyramid.h"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <optional>
#include <iomanip>
#include <iostream>
#include <memory>

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
    ExrOutputArgs storage;
    bool json = false;
    bool quiet = false;
    bool update = false;
};

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
    app->add_option("--order", args->order,
                    "Moments per texel: 2 (f, f^2: gaussian) or 4 (also f^3, f^4: apply --method mixture)")
        ->capture_default_str();
    add_exr_output_options(*app, args->storage, "64 64");
    app->add_flag("--json", args->json, "Print a machine-readable summary on stdout");
    app->add_flag("-q,--quiet", args->quiet, "Print nothing on success (and no progress)");
    add_update_option(*app, args->update);
    FieldFlags flags = exr_output_flags();
    flags.insert(flags.end(), {{"DriverReadOptions::channel", "--channel"},
                               {"DriverReadOptions::nonfinite", "--nan"},
                               {"MomentBakeOptions::order", "--order"}});
    return {app, [args, app] { return run(*args, *app); }, flags};
}

}  // namespace cmfilter::cli
