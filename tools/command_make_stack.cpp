// SPDX-License-Identifier: Apache-2.0
// cmfilter make-stack: a synthetic image stack with exact ground truth
// (make_stack.h, docs/make-stack.md): one tile of a scene's
// microsurface or displacement, ray traced under each light of a dome, from
// one view (a stack: -o stack.lp) or several (a BTF: -o btf.json); with
// --from, the surface of an earlier stack's record rendered again under
// other lights (ground truth at held-out lights).
#include "command.h"

#include "cmfilter/synthetic/make_stack.h"
#include "cmfilter/synthetic/stack_record.h"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <iostream>
#include <memory>

namespace cmfilter::cli {

namespace {

struct MakeStackArgs {
    std::string scene;
    std::string from;
    std::string output;
    std::size_t surface = 0;
    std::vector<std::string> views;
    int size = 64;
    int samples = 16;
    std::string dome = "fibonacci:64";
    double min_elevation = 10;
    std::string specular = "none";
    std::uint64_t seed = 0;
    std::string format = "exr";
    bool albedo = false;
    std::string ocio_config;
    int threads = 0;
    bool json = false;
    bool quiet = false;
};

FieldFlags make_stack_flags()
{
    return {{"MakeStackOptions::views", "--view"},
            {"MakeStackOptions::size", "--size"},
            {"MakeStackOptions::samples", "--spp"},
            {"MakeStackOptions::dome", "--dome"},
            {"MakeStackOptions::specular", "--specular"},
            {"MakeStackOptions::output", "--output"},
            {"MakeStackOptions::image_extension", "--format"},
            {"DomeOptions::kind", "--dome"},
            {"DomeOptions::count", "the --dome count"},
            {"DomeOptions::min_elevation_degrees", "--min-elevation"},
            {"SyntheticSurfaceOptions::surface", "--surface"},
            {"SyntheticStackOptions::view", "--view"},
            {"SyntheticStackOptions::size", "--size"},
            {"SyntheticStackOptions::samples", "--spp"},
            {"SpecularLobe::ks", "the --specular ks"},
            {"SpecularLobe::exponent", "the --specular n"},
            {"SpecularLobe::alpha", "the --specular alpha"}};
}

Status run(const MakeStackArgs& args, const CLI::App& app)
{
    MakeStackOptions options;
    if (!args.from.empty()) {
        if (!args.scene.empty())
            return bad_input("make-stack takes either a scene or --from a record, not both (got " + args.scene +
                             " and --from " + args.from + ")");
        for (const char* flag :
             {"--surface", "--view", "--size", "--spp", "--specular", "--seed", "--format", "--albedo"})
            if (app.count(flag) > 0)
                return bad_input(std::string(flag) + " cannot be given with --from: the record " + args.from +
                                 " holds it (the ground truth renders the same surface, view and rays)");
        auto record = read_stack_record(args.from);
        if (!record) return record.error();
        options = *record;
    } else {
        if (args.scene.empty()) return bad_input("make-stack needs a scene file (or --from a stack's record)");
        options.scene = args.scene;
        options.surface = args.surface;
        options.size = args.size;
        options.samples = args.samples;
        options.seed = args.seed;
        auto lobe = parse_specular_lobe(args.specular);
        if (!lobe) return lobe.error();
        options.specular = *lobe;
        if (args.format != "exr" && args.format != "png")
            return bad_input("--format '" + args.format + "' is unknown (expected exr or png)");
        options.image_extension = "." + args.format;
        options.albedo = args.albedo;
        if (!args.views.empty()) {
            options.views.clear();
            for (const std::string& text : args.views) {
                auto view = parse_direction("--view", text);
                if (!view) return view.error();
                options.views.push_back(*view);
            }
        }
    }
    auto dome = parse_dome(args.dome);
    if (!dome) return dome.error();
    options.dome = *dome;
    options.dome.min_elevation_degrees = args.min_elevation;
    options.output = args.output;
    options.threads = args.threads;
    const bool talk = !args.quiet && !args.json;
    if (talk && isatty(STDERR_FILENO)) options.progress = terminal_progress("make-stack");
    auto config = load_color_config(args.ocio_config);
    if (!config) return config.error();
    auto made = make_stack(options, *config);
    if (!made) return made.error();

    if (args.json) {
        nlohmann::json j;
        j["output"] = args.output;
        j["light_files"] = made->light_files;
        j["records"] = made->records;
        if (!made->manifest.empty()) j["manifest"] = made->manifest;
        j["surface_kind"] = to_string(made->kind);
        j["tile"] = made->tile;
        j["lights"] = made->lights;
        j["views"] = made->light_files.size();
        j["size"] = made->size;
        j["samples"] = made->samples;
        j["dome"] = dome_text(options.dome);
        j["specular"] = specular_text(options.specular);
        j["files"] = made->files;
        j["rays"] = made->rays;
        j["render_seconds"] = made->render_seconds;
        j["seconds"] = made->seconds;
        print_json("make-stack", std::move(j));
    } else if (!args.quiet) {
        std::cout << "wrote " << args.output << ": " << made->light_files.size() << " view(s) x " << made->lights
                  << " lights, " << made->size << " x " << made->size << ", " << made->samples << " ray(s) per pixel, "
                  << to_string(made->kind) << " tile " << made->tile << ", " << made->files << " files, "
                  << made->seconds << " s (" << made->render_seconds << " s tracing)\n";
    }
    return ok();
}

}  // namespace

Command setup_make_stack(CLI::App& parent)
{
    auto args = std::make_shared<MakeStackArgs>();
    CLI::App* app = parent.add_subcommand(
        "make-stack", "Ray trace a tile of a scene's microsurface under a dome of lights: a synthetic image stack");
    app->add_option("scene", args->scene, "Scene file (JSON, docs/scene-format.md)");
    app->add_option("-o,--output", args->output,
                    "The stack's light file (.lp; images, normals and record beside it), or with several --view "
                    "the BTF manifest (.json; a view-NN/ folder per view)")
        ->required();
    app->add_option("--from", args->from,
                    "A stack's record (stack.json): render its surface, view and rays again under --dome (ground "
                    "truth at further lights)");
    app->add_option("--surface", args->surface, "The scene surface to trace (a microsurface or displacement)")
        ->capture_default_str();
    app->add_option("--view", args->views,
                    "Towards the camera, x,y,z in the stack's frame (x right, y up, z out of the surface); "
                    "repeat for a BTF (default 0,0,1)");
    app->add_option("--size", args->size, "Pixels per side of the tile's images")->capture_default_str();
    app->add_option("--spp", args->samples, "Rays per pixel (stratified)")->capture_default_str();
    app->add_option("--dome", args->dome, "Lights: regular:N, fibonacci:N, stage:N (uneven) or file:PATH.lp")
        ->capture_default_str();
    app->add_option("--min-elevation", args->min_elevation, "Lowest light elevation in degrees (made domes)")
        ->capture_default_str();
    app->add_option("--specular", args->specular,
                    "Facets' specular lobe: none, blinn-phong:ks=K,n=N or ggx:ks=K,alpha=A")
        ->capture_default_str();
    app->add_option("--seed", args->seed, "Seed of the rays' jitter")->capture_default_str();
    app->add_option("--format", args->format, "Images: exr (scene-linear float) or png (8-bit sRGB)")
        ->capture_default_str();
    app->add_flag("--albedo", args->albedo, "Also write the mean colour per pixel (STEM.albedo.exr)");
    app->add_option("--ocio-config,--colorconfig", args->ocio_config,
                    "OpenColorIO config (default: $OCIO if set, else the built-in config)");
    app->add_option("--threads", args->threads, "Threads (0: all cores)")->capture_default_str();
    app->add_flag("--json", args->json, "Print a machine-readable summary on stdout");
    app->add_flag("-q,--quiet", args->quiet, "Print nothing on success (and no progress)");
    FieldFlags flags = color_map_flags();
    const FieldFlags own = make_stack_flags();
    flags.insert(flags.end(), own.begin(), own.end());
    return {app, [args, app] { return run(*args, *app); }, flags};
}

}  // namespace cmfilter::cli
