// SPDX-License-Identifier: Apache-2.0
// cmfilter noise-image: a procedural noise sampled at pixel centres into a
// single-channel float EXR driver (docs/noise.md), for bake-moments and apply.
#include "command.h"

#include "cmfilter/util/atomic_output.h"
#include "cmfilter/noise/noise_image.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <iostream>
#include <memory>

namespace cmfilter::cli {

namespace {

struct NoiseImageArgs {
    std::string noise;
    std::string size;
    double scale = 1.0 / 16.0;
    std::string output;
    int threads = 0;
    bool json = false;
    bool quiet = false;
};

Status run(const NoiseImageArgs& args)
{
    if (auto st = check_output_path(args.output, ".exr"); !st) return st;
    auto spec = parse_noise_spec(args.noise);
    if (!spec) return spec.error();
    auto size = parse_size("--size", args.size);
    if (!size) return size.error();
    if (!(args.scale > 0) || !std::isfinite(args.scale))
        return bad_input("--scale " + std::to_string(args.scale) + " is invalid (expected a finite value > 0)");
    NoiseImageOptions options;
    options.spec = *spec;
    options.width = size->first;
    options.height = size->second;
    options.scale = args.scale;
    options.threads = args.threads;
    if (auto st = write_noise_image(args.output, options); !st) return st;

    if (args.json) {
        nlohmann::json j;
        j["output"] = args.output;
        j["kind"] = kNoiseImageKind;
        j["size"] = {options.width, options.height};
        j["scale"] = options.scale;
        j["noise"] = to_string(options.spec);
        print_json("noise-image", std::move(j));
    } else if (!args.quiet) {
        std::cout << "wrote " << args.output << ": noise image, " << options.width << " x " << options.height << ", "
                  << options.scale << " noise units per pixel\n"
                  << "  noise " << to_string(options.spec) << "\n";
    }
    return ok();
}

}  // namespace

Command setup_noise_image(CLI::App& parent)
{
    auto args = std::make_shared<NoiseImageArgs>();
    CLI::App* app = parent.add_subcommand(
        "noise-image", "Sample a procedural noise at pixel centres into a float EXR driver (channel Y)");
    app->add_option("--noise", args->noise, "Noise spec, e.g. fbm:base=gradient,octaves=6,seed=1 (docs/noise.md)")
        ->required();
    app->add_option("--size", args->size, "Image size WxH")->required();
    app->add_option("--scale", args->scale, "Noise units per pixel")->capture_default_str();
    app->add_option("-o,--output", args->output, "Image to write (.exr)")->required();
    app->add_option("--threads", args->threads, "Threads (0: all cores)")->capture_default_str();
    app->add_flag("--json", args->json, "Print a machine-readable summary on stdout");
    app->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
    return {app, [args] { return run(*args); }, {}};
}

}  // namespace cmfilter::cli
