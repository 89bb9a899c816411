// SPDX-License-Identifier: Apache-2.0
// cmfilter compare: RMSE and CIEDE2000 (mean, p95, max) between two images of
// the same size, both in scene-linear, with an optional per-pixel heat map.
#include "command.h"

#include "cmfilter/ops/image_comparison.h"

#include <nlohmann/json.hpp>

#include <iomanip>
#include <iostream>
#include <memory>

namespace cmfilter::cli {

namespace {

struct CompareArgs {
    ImageComparisonOptions options;  // the options bind straight to its fields
    std::string ocio_config;
    bool json = false;
    bool quiet = false;
};

nlohmann::json image_json(const ComparedImage& image)
{
    return {{"path", image.path},
            {"channels", image.channels},
            {"pixel_type", image.pixel_type},
            {"colorspace", image.colorspace},
            {"colorspace_rule", image.colorspace_rule}};
}

void print_table(const ImageComparison& c)
{
    std::cout << "compared " << c.a.path << " and " << c.b.path << ": " << c.width << " x " << c.height << ", "
              << c.pixels << " pixels, R G B in " << c.linear_space << "\n";
    for (const ComparedImage* image : {&c.a, &c.b})
        std::cout << "  " << (image == &c.a ? "A" : "B") << "  " << image->path << ": " << image->channels
                  << " channels " << image->pixel_type << ", " << image->colorspace << " (" << image->colorspace_rule
                  << ")\n";
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

Status run(const CompareArgs& args)
{
    auto config = load_color_config(args.ocio_config);
    if (!config) return config.error();
    auto c = compare_images(args.options, *config);
    if (!c) return c.error();

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
        std::cout << j.dump(2) << "\n";
    } else if (!args.quiet) {
        print_table(*c);
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
    app->add_option("--ocio-config", args->ocio_config,
                    "OpenColorIO config (default: $OCIO if set, else the built-in config)");
    auto* heatmap = app->add_option("--heatmap", args->options.heatmap_path,
                                    "Write the per-pixel CIEDE2000 as an 8-bit sRGB PNG (black, red, yellow, white)");
    app->add_option("--heatmap-max", args->options.heatmap_max,
                    "CIEDE2000 drawn as white in the heat map; larger errors saturate")
        ->capture_default_str()
        ->needs(heatmap);
    app->add_option("--threads", args->options.threads, "Threads (0: all cores)")->capture_default_str();
    app->add_flag("--json", args->json, "Print the results as JSON on stdout");
    app->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
    return {app, [args] { return run(*args); }, {{"ImageComparisonOptions::heatmap_max", "--heatmap-max"}}};
}

}  // namespace cmfilter::cli
