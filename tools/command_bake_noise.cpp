// SPDX-License-Identifier: Apache-2.0
// cmfilter bake-noise: a procedural noise -> its sigma table, the standard
// deviation a footprint of each LOD leaves unresolved (Heitz et al. 2013,
// sec. 4.2), measured by Monte-Carlo with confidence intervals
// (docs/bake-noise.md).
#include "command.h"

#include "cmfilter/io/build_record.h"

#include "cmfilter/util/atomic_output.h"
#include "cmfilter/noise/noise_sigma_bake.h"
#include "cmfilter/noise/noise_sigma_table_file.h"
#include "cmfilter/noise/noise_spec.h"
#include "cmfilter/util/stopwatch.h"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>

namespace cmfilter::cli {

namespace {

struct BakeNoiseArgs {
    std::string noise;
    std::string output;
    std::string csv;
    double lod_step = 0.25;
    std::uint64_t sample_seed = 1;
    int max_footprints = 1 << 16;
    int threads = 0;
    ExrOutputArgs storage;
    bool json = false;
    bool quiet = false;
    bool update = false;
};

nlohmann::json estimate_json(const SigmaEstimate& e)
{
    return {
        {"sigma", e.sigma}, {"ci", e.half_width}, {"footprints", e.footprints}, {"samples", e.samples_per_footprint}};
}

Status run(const BakeNoiseArgs& args, const CLI::App& app)
{
    if (auto st = check_output_path(args.output, ".exr"); !st) return st;
    if (!args.csv.empty())
        if (auto st = check_output_path(args.csv, ".csv"); !st) return st;
    if (!(args.lod_step > 0) || !std::isfinite(args.lod_step) || args.lod_step > 4)
        return bad_input("--lod-step " + std::to_string(args.lod_step) +
                         " is invalid (expected a finite value in (0, 4])");
    if (args.max_footprints < 1024)
        return bad_input("--max-footprints " + std::to_string(args.max_footprints) + " is invalid (expected >= 1024)");
    auto storage = exr_output_options_from_args(args.storage);
    if (!storage) return storage.error();
    // The CSV is a second output, not a parameter; -u needs the table only.
    auto digest = build_digest(app, {"--csv"}, "");
    if (!digest) return digest.error();
    if (args.update && outputs_record_build({args.output}, *digest) &&
        (args.csv.empty() || std::filesystem::is_regular_file(args.csv))) {
        report_up_to_date("bake-noise", {args.output}, *digest, args.json, args.quiet);
        return ok();
    }
    storage->attributes.emplace_back(kBuildRecordAttribute, *digest);
    auto spec = parse_noise_spec(args.noise);
    if (!spec) return spec.error();
    auto noise = make_noise(*spec);
    if (!noise) return noise.error();

    NoiseSigmaBakeOptions options;
    options.lod_step = args.lod_step;
    options.seed = args.sample_seed;
    options.max_footprints = args.max_footprints;
    options.threads = args.threads;
    const bool progress = !args.quiet && !args.json && isatty(STDERR_FILENO);
    if (progress) options.progress = terminal_progress("bake-noise");
    const Stopwatch t0;
    auto bake = bake_noise_sigma(*noise, options);
    if (!bake) return bake.error();
    const std::string spec_text = to_string(*spec);
    if (auto st = write_noise_sigma_table(args.output, *bake, spec_text, noise->base_period(), *storage); !st)
        return st;
    if (!args.csv.empty())
        if (auto st = write_noise_sigma_csv(args.csv, *bake, noise->base_period()); !st) {
            std::remove(args.output.c_str());  // all or nothing
            return st;
        }
    const double total_ms = t0.elapsed_ms();
    const NoiseGlobalStats& g = bake->global;

    if (args.json) {
        nlohmann::json j;
        j["output"] = args.output;
        j["storage"] = storage_json(*storage);
        j["up_to_date"] = false;
        j["build"] = *digest;
        if (!args.csv.empty()) j["csv"] = args.csv;
        j["kind"] = kNoiseSigmaTableKind;
        j["noise"] = spec_text;
        j["base_period"] = noise->base_period();
        j["lod_first"] = bake->lod_first;
        j["lod_step"] = bake->lod_step;
        j["global"] = {{"samples", g.samples},
                       {"mean", g.mean},
                       {"sigma", g.sigma},
                       {"skewness", g.skewness},
                       {"excess_kurtosis", g.excess_kurtosis}};
        for (const auto& r : bake->rows)
            j["lods"].push_back(
                {{"lod", r.lod}, {"box", estimate_json(r.box)}, {"gaussian", estimate_json(r.gaussian)}});
        j["time_ms"] = total_ms;
        print_json("bake-noise", std::move(j));
    } else if (!args.quiet) {
        double worst = 0;
        for (const auto& r : bake->rows)
            for (const SigmaEstimate* e : {&r.box, &r.gaussian})
                if (e->sigma > 0) worst = std::max(worst, e->half_width / e->sigma);
        std::cout << std::setprecision(6) << "wrote " << args.output << ": noise sigma table, " << bake->rows.size()
                  << " LODs from " << bake->lod_first << " in steps of " << bake->lod_step << "\n"
                  << "  noise   " << spec_text << " (base period " << noise->base_period() << ")\n"
                  << "  global  mean " << g.mean << ", sigma " << g.sigma << ", skewness " << g.skewness
                  << ", excess kurtosis " << g.excess_kurtosis << " (" << g.samples << " samples)\n"
                  << "  CI      worst 95% half-width " << 100 * worst << "% of sigma\n";
        if (!args.csv.empty()) std::cout << "  csv     " << args.csv << "\n";
        std::cout << "  storage " << exr_output_text(*storage, "scanlines") << "\n";
        std::cout << std::setprecision(3) << "  time    " << total_ms << " ms\n";
    }
    return ok();
}

}  // namespace

Command setup_bake_noise(CLI::App& parent)
{
    auto args = std::make_shared<BakeNoiseArgs>();
    CLI::App* app = parent.add_subcommand(
        "bake-noise", "Bake a procedural noise's sigma table: unresolved standard deviation per LOD (sec. 4.2)");
    app->add_option("--noise", args->noise, "Noise spec, e.g. fbm:base=gradient,octaves=6,seed=1 (docs/noise.md)")
        ->required();
    app->add_option("-o,--output", args->output, "Sigma table to write (.exr)")->required();
    app->add_option("--csv", args->csv, "Also write the table as CSV (.csv)");
    app->add_option("--lod-step", args->lod_step, "LOD spacing of the table")->capture_default_str();
    app->add_option("--sample-seed", args->sample_seed, "Seed of the Monte-Carlo sampling")->capture_default_str();
    app->add_option("--max-footprints", args->max_footprints, "Cap on footprints per LOD")->capture_default_str();
    app->add_option("--threads", args->threads, "Threads (0: all cores)")->capture_default_str();
    add_exr_output_options(*app, args->storage, "scanlines");
    app->add_flag("--json", args->json, "Print a machine-readable summary on stdout");
    app->add_flag("-q,--quiet", args->quiet, "Print nothing on success (and no progress)");
    add_update_option(*app, args->update);
    return {app, [args, app] { return run(*args, *app); }, exr_output_flags()};
}

}  // namespace cmfilter::cli
