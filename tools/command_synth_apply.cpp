// SPDX-License-Identifier: Apache-2.0
// cmfilter synth-apply: a coordinate map rendered with one image of its
// sample, or a fit of it relit at a light (and view), at full size or at a
// level of detail by a chosen lookup (docs/synthesis.md#levels-of-detail).
// Memory is the sample image (or fit) plus the map, not the full surface.
#include "command.h"

#include "cmfilter/io/recorded_path.h"
#include "cmfilter/synthesis/coordinate_lookup.h"
#include "cmfilter/synthesis/coordinate_map_file.h"
#include "cmfilter/synthesis/synthesis_sample.h"
#include "cmfilter/synthesis/synthesis_source.h"
#include "cmfilter/util/atomic_output.h"
#include "cmfilter/util/stopwatch.h"

#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>
#include <optional>

namespace cmfilter::cli {

namespace {

struct SynthApplyArgs {
    std::string map;
    std::string source;
    std::string output;
    int image = -1;
    std::string light;
    std::string view;
    int lod = 0;
    std::string method = "patches";
    int patches = LodOptions{}.patches;
    std::string colorspace;
    bool no_hash_check = false;
    std::string ocio_config;
    int threads = 0;
    bool json = false;
    bool quiet = false;
};

Status run(const SynthApplyArgs& args, const CLI::App& app)
{
    if (auto st = check_rgb_image_output(args.output); !st) return st;
    auto method = parse_lod_method(args.method);
    if (!method) return method.error();
    if (app.count("--image") && (!args.light.empty() || !args.view.empty()))
        return bad_input("--image picks an image by its index; it cannot be given with --light or --view");
    auto config = load_color_config(args.ocio_config);
    if (!config) return config.error();
    auto map = read_coordinate_map_exr(args.map);
    if (!map) return map.error();

    SourceOptions source;
    source.path = args.source;
    source.image = args.image;
    source.colorspace = args.colorspace;
    source.periodic = map->info.sample_periodic;
    source.threads = args.threads;
    if (!args.light.empty()) {
        auto light = parse_direction("--light", args.light);
        if (!light) return light.error();
        source.light = *light;
    }
    if (!args.view.empty()) {
        auto view = parse_direction("--view", args.view);
        if (!view) return view.error();
        source.view = *view;
    }
    // A sample's files must be the ones the map was synthesised from; a
    // fit (an EXR, .ptm or .rti that is not the sample itself) is checked
    // by its size.
    bool hash_checked = false;
    if (!args.no_hash_check && !map->info.sample_hash.empty()) {
        auto files = sample_image_files(args.source);
        const auto fit = is_fit_source(args.source);
        if (files && !(fit && *fit)) {
            auto hash = sample_content_hash(*files);
            if (!hash) return hash.error();
            if (*hash != map->info.sample_hash)
                return bad_input("the coordinate map '" + args.map + "' was synthesised from another sample ('" +
                                 map->info.sample_path + "', hash " + map->info.sample_hash.substr(0, 16) +
                                 "...), not '" + args.source + "' (hash " + hash->substr(0, 16) +
                                 "...); pass --no-hash-check to render through it anyway");
            hash_checked = true;
        }
    }
    Stopwatch clock;
    auto image = load_source_image(source, *config);
    if (!image) return image.error();
    const CoordinateLevel& full = map->full();
    if (image->image.width != full.sample_width || image->image.height != full.sample_height)
        return bad_input("the coordinate map '" + args.map + "' points into a " + std::to_string(full.sample_width) +
                         " x " + std::to_string(full.sample_height) + " sample, but '" + args.source + "' is " +
                         std::to_string(image->image.width) + " x " + std::to_string(image->image.height));
    LodOptions lod;
    lod.lod = args.lod;
    lod.method = *method;
    lod.patches = args.patches;
    lod.threads = args.threads;
    auto out = render_at_lod(*map, image->image, lod);
    if (!out) return out.error();
    const double seconds = clock.elapsed_ms() / 1000;

    ImageAttributes attributes;
    attributes.text = {{"cmfilter:kind", "synthesised-image"},
                       {"cmfilter:coordinate_map", path_for_record(args.map, args.output)},
                       {"cmfilter:source", path_for_record(args.source, args.output)},
                       {"cmfilter:lod_method", to_string(*method)},
                       {"cmfilter:description", image->description}};
    attributes.numbers = {{"cmfilter:lod", static_cast<double>(args.lod)}};
    const int width = out->width, height = out->height, channels = out->channels;
    if (auto st = write_output_image(args.output, width, height, channels, std::move(out->pixels), image->colorspace,
                                     attributes, *config);
        !st)
        return st;

    // What the surface costs: the sample image and the map, against the
    // full-size image the map stands for.
    using Bytes = unsigned long long;
    const Bytes sample_bytes = Bytes{4} * image->image.width * image->image.height * image->image.channels;
    const Bytes map_bytes = Bytes{4} * 2 * full.width * full.height;
    const Bytes full_bytes = Bytes{4} * full.width * full.height * image->image.channels;
    if (args.json) {
        nlohmann::json j;
        j["output"] = args.output;
        j["coordinate_map"] = args.map;
        j["source"] = args.source;
        j["description"] = image->description;
        j["fit"] = image->is_fit;
        j["hash_checked"] = hash_checked;
        j["lod"] = args.lod;
        j["lod_method"] = to_string(*method);
        j["size"] = {width, height};
        j["seconds"] = seconds;
        j["bytes"] = {{"sample", sample_bytes}, {"map", map_bytes}, {"full_size_image", full_bytes}};
        print_json("synth-apply", std::move(j));
    } else if (!args.quiet) {
        std::cout << "wrote " << args.output << ": " << image->description << " through " << args.map << ", " << width
                  << " x " << height << " (LOD " << args.lod << ", " << to_string(*method) << "), " << seconds
                  << " s\n";
    }
    return ok();
}

}  // namespace

Command setup_synth_apply(CLI::App& parent)
{
    auto args = std::make_shared<SynthApplyArgs>();
    CLI::App* app = parent.add_subcommand(
        "synth-apply", "Render a sample image or a relit fit through a coordinate map, at any level of detail "
                       "(docs/synthesis.md)");
    app->add_option("COORDS", args->map, "A coordinate map written by synth (.exr)")->required();
    app->add_option("--source", args->source,
                    "The sample (image, .lp, BTF .json) or a fit of it (.ptm, .rti, cmfilter fit .exr)")
        ->required();
    app->add_option("-o,--output", args->output, "Image to write: .exr (scene-linear), .png or .jpg (sRGB)")
        ->required();
    app->add_option("--image", args->image, "The sample's image by index (a BTF: across all views, in order)");
    app->add_option("--light", args->light,
                    "Light x,y,z: the stack's image lit from it, or the fit relit there (x right, y up, z out)");
    app->add_option("--view", args->view, "View x,y,z: a BTF's view slot, or the view a Lafortune fit is seen from");
    app->add_option("--lod", args->lod, "Level of detail: footprints of 2^LOD x 2^LOD texels")->capture_default_str();
    app->add_option("--lod-method", args->method,
                    "How a footprint is filtered: patches (exact inside a patch, a mixture at seams), levels "
                    "(hierarchical synthesis's own maps), point, naive (mip of the coordinates), reference (box "
                    "filter of the full-size output)")
        ->capture_default_str();
    app->add_option("--patches", args->patches, "Patch offsets kept per footprint (--lod-method patches)")
        ->capture_default_str();
    app->add_option("--colorspace", args->colorspace, "Colour space of the sample's integer images");
    app->add_flag("--no-hash-check", args->no_hash_check,
                  "Render through the map even when the sample's files differ from those it was made from");
    app->add_option("--ocio-config,--colorconfig", args->ocio_config,
                    "OpenColorIO config (default: $OCIO, else built in)");
    app->add_option("--threads", args->threads, "Threads (0: all cores)")->capture_default_str();
    app->add_flag("--json", args->json, "Print a machine-readable summary on stdout");
    app->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
    return {app,
            [args, app] { return run(*args, *app); },
            {{"SourceOptions::image", "--image"},
             {"SourceOptions::light", "--light"},
             {"SourceOptions::view", "--view"},
             {"SourceOptions::colorspace", "--colorspace"},
             {"StackLoadOptions::colorspace", "--colorspace"},
             {"LodOptions::lod", "--lod"},
             {"LodOptions::patches", "--patches"},
             {"LodOptions::method", "--lod-method"}}};
}

}  // namespace cmfilter::cli
