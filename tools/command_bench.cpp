// SPDX-License-Identifier: Apache-2.0
// cmfilter bench: speed against accuracy on scenes (docs/render.md): every
// method and configuration timed and compared with a reference (1024 rays
// per pixel, more where two references with other seeds differ by > 0.2),
// overall and per distance band; a CSV, and a log-log chart per scene; with
// --references the reference of each scene as an EXR; with --region all of
// it on a region of each frame (docs/farm.md).
#include "command.h"

#include "bench/bench_chart.h"
#include "bench/render_benchmark.h"
#include "cmfilter/io/recorded_path.h"
#include "cmfilter/io/rgb_image_file.h"
#include "cmfilter/util/atomic_output.h"
#include "cmfilter/util/version.h"
#include "cmfilter/scene/scene_loading.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

namespace cmfilter::cli {

namespace {

using namespace cmfilter::bench;

struct BenchArgs {
    std::vector<std::string> scenes;
    std::string csv;
    std::string charts;
    std::string resolution;
    std::string region;      // x0,y0,x1,y1 of every scene's frame (after --size)
    std::string references;  // folder for SCENE.reference.exr
    int reference_samples = kReferenceSamples;
    double reference_repeat = 0.2;
    int max_reference_samples = 16 * kReferenceSamples;
    int repeats = 3;
    int probes = 16;
    int sub_footprints = SubFootprintOptions{}.max_cells;
    std::vector<std::string> only;
    bool no_edge_coverage = false;
    std::uint64_t seed = 0;
    std::string ocio_config;
    int threads = 0;
    bool quiet = false;
};

Status write_text(const std::string& path, const std::string& text)
{
    auto out = AtomicOutput::begin(path);
    if (!out) return out.error();
    {
        std::ofstream f(out->temp_path());
        f << text;
        f.close();
        if (!f) return out->write_error("");
    }
    return out->commit();
}

// The reference of `scene_path` in the --references folder.
std::string reference_path(const std::string& folder, const std::string& scene_path)
{
    return (std::filesystem::path(folder) / (std::filesystem::path(scene_path).stem().string() + ".reference.exr"))
        .string();
}

// The reference the rows were measured against, scene-linear, its region as
// the data window (as render writes it).
Status write_reference(const std::string& path, const SceneBench& bench, const BenchOptions& options,
                       const ColorConfig& config)
{
    const RenderedImage& image = *bench.reference_image;
    ImageAttributes a;
    a.text = {{"cmfilter:kind", "render"},
              {"cmfilter:version", version()},
              {"cmfilter:scene", path_for_record(bench.scene, path)},
              {"cmfilter:method", to_string(RenderMethod::Reference)}};
    a.numbers = {{"cmfilter:samples", static_cast<double>(image.samples)},
                 {"cmfilter:seed", static_cast<double>(options.seed)}};
    return write_rgb_image(path, image.width, image.height, 3, image.rgb, config.scene_linear_name(), a, config,
                           {image.x0, image.y0, image.frame_width, image.frame_height});
}

Status run(const BenchArgs& args)
{
    if (auto st = check_output_path(args.csv, ".csv"); !st) return st;
    if (!args.charts.empty() && !std::filesystem::is_directory(args.charts))
        return io_error("--charts '" + args.charts + "' is not a folder");
    if (!args.references.empty()) {
        if (!std::filesystem::is_directory(args.references))
            return io_error("--references '" + args.references + "' is not a folder");
        for (const std::string& path : args.scenes)
            if (auto st = check_rgb_image_output(reference_path(args.references, path), true); !st) return st;
    }
    BenchOptions options;
    options.reference_samples = args.reference_samples;
    options.reference_repeat = args.reference_repeat;
    options.max_reference_samples = args.max_reference_samples;
    if (auto st = check_reference_options(options); !st) return st;
    std::optional<std::pair<int, int>> size;
    if (!args.resolution.empty()) {
        auto parsed = parse_image_size("--size", args.resolution);
        if (!parsed) return parsed.error();
        size = *parsed;
    }
    if (!args.region.empty()) {
        auto parsed = parse_region("--region", args.region);
        if (!parsed) return parsed.error();
        options.region = *parsed;
    }
    options.keep_reference = !args.references.empty();
    auto config = load_color_config(args.ocio_config);
    if (!config) return config.error();

    options.repeats = args.repeats;
    options.max_probes = args.probes;
    if (auto st = check_render_probes(args.probes); !st) return st;
    options.sub_footprints.max_cells = args.sub_footprints;
    if (auto st = check_sub_footprint_options(options.sub_footprints); !st) return st;
    if (!args.only.empty()) {
        auto chosen = select_bench_configurations(options.configurations, args.only);
        if (!chosen) return chosen.error();
        options.configurations = std::move(*chosen);
    }
    options.edge_coverage = !args.no_edge_coverage;
    options.seed = args.seed;
    options.threads = args.threads;
    if (!args.quiet) options.note = [](const std::string& line) { std::cerr << "bench: " << line << "\n"; };

    std::vector<SceneBench> benches;
    for (const std::string& path : args.scenes) {
        auto scene = load_scene(path);
        if (!scene) return scene.error();
        if (size) {
            scene->camera.width = size->first;
            scene->camera.height = size->second;
        }
        // Checked before the materials are prepared (their tables may take a while).
        if (options.region)
            if (auto st = check_pixel_region(*options.region, scene->camera.width, scene->camera.height,
                                             "BenchOptions::region");
                !st)
                return prefixed(scene->path + ": ", st.error());
        MaterialOptions mo;
        mo.threads = args.threads;
        mo.note = options.note;
        auto materials = prepare_materials(*scene, *config, mo);
        if (!materials) return materials.error();
        auto bench = bench_scene(*scene, *materials, options);
        if (!bench) return bench.error();
        if (!args.charts.empty()) {
            const std::string png =
                (std::filesystem::path(args.charts) / (std::filesystem::path(path).stem().string() + ".png")).string();
            if (auto st = write_bench_chart(*bench, png); !st) return st;
            if (!args.quiet) std::cerr << "bench: wrote " << png << "\n";
            const std::string bytes_png =
                (std::filesystem::path(args.charts) / (std::filesystem::path(path).stem().string() + "-bytes.png"))
                    .string();
            if (auto st = write_bench_chart(*bench, bytes_png, ChartAxis::Bytes); !st) return st;
            if (!args.quiet) std::cerr << "bench: wrote " << bytes_png << "\n";
        }
        if (!args.references.empty()) {
            const std::string exr = reference_path(args.references, path);
            if (auto st = write_reference(exr, *bench, options, *config); !st) return st;
            bench->reference_image.reset();
            if (!args.quiet) std::cerr << "bench: wrote " << exr << "\n";
        }
        benches.push_back(std::move(*bench));
    }
    if (auto st = write_text(args.csv, bench_csv(benches)); !st) return st;
    if (!args.quiet) std::cout << "wrote " << args.csv << ": " << benches.size() << " scene(s)\n";
    return ok();
}

}  // namespace

Command setup_bench(CLI::App& parent)
{
    auto args = std::make_shared<BenchArgs>();
    CLI::App* app =
        parent.add_subcommand("bench", "Time every render method on scenes and measure its error against a reference");
    app->add_option("scenes", args->scenes, "Scene files (JSON, docs/scene-format.md)")->required();
    app->add_option("--csv", args->csv, "CSV to write: one row per scene and configuration")->required();
    app->add_option(
        "--charts", args->charts,
        "Folder for two charts per scene: error against time (SCENE.png) and against bytes read (SCENE-bytes.png); needs gnuplot");
    app->add_option("--size,--resolution", args->resolution, "Render every scene at WxH instead of its own resolution");
    app->add_option("--region", args->region,
                    "Render and compare only the pixels x0,y0,x1,y1 of every scene's frame (after --size; x0,y0 "
                    "inclusive, x1,y1 exclusive; docs/farm.md)");
    app->add_option("--references", args->references,
                    "Folder for each scene's reference as SCENE.reference.exr (scene-linear; a --region as its "
                    "data window)");
    app->add_option("--reference-spp", args->reference_samples, "Rays per pixel of each reference round (>= 1024)")
        ->capture_default_str();
    app->add_option("--reference-repeat", args->reference_repeat,
                    "Mean CIEDE2000 two references with other seeds may differ by; both grow by --reference-spp "
                    "rays per round until they do")
        ->capture_default_str();
    app->add_option("--max-reference-spp", args->max_reference_samples,
                    "Stop growing the references at this many rays per pixel")
        ->capture_default_str();
    app->add_option("--repeats", args->repeats, "Timed runs per configuration (the fastest counts)")
        ->capture_default_str();
    app->add_option("--probes", args->probes, "Probes along an anisotropic footprint (naive, gaussian, exact)")
        ->capture_default_str();
    app->add_option("--sub-footprints", args->sub_footprints,
                    "mixture, noise drivers: up to N x N squares per footprint in the transition (1 to 16)")
        ->capture_default_str();
    app->add_option("--only", args->only,
                    "Run only these configurations, by the CSV's labels, comma-separated "
                    "(e.g. \"naive,gaussian 256x256 sqrt\"; default: all)")
        ->delimiter(',');
    app->add_flag("--no-edge-coverage", args->no_edge_coverage,
                  "naive, gaussian: the centre ray's surface for the whole pixel, also on silhouettes and horizons");
    app->add_option("--seed", args->seed, "Seed of the sub-pixel samples")->capture_default_str();
    app->add_option("--ocio-config,--colorconfig", args->ocio_config,
                    "OpenColorIO config (default: $OCIO if set, else the built-in config)");
    app->add_option("--threads", args->threads, "Threads (0: all cores)")->capture_default_str();
    app->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
    FieldFlags flags = color_map_flags();
    flags.insert(flags.end(), {{"BenchOptions::reference_samples", "--reference-spp"},
                               {"BenchOptions::reference_repeat", "--reference-repeat"},
                               {"BenchOptions::max_reference_samples", "--max-reference-spp"},
                               {"BenchOptions::region", "--region"},
                               {"RenderOptions::max_probes", "--probes"},
                               {"SubFootprintOptions::max_cells", "--sub-footprints"}});
    return {app, [args] { return run(*args); }, flags};
}

}  // namespace cmfilter::cli
