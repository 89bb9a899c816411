// SPDX-License-Identifier: Apache-2.0
// cmfilter normals: per texel the light direction at which a fit is
// brightest (for a PTM, Malzbender et al. 2001's normal from the
// polynomial's maximum), as a float EXR of unit vectors X, Y, Z in the
// stack's frame; with --reference, the angle to true normals (make-stack's).
#include "command.h"

#include "cmfilter/io/rgb_image_file.h"
#include "cmfilter/stack/fit_normals.h"
#include "cmfilter/stack/normal_error.h"
#include "cmfilter/stack/stack_fit.h"
#include "cmfilter/util/atomic_output.h"

#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>
#include <optional>
#include <variant>

namespace cmfilter::cli {

namespace {

struct NormalsArgs {
    std::string fit;
    std::string output;
    std::string reference;
    int threads = 0;
    bool json = false;
    bool quiet = false;
};

Status run(const NormalsArgs& args)
{
    if (args.output.empty() && args.reference.empty())
        return bad_input("normals needs -o NORMALS.exr, --reference TRUE_NORMALS.exr, or both");
    if (!args.output.empty())
        if (auto st = check_output_path(args.output, ".exr"); !st) return st;
    auto loaded = load_stack_fit(args.fit);
    if (!loaded) return loaded.error();
    // A Lafortune fit's brightest light is its highlight's, at the mirror
    // direction of the view, not the normal that Malzbender's maximum gives
    // for a diffuse surface.
    const auto* fit = std::get_if<LinearFit>(&*loaded);
    if (!fit)
        return bad_input("'" + args.fit + "' is a " + stack_fit_model_name(*loaded) +
                         " fit: normals takes a linear fit (PTM or HSH), whose brightest light is the normal of a "
                         "diffuse surface; a Lafortune lobe's is its highlight's (fit a PTM or HSH to the same stack)");
    const FitNormals normals = fit_normals(*fit, args.threads);
    std::optional<ErrorSummary> error;
    if (!args.reference.empty()) {
        int w = 0, h = 0;
        auto reference = read_normals_image(args.reference, w, h);
        if (!reference) return reference.error();
        auto e = normal_angle_error(normals, *reference, w, h);
        if (!e) return prefixed("'" + args.reference + "': ", e.error());
        error = *e;
    }
    if (!args.output.empty()) {
        auto config = ColorConfig::load("");
        if (!config) return config.error();
        ImageAttributes attributes;
        attributes.text = {{"cmfilter:kind", "fit-normals"}, {"cmfilter:fit", args.fit}};
        attributes.numbers = {{"cmfilter:degenerate_texels", static_cast<double>(normals.degenerate)}};
        // Normals are data: written as they are, with no colour space.
        if (auto st = write_rgb_image(args.output, normals.width, normals.height, 3, normals.normals, "", attributes,
                                      *config);
            !st)
            return st;
    }
    const std::size_t texels = static_cast<std::size_t>(normals.width) * normals.height;
    if (args.json) {
        nlohmann::json j;
        j["fit"] = args.fit;
        if (!args.output.empty()) j["output"] = args.output;
        j["size"] = {normals.width, normals.height};
        j["degenerate_texels"] = normals.degenerate;
        if (error)
            j["angle_degrees"] = {
                {"mean", error->mean}, {"p95", error->p95}, {"max", error->max}, {"count", error->count}};
        print_json("normals", std::move(j));
    } else if (!args.quiet) {
        if (!args.output.empty()) std::cout << "wrote " << args.output << ": normals of " << args.fit << "\n";
        std::cout
            << "  " << normals.degenerate << " of " << texels
            << " texels without an interior maximum (their brightest direction is on the horizon, or the fit is flat)\n";
        if (error)
            std::cout << "  angle to " << args.reference << ": mean " << error->mean << " degrees, p95 " << error->p95
                      << ", max " << error->max << "\n";
    }
    return ok();
}

}  // namespace

Command setup_normals(CLI::App& parent)
{
    auto args = std::make_shared<NormalsArgs>();
    CLI::App* app = parent.add_subcommand(
        "normals", "Surface normals of a fit: the light direction that maximises it, per texel (docs/stacks.md)");
    app->add_option("FIT", args->fit, "A fit: cmfilter's .exr, or a .ptm or .rti")->required();
    app->add_option("-o,--output", args->output, "Normals to write (.exr, channels R G B = X Y Z)");
    app->add_option("--reference", args->reference,
                    "True normals (.exr, such as make-stack's normals.exr): report the angle to them");
    app->add_option("--threads", args->threads, "Threads (0: all cores)")->capture_default_str();
    app->add_flag("--json", args->json, "Print a machine-readable summary on stdout");
    app->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
    return {app, [args] { return run(*args); }, {}};
}

}  // namespace cmfilter::cli
