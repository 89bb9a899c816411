// SPDX-License-Identifier: Apache-2.0
// cmfilter relight: a fit (cmfilter's linear or Lafortune EXR, or a .ptm or
// .rti from any tool) evaluated under a light (and, for Lafortune lobes, a
// view): an EXR in scene-linear, or a PNG/JPEG in sRGB; or, with
// --reference, its error against a stack's images at the stack's lights
// (docs/stacks.md).
#include "command.h"

#include "cmfilter/io/rgb_image_file.h"
#include "cmfilter/stack/relight_error.h"
#include "cmfilter/stack/stack_encoding.h"
#include "cmfilter/stack/stack_fit.h"
#include "cmfilter/util/atomic_output.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <variant>

namespace cmfilter::cli {

namespace {

struct RelightArgs {
    std::string fit;
    std::string light;
    std::string output;
    std::string reference;
    int slot = 0;
    std::string view;
    std::string colorspace;
    std::string ocio_config;
    int threads = 0;
    bool json = false;
    bool quiet = false;
};

Status run(const RelightArgs& args, const CLI::App& app)
{
    if (args.output.empty() == args.reference.empty())
        return bad_input("relight needs either --light X,Y,Z with -o IMAGE, or --reference STACK.lp");
    if (!args.output.empty()) {
        if (args.light.empty()) return bad_input("-o " + args.output + " needs --light X,Y,Z");
        if (auto st = check_rgb_image_output(args.output); !st) return st;
    }
    auto config = load_color_config(args.ocio_config);
    if (!config) return config.error();
    auto fit = load_stack_fit(args.fit);
    if (!fit) return fit.error();
    const bool lafortune = std::holds_alternative<LafortuneFit>(*fit);
    std::optional<Vec3> view;
    if (!args.view.empty()) {
        auto parsed = parse_direction("--view", args.view);
        if (!parsed) return parsed.error();
        view = *parsed;
    }

    if (!args.reference.empty()) {
        auto slot =
            resolve_stack_slot(args.reference, app.count("--slot") ? std::optional<int>(args.slot) : std::nullopt);
        if (!slot) return slot.error();
        if (slot->view && view)
            return bad_input("--view cannot be given with the BTF manifest '" + args.reference +
                             "': its view slot's direction is the view compared (pick the slot with --slot K)");
        // A Lafortune fit is rendered at the slot's view; a linear fit holds
        // one view and is compared at the slot's lights as it is.
        if (slot->view && lafortune) view = slot->view;
        StackLoadOptions load;
        load.light_file = slot->light_file;
        load.colorspace = args.colorspace;
        load.threads = args.threads;
        // The stack's images streamed, one per thread at a time.
        auto e = stack_fit_error(*fit, load, *config, args.threads, view);
        if (!e) return e.error();
        if (args.json) {
            nlohmann::json j;
            j["fit"] = args.fit;
            j["reference"] = args.reference;
            j["light_file"] = slot->light_file;
            if (slot->slot) j["slot"] = *slot->slot;
            j["model"] = stack_fit_model_name(*fit);
            if (lafortune) {
                const Vec3 v = view.value_or(stack_fit_view(*fit));
                j["view"] = {v.x, v.y, v.z};
            }
            j["lights"] = e->lights;
            j["rmse"] = e->rmse;
            j["delta_e"] = {{"mean", e->delta_e.mean}, {"p95", e->delta_e.p95}, {"max", e->delta_e.max}};
            j["light_rmse"] = e->light_rmse;
            j["light_delta_e_mean"] = e->light_delta_e;
            print_json("relight", std::move(j));
        } else if (!args.quiet) {
            std::cout << args.fit << " against " << slot->light_file << " (" << e->lights << " lights)\n"
                      << "  RMSE " << e->rmse << " (scene-linear)\n"
                      << "  CIEDE2000 mean " << e->delta_e.mean << ", p95 " << e->delta_e.p95 << ", max "
                      << e->delta_e.max << "\n";
        }
        return ok();
    }

    if (app.count("--slot")) return bad_input("--slot picks a view slot of a --reference BTF manifest");
    auto light = parse_direction("--light", args.light);
    if (!light) return light.error();
    auto relit = relight_stack_fit(*fit, *light, view, args.threads);
    if (!relit) return relit.error();
    std::vector<float> values = std::move(*relit);
    const int width = stack_fit_width(*fit), height = stack_fit_height(*fit);
    const std::size_t texels = stack_fit_texels(*fit);
    // Display-encoded fits (.ptm, .rti) are decoded first: images are
    // written from scene-linear (EXR as it is, PNG/JPEG encoded to sRGB).
    if (auto st = convert_stack_encoding(values, stack_fit_channels(*fit), stack_fit_encoding(*fit),
                                         StackEncoding::SceneLinear, *config);
        !st)
        return st;
    for (float& v : values)
        if (!std::isfinite(v)) v = 0;
    int channels = stack_fit_channels(*fit);
    const std::string ext = lowercase_extension(args.output);
    if (ext != ".exr" && channels != 3) {
        // PNG/JPEG take RGB: a grey fit is written as grey RGB, alpha dropped.
        std::vector<float> rgb(texels * 3);
        for (std::size_t t = 0; t < texels; ++t)
            for (int c = 0; c < 3; ++c) rgb[3 * t + c] = values[t * channels + (channels >= 3 ? c : 0)];
        values.swap(rgb);
        channels = 3;
    }
    ImageAttributes attributes;
    attributes.text = {{"cmfilter:kind", "relit-image"}, {"cmfilter:fit", args.fit}};
    const Vec3 seen = view.value_or(stack_fit_view(*fit));
    attributes.numbers = {{"cmfilter:light_x", light->x}, {"cmfilter:light_y", light->y},
                          {"cmfilter:light_z", light->z}, {"cmfilter:view_x", seen.x},
                          {"cmfilter:view_y", seen.y},    {"cmfilter:view_z", seen.z}};
    if (auto st = write_rgb_image(args.output, width, height, channels, values, config->scene_linear_name(), attributes,
                                  *config);
        !st)
        return st;
    const std::string model = stack_fit_model_name(*fit);
    if (args.json) {
        nlohmann::json j;
        j["output"] = args.output;
        j["fit"] = args.fit;
        j["model"] = model;
        j["light"] = {light->x, light->y, light->z};
        j["view"] = {seen.x, seen.y, seen.z};
        j["size"] = {width, height};
        print_json("relight", std::move(j));
    } else if (!args.quiet) {
        std::cout << "wrote " << args.output << ": " << model << " relit at (" << light->x << ", " << light->y << ", "
                  << light->z << ")";
        if (lafortune) std::cout << " seen from (" << seen.x << ", " << seen.y << ", " << seen.z << ")";
        std::cout << ", " << width << " x " << height << "\n";
    }
    return ok();
}

}  // namespace

Command setup_relight(CLI::App& parent)
{
    auto args = std::make_shared<RelightArgs>();
    CLI::App* app = parent.add_subcommand(
        "relight", "Evaluate a fit (.exr, .ptm, .rti) under a light, or measure it against a stack (docs/stacks.md)");
    app->add_option("FIT", args->fit, "A fit: cmfilter's .exr (linear or Lafortune), or a .ptm or .rti")->required();
    app->add_option("--light", args->light, "Light direction x,y,z (x right, y up, z towards the camera)");
    app->add_option("--view", args->view,
                    "View direction x,y,z to render a Lafortune fit from (default: its fitted view; a PTM/HSH holds "
                    "one view)");
    app->add_option("-o,--output", args->output, "Image to write: .exr (scene-linear), .png or .jpg (sRGB)");
    app->add_option("--reference", args->reference,
                    "A stack (.lp) or BTF manifest (.json, with --slot): report the fit's RMSE and CIEDE2000 at its "
                    "lights instead of writing an image");
    app->add_option("--slot", args->slot,
                    "With a --reference BTF manifest: the view slot compared (its lights, and its view for a "
                    "Lafortune fit)")
        ->capture_default_str();
    app->add_option("--colorspace", args->colorspace, "Colour space of the reference stack's integer images");
    app->add_option("--ocio-config,--colorconfig", args->ocio_config,
                    "OpenColorIO config (default: $OCIO, else built in)");
    app->add_option("--threads", args->threads, "Threads (0: all cores)")->capture_default_str();
    app->add_flag("--json", args->json, "Print a machine-readable summary on stdout");
    app->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
    return {app, [args, app] { return run(*args, *app); }, {{"StackLoadOptions::colorspace", "--colorspace"}}};
}

}  // namespace cmfilter::cli
