// cmfilter render: a scene file (docs/scene-format.md) rendered with one
// filtering method (docs/render.md): scene-linear EXR or sRGB PNG/JPEG, and
// with --aov the per-pixel filtered mean, sigma and LOD as float EXRs.
#include "command.h"

#include "cmfilter/render.h"
#include "cmfilter/rgb_image_file.h"
#include "cmfilter/scene_loading.h"
#include "cmfilter/version.h"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <iostream>
#include <memory>

namespace cmfilter::cli {

namespace {

struct RenderArgs {
    std::string scene;
    std::string output;
    std::string method = "gaussian";
    int samples = 16;
    int probes = 16;
    bool no_edge_coverage = false;
    std::uint64_t seed = 0;
    std::string footprint = "rms";
    std::string aov;
    std::string ocio_config;
    int threads = 0;
    bool json = false;
    bool quiet = false;
};

Status write_aov(const std::string& path, const RenderedImage& image, const std::vector<float>& values,
                 const std::string& name, const ColorConfig& config)
{
    ImageAttributes a;
    a.text = {{"cmfilter:kind", "render-aov"}, {"cmfilter:aov", name}, {"cmfilter:version", version()}};
    return write_rgb_image(path, image.width, image.height, 1, values, "", a, config);
}

Status run(const RenderArgs& args)
{
    if (auto st = check_rgb_image_output(args.output); !st) return st;
    auto method = parse_render_method(args.method);
    if (!method) return method.error();
    auto footprint = parse_footprint_width(args.footprint);
    if (!footprint) return footprint.error();
    if (args.samples < 1 || args.samples > kMaxSamples)
        return bad_input("--spp " + std::to_string(args.samples) + " is out of range (expected 1 to " +
                         std::to_string(kMaxSamples) + ")");
    const std::string aov_paths[3] = {args.aov + ".mean.exr", args.aov + ".sigma.exr", args.aov + ".lod.exr"};
    if (!args.aov.empty())
        for (const auto& path : aov_paths)
            if (auto st = check_rgb_image_output(path, true); !st) return st;
    auto scene = load_scene(args.scene);
    if (!scene) return scene.error();
    auto config = load_color_config(args.ocio_config);
    if (!config) return config.error();

    const bool talk = !args.quiet && !args.json;
    MaterialOptions material_options;
    material_options.threads = args.threads;
    material_options.histograms = *method == RenderMethod::Exact;
    if (talk) material_options.note = [](const std::string& line) { std::cerr << "render: " << line << "\n"; };
    auto materials = prepare_materials(*scene, *config, material_options);
    if (!materials) return materials.error();

    RenderOptions options;
    options.method = *method;
    options.samples = args.samples;
    options.seed = args.seed;
    options.threads = args.threads;
    options.footprint = *footprint;
    if (args.probes < 1 || args.probes > 64)
        return bad_input("--probes " + std::to_string(args.probes) + " is out of range (expected 1 to 64)");
    options.max_probes = args.probes;
    options.edge_coverage = !args.no_edge_coverage;
    if (talk && isatty(STDERR_FILENO)) options.progress = terminal_progress("render");
    auto image = render(*scene, *materials, options);
    if (!image) return image.error();

    ImageAttributes a;
    a.text = {{"cmfilter:kind", "render"},
              {"cmfilter:version", version()},
              {"cmfilter:scene", scene->path},
              {"cmfilter:method", to_string(image->method)},
              {"cmfilter:footprint", to_string(options.footprint)}};
    a.numbers = {{"cmfilter:samples", static_cast<double>(image->samples)},
                 {"cmfilter:seed", static_cast<double>(args.seed)}};
    if (auto st = write_rgb_image(args.output, image->width, image->height, 3, image->rgb, config->scene_linear_name(), a,
                                  *config);
        !st)
        return st;
    if (!args.aov.empty()) {
        if (auto st = write_aov(aov_paths[0], *image, image->mean, "mean", *config); !st) return st;
        if (auto st = write_aov(aov_paths[1], *image, image->sigma, "sigma", *config); !st) return st;
        if (auto st = write_aov(aov_paths[2], *image, image->lod, "lod", *config); !st) return st;
    }

    std::size_t hits = 0;
    for (unsigned char h : image->hit) hits += h;
    if (args.json) {
        nlohmann::json j;
        j["output"] = args.output;
        j["scene"] = scene->path;
        j["method"] = to_string(image->method);
        j["samples"] = image->samples;
        j["seed"] = args.seed;
        j["footprint"] = to_string(options.footprint);
        j["edge_coverage"] = options.edge_coverage && *method != RenderMethod::Supersample &&
                             *method != RenderMethod::Reference;
        j["size"] = {image->width, image->height};
        j["pixels_hit"] = hits;
        j["seconds"] = image->seconds;
        if (!args.aov.empty()) j["aov"] = {aov_paths[0], aov_paths[1], aov_paths[2]};
        std::cout << j.dump(2) << "\n";
    } else if (!args.quiet) {
        std::cout << "wrote " << args.output << ": " << image->width << " x " << image->height << ", "
                  << to_string(image->method) << ", " << image->samples << " ray(s) per pixel, " << hits
                  << " pixels on a surface, " << image->seconds << " s\n";
    }
    return ok();
}

}  // namespace

Command setup_render(CLI::App& parent)
{
    auto args = std::make_shared<RenderArgs>();
    CLI::App* app = parent.add_subcommand("render", "Render a scene with colour-mapped surfaces, filtered per pixel");
    app->add_option("scene", args->scene, "Scene file (JSON, docs/scene-format.md)")->required();
    app->add_option("-o,--output", args->output, "Image to write (.exr scene-linear, .png/.jpg sRGB)")->required();
    app->add_option("--method", args->method, "naive, gaussian, exact (texture drivers with at most 256 values), supersample or reference")->capture_default_str();
    app->add_option("--spp", args->samples, "Rays per pixel for supersample (reference: at least 1024)")
        ->capture_default_str();
    app->add_option("--seed", args->seed, "Seed of the sub-pixel samples")->capture_default_str();
    app->add_option("--footprint", args->footprint, "Width of an anisotropic footprint: rms, area, major or minor")
        ->capture_default_str();
    app->add_option("--probes", args->probes,
                    "Filter an anisotropic footprint as up to N probes along its major edge (naive, gaussian, exact)")
        ->capture_default_str();
    app->add_flag("--no-edge-coverage", args->no_edge_coverage,
                  "naive, gaussian, exact: take the centre ray's surface for the whole pixel, also on silhouettes "
                  "and horizons");
    app->add_option("--aov", args->aov, "Also write PREFIX.mean.exr, PREFIX.sigma.exr and PREFIX.lod.exr");
    app->add_option("--ocio-config", args->ocio_config,
                    "OpenColorIO config (default: $OCIO if set, else the built-in config)");
    app->add_option("--threads", args->threads, "Threads (0: all cores)")->capture_default_str();
    app->add_flag("--json", args->json, "Print a machine-readable summary on stdout");
    app->add_flag("-q,--quiet", args->quiet, "Print nothing on success (and no progress)");
    return {app, [args] { return run(*args); }};
}

}  // namespace cmfilter::cli
