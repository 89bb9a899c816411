// SPDX-License-Identifier: Apache-2.0
// cmfilter relight: a fit (cmfilter's EXR, or a .ptm or .rti from any tool)
// evaluated under a light: an EXR in scene-linear, or a PNG/JPEG in sRGB;
// or, with --reference, its error against a stack's images at the stack's
// lights (docs/stacks.md).
#include "command.h"

#include "cmfilter/io/rgb_image_file.h"
#include "cmfilter/stack/fit_loading.h"
#include "cmfilter/stack/relight_error.h"
#include "cmfilter/stack/stack_encoding.h"
#include "cmfilter/util/atomic_output.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <iostream>
#include <memory>

namespace cmfilter::cli {

namespace {

struct RelightArgs {
    std::string fit;
    std::string light;
    std::string output;
    std::string reference;
    std::string colorspace;
    std::string ocio_config;
    int threads = 0;
    bool json = false;
    bool quiet = false;
};

Status run(const RelightArgs& args)
{
    if (args.output.empty() == args.reference.empty())
        return bad_input("relight needs either --light X,Y,Z with -o IMAGE, or --reference STACK.lp");
    if (!args.output.empty()) {
        if (args.light.empty()) return bad_input("-o " + args.output + " needs --light X,Y,Z");
        if (auto st = check_rgb_image_output(args.output); !st) return st;
    }
    auto config = load_color_config(args.ocio_config);
    if (!config) return config.error();
    auto fit = load_fit(args.fit);
    if (!fit) return fit.error();

    if (!args.reference.empty()) {
        StackLoadOptions load;
        load.light_file = args.reference;
        load.colorspace = args.colorspace;
        load.threads = args.threads;
        // The stack's images streamed, one per thread at a time.
        auto e = relight_error_from_files(*fit, load, *config, args.threads);
        if (!e) return e.error();
        if (args.json) {
            nlohmann::json j;
            j["fit"] = args.fit;
            j["reference"] = args.reference;
            j["lights"] = e->lights;
            j["rmse"] = e->rmse;
            j["delta_e"] = {{"mean", e->delta_e.mean}, {"p95", e->delta_e.p95}, {"max", e->delta_e.max}};
            j["light_rmse"] = e->light_rmse;
            j["light_delta_e_mean"] = e->light_delta_e;
            std::cout << j.dump(2) << "\n";
        } else if (!args.quiet) {
            std::cout << args.fit << " against " << args.reference << " (" << e->lights << " lights)\n"
                      << "  RMSE " << e->rmse << " (scene-linear)\n"
                      << "  CIEDE2000 mean " << e->delta_e.mean << ", p95 " << e->delta_e.p95 << ", max "
                      << e->delta_e.max << "\n";
        }
        return ok();
    }

    auto light = parse_direction("--light", args.light);
    if (!light) return light.error();
    std::vector<float> values = relight(*fit, *light, args.threads);
    // Display-encoded fits (.ptm, .rti) are decoded first: images are
    // written from scene-linear (EXR as it is, PNG/JPEG encoded to sRGB).
    if (auto st = convert_stack_encoding(values, fit->channels, fit->encoding, StackEncoding::SceneLinear, *config);
        !st)
        return st;
    for (float& v : values)
        if (!std::isfinite(v)) v = 0;
    int channels = fit->channels;
    const std::string ext = lowercase_extension(args.output);
    if (ext != ".exr" && channels != 3) {
        // PNG/JPEG take RGB: a grey fit is written as grey RGB, alpha dropped.
        std::vector<float> rgb(fit->texels() * 3);
        for (std::size_t t = 0; t < fit->texels(); ++t)
            for (int c = 0; c < 3; ++c) rgb[3 * t + c] = values[t * channels + (channels >= 3 ? c : 0)];
        values.swap(rgb);
        channels = 3;
    }
    ImageAttributes attributes;
    attributes.text = {{"cmfilter:kind", "relit-image"}, {"cmfilter:fit", args.fit}};
    attributes.numbers = {
        {"cmfilter:light_x", light->x}, {"cmfilter:light_y", light->y}, {"cmfilter:light_z", light->z}};
    if (auto st = write_rgb_image(args.output, fit->width, fit->height, channels, values, config->scene_linear_name(),
                                  attributes, *config);
        !st)
        return st;
    if (args.json) {
        nlohmann::json j;
        j["output"] = args.output;
        j["fit"] = args.fit;
        j["model"] = to_string(fit->model);
        j["light"] = {light->x, light->y, light->z};
        j["size"] = {fit->width, fit->height};
        std::cout << j.dump(2) << "\n";
    } else if (!args.quiet) {
        std::cout << "wrote " << args.output << ": " << to_string(fit->model) << " relit at (" << light->x << ", "
                  << light->y << ", " << light->z << "), " << fit->width << " x " << fit->height << "\n";
    }
    return ok();
}

}  // namespace

Command setup_relight(CLI::App& parent)
{
    auto args = std::make_shared<RelightArgs>();
    CLI::App* app = parent.add_subcommand(
        "relight", "Evaluate a fit (.exr, .ptm, .rti) under a light, or measure it against a stack (docs/stacks.md)");
    app->add_option("FIT", args->fit, "A fit: cmfilter's .exr, or a .ptm or .rti")->required();
    app->add_option("--light", args->light, "Light direction x,y,z (x right, y up, z towards the camera)");
    app->add_option("-o,--output", args->output, "Image to write: .exr (scene-linear), .png or .jpg (sRGB)");
    app->add_option("--reference", args->reference,
                    "A stack (.lp): report the fit's RMSE and CIEDE2000 at its lights instead of writing an image");
    app->add_option("--colorspace", args->colorspace, "Colour space of the reference stack's integer images");
    app->add_option("--ocio-config", args->ocio_config, "OpenColorIO config (default: $OCIO, else built in)");
    app->add_option("--threads", args->threads, "Threads (0: all cores)")->capture_default_str();
    app->add_flag("--json", args->json, "Print a machine-readable summary on stdout");
    app->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
    return {app, [args] { return run(*args); }, {{"StackLoadOptions::colorspace", "--colorspace"}}};
}

}  // namespace cmfilter::cli
