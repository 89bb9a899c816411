// SPDX-License-Identifier: Apache-2.0
// cmfilter compare: RMSE and CIEDE2000 (mean, p95, max) between two images of
// the same size, both in scene-linear, with an optional per-pixel heat map.
#include "command.h"

#include "cmfilter/color/error_summary.h"
#include "cmfilter/ops/image_comparison.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

namespace cmfilter::cli {

namespace {

// The flags of the fields compare's library calls may name.
FieldFlags compare_flags()
{
    return {{"ImageComparisonOptions::heatmap_max", "--heatmap-max"},
            {"ImageComparisonOptions::colorspace_a", "--colorspace-a"},
            {"ImageComparisonOptions::colorspace_b", "--colorspace-b"}};
}

struct CompareArgs {
    ImageComparisonOptions options;  // the options bind straight to its fields
    std::string ocio_config;
    bool json = false;
    bool quiet = false;
    // Build gates, as idiff's -warn / -fail: thresholds on one CIEDE2000
    // statistic; the run's exit code says which was exceeded.
    std::optional<double> warn, fail;
    std::string gate_statistic = "max";
    int exit_code = 0;
};

// Exit codes of the gates (docs/exit-codes.md), after the error codes 1-4.
constexpr int kExitWarn = 5;
constexpr int kExitFail = 6;

Expected<double> gate_value(const ErrorSummary& de, const std::string& statistic)
{
    if (statistic == "mean") return de.mean;
    if (statistic == "p95") return de.p95;
    if (statistic == "max") return de.max;
    return bad_input("--gate '" + statistic + "' is unknown (expected mean, p95 or max)");
}

Status check_threshold(const char* flag, const std::optional<double>& v)
{
    if (v && !(std::isfinite(*v) && *v >= 0)) {
        std::ostringstream msg;
        msg << flag << " " << *v << " is invalid (expected a CIEDE2000 difference >= 0)";
        return bad_input(msg.str());
    }
    return ok();
}

struct GateResult {
    std::string result = "pass";  // pass, warn, fail
    double value = 0;
};

nlohmann::json image_json(const ComparedImage& image)
{
    return {{"path", image.path},
            {"channels", image.channels},
            {"pixel_type", image.pixel_type},
            {"colorspace", image.colorspace},
            {"colorspace_rule", name_flags(image.colorspace_rule, compare_flags())}};
}

void print_table(const ImageComparison& c)
{
    std::cout << "compared " << c.a.path << " and " << c.b.path << ": " << c.width << " x " << c.height << ", "
              << c.pixels << " pixels, R G B in " << c.linear_space << "\n";
    for (const ComparedImage* image : {&c.a, &c.b})
        std::cout << "  " << (image == &c.a ? "A" : "B") << "  " << image->path << ": " << image->channels
                  << " channels " << image->pixel_type << ", " << image->colorspace << " ("
                  << name_flags(image->colorspace_rule, compare_flags()) << ")\n";
    const auto row = [](const char* name, double value) {
        std::cout << "  " << std::left << std::setw(16) << name << std::right << std::setw(12) << std::setprecision(6)
                  << value << "\n";
    };
    std::cout << "  " << std::left << std::setw(16) << "metric" << std::right << std::setw(12) << "value"
              << "\n";
    row("RMSE", c.rmse);
    row("RMSE R", c.rmse_rgb[0]);
    row("RMSE G", c.rmse_rgb[1]);
    row("RMSE B", c.rmse_rgb[2]);
    row("dE2000 mean", c.de2000.mean);
    row("dE2000 p95", c.de2000.p95);
    row("dE2000 max", c.de2000.max);
    if (!c.heatmap_path.empty())
        std::cout << "wrote " << c.heatmap_path << ": CIEDE2000 heat map, 0 black, " << c.heatmap_max / 3 << " red, "
                  << 2 * c.heatmap_max / 3 << " yellow, >= " << c.heatmap_max << " white\n";
}

Status run(CompareArgs& args)
{
    if (auto st = check_threshold("--warn", args.warn); !st) return st;
    if (auto st = check_threshold("--fail", args.fail); !st) return st;
    if (auto st = gate_value(ErrorSummary{}, args.gate_statistic); !st) return st.error();
    auto config = load_color_config(args.ocio_config);
    if (!config) return config.error();
    auto c = compare_images(args.options, *config);
    if (!c) return c.error();

    GateResult gate;
    gate.value = *gate_value(c->de2000, args.gate_statistic);
    // Strictly over: a threshold is the largest difference that passes.
    if (args.fail && gate.value > *args.fail) gate.result = "fail";
    else if (args.warn && gate.value > *args.warn) gate.result = "warn";
    args.exit_code = gate.result == "fail" ? kExitFail : gate.result == "warn" ? kExitWarn : 0;

    if (args.json) {
        nlohmann::json j;
        j["a"] = image_json(c->a);
        j["b"] = image_json(c->b);
        j["size"] = {c->width, c->height};
        j["pixels"] = c->pixels;
        j["channels_compared"] = c->channels_compared;
        j["linear_space"] = c->linear_space;
        j["ocio_config"] = c->ocio_config;
        j["rmse"] = c->rmse;
        j["rmse_rgb"] = c->rmse_rgb;
        j["ciede2000"] = {{"mean", c->de2000.mean}, {"p95", c->de2000.p95}, {"max", c->de2000.max}};
        j["heatmap"] = nullptr;
        if (!c->heatmap_path.empty()) j["heatmap"] = {{"path", c->heatmap_path}, {"max", c->heatmap_max}};
        j["gate"] = nullptr;
        if (args.warn || args.fail) {
            j["gate"] = {{"statistic", args.gate_statistic},
                         {"value", gate.value},
                         {"warn", args.warn ? nlohmann::json(*args.warn) : nlohmann::json(nullptr)},
                         {"fail", args.fail ? nlohmann::json(*args.fail) : nlohmann::json(nullptr)},
                         {"result", gate.result},
                         {"exit_code", args.exit_code}};
        }
        print_json("compare", std::move(j));
    } else if (!args.quiet) {
        print_table(*c);
    }
    // A gate that is exceeded says so on stderr, even with --quiet and --json.
    if (gate.result != "pass") {
        const double threshold = gate.result == "fail" ? *args.fail : *args.warn;
        std::cerr << "cmfilter compare: " << (gate.result == "fail" ? "FAIL" : "WARN") << ": CIEDE2000 "
                  << args.gate_statistic << " " << gate.value << " > --" << gate.result << " " << threshold << " ("
                  << c->a.path << " vs " << c->b.path << ")\n";
    } else if ((args.warn || args.fail) && !args.quiet && !args.json) {
        std::cout << "gate passed: CIEDE2000 " << args.gate_statistic << " " << gate.value
                  << " <= " << (args.warn ? "--warn " : "--fail ") << (args.warn ? *args.warn : *args.fail) << "\n";
    }
    return ok();
}

}  // namespace

Command setup_compare(CLI::App& parent)
{
    auto args = std::make_shared<CompareArgs>();
    CLI::App* app =
        parent.add_subcommand("compare", "RMSE and CIEDE2000 (mean, p95, max) between two images, with a heat map");
    app->add_option("A", args->options.path_a, "First image: any image OpenImageIO reads")->required();
    app->add_option("B", args->options.path_b, "Second image, the same size as A")->required();
    app->add_option("--colorspace-a", args->options.colorspace_a,
                    "Colour space of A (default: the file's metadata, else sRGB for integer and "
                    "linear for float files)");
    app->add_option("--colorspace-b", args->options.colorspace_b, "Colour space of B (default: as for A)");
    app->add_option("--ocio-config,--colorconfig", args->ocio_config,
                    "OpenColorIO config (default: $OCIO if set, else the built-in config)");
    auto* heatmap = app->add_option("--heatmap", args->options.heatmap_path,
                                    "Write the per-pixel CIEDE2000 as an 8-bit sRGB PNG (black, red, yellow, white)");
    app->add_option("--heatmap-max", args->options.heatmap_max,
                    "CIEDE2000 drawn as white in the heat map; larger errors saturate")
        ->capture_default_str()
        ->needs(heatmap);
    app->add_option("--threads", args->options.threads, "Threads (0: all cores)")->capture_default_str();
    app->add_flag("--json", args->json, "Print the results as JSON on stdout");
    app->add_option("--warn", args->warn, "Exit 5 when the CIEDE2000 statistic of --gate exceeds DE (as idiff -warn)");
    app->add_option("--fail", args->fail, "Exit 6 when the CIEDE2000 statistic of --gate exceeds DE (as idiff -fail)");
    app->add_option("--gate", args->gate_statistic,
                    "The statistic --warn and --fail test: mean, p95 or max (as idiff, the largest pixel)")
        ->capture_default_str();
    app->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
    return {app, [args] { return run(*args); }, compare_flags(), [args] { return args->exit_code; }};
}

}  // namespace cmfilter::cli
