// SPDX-License-Identifier: Apache-2.0
// cmfilter render: a scene file (docs/scene-format.md) rendered with one
// filtering method (docs/render.md): scene-linear EXR or sRGB PNG/JPEG, and
// with --aov the per-pixel filtered mean, sigma and LOD as float EXRs; with
// --region only a region of the frame, as EXR data windows (docs/farm.md).
#include "command.h"

#include "cmfilter/render/render.h"
#include "cmfilter/io/rgb_image_file.h"
#include "cmfilter/io/recorded_path.h"
#include "cmfilter/scene/scene_loading.h"
#include "cmfilter/scene/tolerance_tables.h"
#include "cmfilter/tables/table_size_search.h"
#include "cmfilter/util/atomic_output.h"
#include "cmfilter/util/version.h"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <tuple>
#include <utility>

namespace cmfilter::cli {

namespace {

struct RenderArgs {
    std::string scene;
    std::string output;
    std::string method = "gaussian";
    int samples = 16;
    int probes = 16;
    int sub_footprints = SubFootprintOptions{}.max_cells;
    bool no_edge_coverage = false;
    std::string masking = "correlated";
    std::string slope_shading = "correlated";
    std::uint64_t seed = 0;
    std::string footprint = "rms";
    std::string aov;
    std::string size;    // WxH replacing the scene's camera resolution
    std::string region;  // x0,y0,x1,y1 of the frame (after --size)
    std::optional<double> tolerance;
    std::vector<double> measure_lods;
    std::optional<double> shortcut;
    std::string ocio_config;
    int threads = 0;
    bool json = false;
    bool quiet = false;
};

// Where the image's pixels lie in the frame: its data window (a region) in
// the frame's display window.
FramePlacement frame_placement(const RenderedImage& image)
{
    return {image.x0, image.y0, image.frame_width, image.frame_height};
}

Status write_aov(const std::string& path, const RenderedImage& image, const std::vector<float>& values,
                 const std::string& name, const ColorConfig& config)
{
    ImageAttributes a;
    a.text = {{"cmfilter:kind", "render-aov"}, {"cmfilter:aov", name}, {"cmfilter:version", version()}};
    return write_rgb_image(path, image.width, image.height, 1, values, "", a, config, frame_placement(image));
}

// "surface 0: 128 x 8 sqrt table, 12288 bytes (1.56% of 256 x 256); ..."
std::string describe_table(std::size_t surface, const ColorLayer& m)
{
    const TableAxes& ax = m.table.axes();
    const GaussianColorTableOptions defaults;
    const std::size_t bytes = m.table.data().size() * sizeof(float);
    const std::size_t default_bytes = TableSize{defaults.values, defaults.sigmas, defaults.spacing}.bytes();
    std::ostringstream s;
    s << "surface " << surface << ": " << ax.values << " x " << ax.sigmas << " " << to_string(ax.spacing) << " table, "
      << bytes << " bytes (" << std::setprecision(3)
      << 100.0 * static_cast<double>(bytes) / static_cast<double>(default_bytes) << "% of " << defaults.values << " x "
      << defaults.sigmas << ")";
    if (m.fit.tolerance > 0)
        s << ", lookup CIEDE2000 " << m.fit.statistic << " " << m.fit.error << " <= " << m.fit.tolerance
          << " over sigma [0, " << m.fit.sigma_max << "]";
    if (m.fit.plain_bound > 0)
        s << "; C0(mean) directly below sigma " << m.plain.smallest() << " to " << m.plain.largest() << " (median "
          << m.plain.median() << ", by mean; within " << m.fit.plain_bound
          << " CIEDE2000 of the exact filtered colour)";
    return s.str();
}

nlohmann::json table_json(const ColorLayer& m)
{
    const TableAxes& ax = m.table.axes();
    nlohmann::json j = {
        {"values", ax.values},
        {"sigmas", ax.sigmas},
        {"spacing", to_string(ax.spacing)},
        {"sigma_max", ax.sigma_max},
        {"bytes", m.table.data().size() * sizeof(float)},
        {"plain_bound", m.fit.plain_bound},
        {"plain_sigma",
         {{"smallest", m.plain.smallest()}, {"median", m.plain.median()}, {"largest", m.plain.largest()}}}};
    if (m.fit.tolerance > 0)
        j["tolerance"] = {{"de2000", m.fit.tolerance},
                          {"statistic", m.fit.statistic},
                          {"reached", m.fit.error},
                          {"sigma_max_source", m.fit.sigma_max_how},
                          {"candidates", m.fit.candidates}};
    return j;
}

// The segment pyramids the render read: each surface's rendered with
// segments (--method segments, or auto's choice), the scene's driver/segments
// or baked for the render.
struct SegmentPyramidUse {
    std::size_t surface = 0;
    const SegmentPyramidTexture* pyramid = nullptr;
    bool baked = false;
};

std::vector<SegmentPyramidUse> segment_pyramids_used(const std::vector<Material>& materials, RenderMethod method,
                                                     const std::vector<SurfaceMethodChoice>& choices)
{
    std::vector<SegmentPyramidUse> out;
    for (std::size_t i = 0; i < materials.size(); ++i) {
        const auto* texture = std::get_if<TextureDriver>(&materials[i].driver);
        if (!texture || !texture->segments) continue;
        bool used = method == RenderMethod::Segments;
        for (const SurfaceMethodChoice& c : choices)
            if (c.surface == i) used = c.choice.choice()->method == FilterMethod::Segments;
        if (used) out.push_back({i, &*texture->segments, materials[i].provenance.segments_file != nullptr});
    }
    return out;
}

// "surface 0: segment pyramid 'S.exr', 14 breakpoints, 13 channels (52 bytes
// a texel), the map's colours at them, read into memory"
std::string describe_segment_pyramid(const SegmentPyramidUse& u)
{
    const SegmentPyramidInfo& info = u.pyramid->info();
    std::ostringstream s;
    s << "surface " << u.surface << ": segment pyramid "
      << (u.baked ? std::string("baked for this render") : "'" + u.pyramid->path() + "'") << ", "
      << info.breakpoints.size() << " breakpoints, " << info.channels() << " channel"
      << (info.channels() == 1 ? "" : "s") << " (" << info.bytes_per_texel() << " bytes a texel), "
      << (info.weights() ? "least-squares colours" : "the map's colours at them") << ", read "
      << (u.pyramid->reads() == PyramidReads::Memory ? "into memory" : "through TextureSystem");
    return s.str();
}

nlohmann::json segment_pyramid_json(const SegmentPyramidUse& u)
{
    const SegmentPyramidInfo& info = u.pyramid->info();
    nlohmann::json j = {{"surface", u.surface},
                        {"breakpoints", info.breakpoints.size()},
                        {"channels", info.channels()},
                        {"bytes_per_texel", info.bytes_per_texel()},
                        {"colors", info.weights() ? "least-squares" : "interpolant"},
                        {"reads", u.pyramid->reads() == PyramidReads::Memory ? "memory" : "texture-system"}};
    if (!u.baked) j["path"] = u.pyramid->path();
    return j;
}

// The fields render's errors name, as its flags.
FieldFlags render_flags()
{
    FieldFlags flags = color_map_flags();
    flags.insert(flags.end(), {{"RenderOptions::region", "--region"},
                               {"RenderOptions::samples", "--spp"},
                               {"RenderOptions::max_probes", "--probes"},
                               {"SubFootprintOptions::max_cells", "--sub-footprints"},
                               {"TableChoiceOptions::tolerance", "--tolerance"},
                               {"TableChoiceOptions::plain_bound", "--shortcut"},
                               {"MethodChoiceOptions::tolerance", "--tolerance"},
                               {"MethodChoiceOptions::lods", "--measure-lods"},
                               {"MomentBakeOptions::order 4", "bake-moments --order 4"},
                               {"ApplyOptions::histograms_path", "a histogram pyramid"},
                               {"MaterialOptions::segments", "--method segments"}});
    return flags;
}

// --method auto's choices as one metadata value, "0: mixture, 2: naive":
// each chosen surface's index and `value` of its choice.
template <typename Choices, typename Value>
std::string surface_list(const Choices& choices, Value value)
{
    std::string list;
    for (const auto& c : choices)
        list += (list.empty() ? "" : ", ") + std::to_string(c.surface) + ": " + value(*c.choice.choice());
    return list;
}

Status run(const RenderArgs& args)
{
    if (auto st = check_rgb_image_output(args.output); !st) return st;
    // auto: each texture surface's method and each noise surface's
    // sub-footprints chosen for --tolerance (render_method_choice.cpp), each
    // microsurface's method (render/microsurface_method_choice.h); every
    // other surface gaussian.
    const bool automatic = args.method == "auto";
    if (automatic && !args.tolerance)
        return bad_input("--method auto chooses each texture's and microsurface's method and each noise's "
                         "sub-footprints for a tolerance: it needs --tolerance DE");
    auto method = parse_render_method(automatic ? "gaussian" : args.method);
    if (!method) return method.error();
    auto footprint = parse_footprint_width(args.footprint);
    if (!footprint) return footprint.error();
    if (auto st = check_render_samples(args.samples); !st) return st;
    if (args.tolerance && !(std::isfinite(*args.tolerance) && *args.tolerance > 0)) {
        std::ostringstream msg;
        msg << "--tolerance " << *args.tolerance << " is invalid (expected a CIEDE2000 difference > 0)";
        return bad_input(msg.str());
    }
    if (auto st = check_plain_bound(args.shortcut); !st) return st;
    if (args.masking != "uncorrelated" && args.masking != "correlated")
        return bad_input("--masking '" + args.masking + "' is unknown (expected uncorrelated or correlated)");
    if (args.slope_shading != "uncorrelated" && args.slope_shading != "correlated")
        return bad_input("--slope-shading '" + args.slope_shading +
                         "' is unknown (expected uncorrelated or correlated)");
    const std::string aov_paths[3] = {args.aov + ".mean.exr", args.aov + ".sigma.exr", args.aov + ".lod.exr"};
    const std::string shaded_path = args.aov + ".shaded.exr";
    if (!args.aov.empty()) {
        for (const auto& path : aov_paths)
            if (auto st = check_rgb_image_output(path, true); !st) return st;
        if (auto st = check_rgb_image_output(shaded_path, true); !st) return st;
    }
    std::optional<std::pair<int, int>> size;
    if (!args.size.empty()) {
        auto parsed = parse_image_size("--size", args.size);
        if (!parsed) return parsed.error();
        size = *parsed;
    }
    // A region is written as an OpenEXR data window inside the frame's
    // display window, which PNG and JPEG cannot hold.
    std::optional<PixelRegion> region;
    if (!args.region.empty()) {
        if (lowercase_extension(args.output) != ".exr")
            return bad_input("--region '" + args.region + "' needs an OpenEXR output (expected -o ending in .exr, " +
                             "whose data window places the region in the frame; got '" + args.output + "')");
        auto parsed = parse_region("--region", args.region);
        if (!parsed) return parsed.error();
        region = *parsed;
    }
    auto scene = load_scene(args.scene);
    if (!scene) return scene.error();
    // A preview at another size: the same camera and field of view (vertical),
    // so a different aspect ratio shows more or less to the sides.
    if (size) std::tie(scene->camera.width, scene->camera.height) = *size;
    // Checked before the materials are prepared (their tables may take a while).
    if (region)
        if (auto st = check_pixel_region(*region, scene->camera.width, scene->camera.height); !st) return st;
    auto config = load_color_config(args.ocio_config);
    if (!config) return config.error();

    const bool talk = !args.quiet && !args.json;
    MaterialOptions material_options;
    material_options.threads = args.threads;
    set_method_materials(*method, material_options);
    // segments: the fewest breakpoints within --tolerance, else all the map's.
    material_options.segments_tolerance = args.tolerance.value_or(0.0);
    material_options.tables.tolerance = args.tolerance;
    material_options.tables.plain_bound = args.shortcut;
    if (talk) material_options.note = [](const std::string& line) { std::cerr << "render: " << line << "\n"; };
    auto materials = prepare_materials(*scene, *config, material_options);
    if (!materials) return materials.error();
    RenderOptions options;
    options.method = *method;
    options.samples = args.samples;
    options.seed = args.seed;
    options.threads = args.threads;
    options.footprint = *footprint;
    if (auto st = check_render_probes(args.probes); !st) return st;
    options.max_probes = args.probes;
    options.sub_footprints.max_cells = args.sub_footprints;
    options.edge_coverage = !args.no_edge_coverage;
    options.masking = args.masking == "correlated" ? MaskingShadowing::DirectionCorrelated
                                                   : MaskingShadowing::Uncorrelated;
    options.slope_shading = args.slope_shading == "correlated" ? SlopeShading::Correlated : SlopeShading::Uncorrelated;
    options.region = region;
    std::vector<SurfaceMethodChoice> choices;
    std::vector<RenderMethod> texture_methods;
    std::vector<SurfaceSubFootprintChoice> noise_choices;
    std::vector<int> noise_sub_footprints;
    std::vector<SurfaceMicrosurfaceChoice> microsurface_choices;
    std::vector<RenderMethod> microsurface_methods;
    if (automatic) {
        // Without --measure-lods, each texture and noise is measured at the
        // LODs the view reaches on it: the whole frame's centre rays,
        // surveyed first.
        std::optional<std::vector<SurfaceLodRange>> view;
        const bool measured = std::any_of(materials->begin(), materials->end(), [](const Material& m) {
            return (has_noise_driver(m) || std::holds_alternative<TextureDriver>(m.driver)) && !is_microsurface(m);
        });
        if (args.measure_lods.empty() && measured) {
            auto seen = survey_surface_lods(*scene, *materials, options);
            if (!seen) return seen.error();
            view = std::move(*seen);
            for (std::size_t i = 0; i < view->size(); ++i) {
                const Material& m = (*materials)[i];
                if (talk && (*view)[i].pixels == 0 && !is_microsurface(m) &&
                    (has_noise_driver(m) || std::holds_alternative<TextureDriver>(m.driver)))
                    std::cerr << "render: surface " << i << ": no pixel sees it; its methods are not measured\n";
            }
        }
        MethodChoiceOptions co;
        co.tolerance = *args.tolerance;
        co.lods = args.measure_lods;
        if (talk) std::cerr << "render: measuring each texture's methods for --tolerance " << *args.tolerance << "\n";
        auto chosen = choose_texture_methods(*scene, *materials, *config, co, view ? &*view : nullptr, args.threads);
        if (!chosen) return chosen.error();
        choices = std::move(*chosen);
        texture_methods.assign(materials->size(), RenderMethod::Gaussian);
        bool mixture = false;
        for (SurfaceMethodChoice& c : choices) {
            for (std::string& why : c.choice.skipped) why = name_flags(why, render_flags());
            const RenderMethod m = render_method_of(c.choice.choice()->method);
            texture_methods[c.surface] = m;
            mixture |= m == RenderMethod::Mixture;
            if (m == RenderMethod::Exact)
                if (auto st = prepare_surface_histograms(*scene, *materials, c.surface, material_options); !st)
                    return st;
            auto* texture = std::get_if<TextureDriver>(&(*materials)[c.surface].driver);
            if (m == RenderMethod::Segments && texture && !texture->segments)
                if (auto st = open_segments(*scene, c.surface, (*materials)[c.surface], c.segments_path,
                                            std::move(c.segments_file));
                    !st)
                    return st;
        }
        if (mixture) {
            material_options.moment_order = 4;
            if (auto st = prepare_moment_order(*scene, *materials, material_options); !st) return st;
        }
        if (talk)
            std::cerr << "render: measuring each noise's sub-footprints for --tolerance " << *args.tolerance << "\n";
        auto squares = choose_noise_sub_footprints(*scene, *materials, *args.tolerance, args.measure_lods,
                                                   view ? &*view : nullptr, args.threads);
        if (!squares) return squares.error();
        noise_choices = std::move(*squares);
        noise_sub_footprints.assign(materials->size(), 0);
        for (const SurfaceSubFootprintChoice& c : noise_choices)
            noise_sub_footprints[c.surface] = c.choice.choice()->max_cells;
        if (std::any_of(materials->begin(), materials->end(), is_microsurface)) {
            if (talk)
                std::cerr << "render: measuring each microsurface's methods for --tolerance " << *args.tolerance
                          << "\n";
            MicrosurfaceChoiceOptions mo;
            mo.tolerance = *args.tolerance;
            mo.render = options;
            auto measured_microsurfaces = choose_microsurface_methods(*scene, *materials, mo);
            if (!measured_microsurfaces) return measured_microsurfaces.error();
            microsurface_choices = std::move(*measured_microsurfaces);
            microsurface_methods.assign(materials->size(), RenderMethod::Gaussian);
            for (const SurfaceMicrosurfaceChoice& c : microsurface_choices) {
                if (!c.choice.choice())  // exact, the reference, is among the candidates
                    return bad_input("surface " + std::to_string(c.surface) + " (" + scene->path +
                                     "): no method meets --tolerance " + std::to_string(*args.tolerance));
                microsurface_methods[c.surface] = c.choice.choice()->method;
            }
            for (std::size_t i = 0; i < materials->size(); ++i)
                if (talk && is_microsurface((*materials)[i]) &&
                    std::none_of(microsurface_choices.begin(), microsurface_choices.end(),
                                 [i](const SurfaceMicrosurfaceChoice& c) { return c.surface == i; }))
                    std::cerr << "render: surface " << i << ": no pixel sees it; its methods are not measured\n";
        }
    }

    options.texture_methods = texture_methods;
    options.noise_sub_footprints = noise_sub_footprints;
    options.microsurface_methods = microsurface_methods;
    std::vector<SurfaceProbeChoice> probe_choices;
    if (automatic) {
        // Last, with each surface's method: the fewest probes that stay
        // within --tolerance of --probes' (surface_probe_choice.h).
        if (talk) std::cerr << "render: measuring each surface's probes for --tolerance " << *args.tolerance << "\n";
        ProbeChoiceOptions po;
        po.tolerance = *args.tolerance;
        po.render = options;
        auto probes = choose_surface_probes(*scene, *materials, po);
        if (!probes) return probes.error();
        probe_choices = std::move(*probes);
        options.surface_probes.assign(materials->size(), 0);
        for (const SurfaceProbeChoice& c : probe_choices) {
            if (!c.choice.choice())  // the ceiling, the reference, is among the candidates
                return bad_input("surface " + std::to_string(c.surface) + " (" + scene->path +
                                 "): no probe count meets --tolerance " + std::to_string(*args.tolerance));
            options.surface_probes[c.surface] = c.choice.choice()->probes;
        }
    }
    if (talk && isatty(STDERR_FILENO)) options.progress = terminal_progress("render");
    auto image = render(*scene, *materials, options);
    if (!image) return image.error();

    ImageAttributes a;
    a.text = {{"cmfilter:kind", "render"},
              {"cmfilter:version", version()},
              {"cmfilter:scene", path_for_record(scene->path, args.output)},
              {"cmfilter:method", automatic ? "auto" : to_string(image->method)},
              {"cmfilter:footprint", to_string(options.footprint)}};
    if (automatic) {  // each surface's choices
        const auto method_name = [](const auto& t) { return std::string(to_string(t.method)); };
        a.text.push_back({"cmfilter:texture_methods", surface_list(choices, method_name)});
        a.text.push_back({"cmfilter:noise_sub_footprints",
                          surface_list(noise_choices, [](const auto& t) { return std::to_string(t.max_cells); })});
        a.text.push_back({"cmfilter:microsurface_methods", surface_list(microsurface_choices, method_name)});
        a.text.push_back({"cmfilter:surface_probes",
                          surface_list(probe_choices, [](const auto& t) { return std::to_string(t.probes); })});
    }
    a.numbers = {{"cmfilter:samples", static_cast<double>(image->samples)},
                 {"cmfilter:seed", static_cast<double>(args.seed)}};
    if (automatic) a.numbers.push_back({"cmfilter:method_tolerance", *args.tolerance});
    if (*method == RenderMethod::Mixture && !automatic)
        a.numbers.push_back({"cmfilter:sub_footprints", static_cast<double>(options.sub_footprints.max_cells)});
    if (auto st = write_rgb_image(args.output, image->width, image->height, 3, image->rgb, config->scene_linear_name(),
                                  a, *config, frame_placement(*image));
        !st)
        return st;
    if (!args.aov.empty()) {
        if (auto st = write_aov(aov_paths[0], *image, image->mean, "mean", *config); !st) return st;
        if (auto st = write_aov(aov_paths[1], *image, image->sigma, "sigma", *config); !st) return st;
        if (auto st = write_aov(aov_paths[2], *image, image->lod, "lod", *config); !st) return st;
        if (!image->shaded.empty()) {
            // The ray-traced microsurfaces, fully shaded (render.h).
            a.text.push_back({"cmfilter:aov", "shaded"});
            if (auto st = write_rgb_image(shaded_path, image->width, image->height, 3, image->shaded,
                                          config->scene_linear_name(), a, *config, frame_placement(*image));
                !st)
                return st;
        }
    }

    std::size_t hits = 0;
    for (unsigned char h : image->hit) hits += h;
    const std::vector<SegmentPyramidUse> segments_used = segment_pyramids_used(*materials, *method, choices);
    if (args.json) {
        nlohmann::json j;
        j["output"] = args.output;
        j["scene"] = scene->path;
        j["method"] = automatic ? "auto" : to_string(image->method);
        if (automatic) {
            j["texture_methods"] = nlohmann::json::array();
            for (const SurfaceMethodChoice& c : choices)
                j["texture_methods"].push_back({{"surface", c.surface}, {"choice", method_choice_json(c.choice)}});
            j["noise_sub_footprints"] = nlohmann::json::array();
            for (const SurfaceSubFootprintChoice& c : noise_choices)
                j["noise_sub_footprints"].push_back(
                    {{"surface", c.surface}, {"choice", sub_footprint_choice_json(c.choice)}});
            j["microsurface_methods"] = nlohmann::json::array();
            for (const SurfaceMicrosurfaceChoice& c : microsurface_choices)
                j["microsurface_methods"].push_back(
                    {{"surface", c.surface}, {"choice", microsurface_choice_json(c.choice)}});
            j["surface_probes"] = nlohmann::json::array();
            for (const SurfaceProbeChoice& c : probe_choices)
                j["surface_probes"].push_back({{"surface", c.surface}, {"choice", probe_choice_json(c.choice)}});
        }
        j["samples"] = image->samples;
        j["seed"] = args.seed;
        j["footprint"] = to_string(options.footprint);
        j["masking"] = args.masking;
        j["slope_shading"] = args.slope_shading;
        j["edge_coverage"] = options.edge_coverage && *method != RenderMethod::Supersample &&
                             *method != RenderMethod::Reference;
        if (*method == RenderMethod::Mixture && !automatic) j["sub_footprints"] = options.sub_footprints.max_cells;
        j["size"] = {image->frame_width, image->frame_height};
        // The pixels computed and written (the whole frame without --region).
        j["region"] = {image->x0, image->y0, image->x0 + image->width, image->y0 + image->height};
        j["pixels_hit"] = hits;
        j["seconds"] = image->seconds;
        j["tables"] = nlohmann::json::array();
        for (const Material& m : *materials) j["tables"].push_back(table_json(table_layer(m)));
        if (!segments_used.empty()) {
            j["segment_pyramids"] = nlohmann::json::array();
            for (const SegmentPyramidUse& u : segments_used) j["segment_pyramids"].push_back(segment_pyramid_json(u));
        }
        if (image->method == RenderMethod::Gaussian || image->method == RenderMethod::Mixture)
            j["footprints"] = {{"filtered", image->footprints}, {"plain", image->plain_footprints}};
        if (!args.aov.empty()) {
            j["aov"] = {aov_paths[0], aov_paths[1], aov_paths[2]};
            if (!image->shaded.empty()) j["aov"].push_back(shaded_path);
        }
        print_json("render", std::move(j));
    } else if (!args.quiet) {
        std::cout << "wrote " << args.output << ": ";
        if (region)
            std::cout << "region " << to_string(*region) << " (" << image->width << " x " << image->height << ") of ";
        std::cout << image->frame_width << " x " << image->frame_height << ", "
                  << (automatic ? "auto" : to_string(image->method)) << ", " << image->samples << " ray(s) per pixel, "
                  << hits << " pixels on a surface, " << image->seconds << " s\n";
        if (image->method == RenderMethod::Gaussian || image->method == RenderMethod::Mixture) {
            for (std::size_t i = 0; i < materials->size(); ++i)
                std::cout << "  " << describe_table(i, table_layer((*materials)[i])) << "\n";
            std::cout << "  " << image->plain_footprints << " of " << image->footprints
                      << " footprints took C0(mean) directly\n";
        }
        for (const SegmentPyramidUse& u : segments_used) std::cout << "  " << describe_segment_pyramid(u) << "\n";
        for (const SurfaceMethodChoice& c : choices) {
            std::cout << "  surface " << c.surface << ": " << to_string(c.choice.choice()->method) << "\n";
            print_method_choice(std::cout, c.choice);
        }
        for (const SurfaceSubFootprintChoice& c : noise_choices) {
            const int n = c.choice.choice()->max_cells;
            std::cout << "  surface " << c.surface << ": "
                      << (n > 1 ? "mixture, up to " + std::to_string(n) + " x " + std::to_string(n) + " squares"
                                : std::string("gaussian (one square)"))
                      << "\n";
            print_sub_footprint_choice(std::cout, c.choice);
        }
        for (const SurfaceMicrosurfaceChoice& c : microsurface_choices) {
            std::cout << "  surface " << c.surface << ": " << to_string(c.choice.choice()->method) << "\n";
            print_microsurface_choice(std::cout, c.choice);
        }
        for (const SurfaceProbeChoice& c : probe_choices) {
            const int n = c.choice.choice()->probes;
            std::cout << "  surface " << c.surface << ": up to " << n << (n == 1 ? " probe\n" : " probes\n");
            print_probe_choice(std::cout, c.choice);
        }
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
    app->add_option(
           "--method", args->method,
           "naive, gaussian, gaussian-exact (microsurfaces: D_h's exact moments), mixture (texture drivers: two Gaussians of four moments; noise drivers: a Gaussian per square of a footprint cut into up to --sub-footprints squares per axis in the transition; others as gaussian), exact (microsurfaces, or texture drivers with at most 256 values), color-pyramid (texture drivers: the box means of C0(f)), segments (texture drivers: the ramp means between the map's breakpoints, the scene's driver/segments or baked for the map; with --tolerance, the fewest breakpoints within it), supersample, reference, or auto (with --tolerance: each texture's and each microsurface's cheapest method, each noise's fewest sub-footprints and then each surface's fewest probes (up to --probes) that meet it, measured; others gaussian)")
        ->capture_default_str();
    app->add_option("--size,--resolution", args->size,
                    "Render at WxH instead of the scene's camera resolution (the same camera and vertical field "
                    "of view)");
    app->add_option("--region", args->region,
                    "Render only the pixels x0,y0,x1,y1 of the frame (after --size; x0,y0 inclusive, x1,y1 "
                    "exclusive), each exactly as the whole frame's render has it, written as an OpenEXR data "
                    "window in the frame (docs/farm.md)");
    app->add_option("--spp", args->samples, "Rays per pixel for supersample (reference: at least 1024)")
        ->capture_default_str();
    app->add_option("--seed", args->seed, "Seed of the sub-pixel samples")->capture_default_str();
    app->add_option("--footprint", args->footprint, "Width of an anisotropic footprint: rms, area, major or minor")
        ->capture_default_str();
    app->add_option("--probes", args->probes,
                    "Filter an anisotropic footprint as up to N probes along its major edge (naive, gaussian, exact)")
        ->capture_default_str();
    app->add_option("--sub-footprints", args->sub_footprints,
                    "mixture, noise drivers: cut a footprint (or probe) in the transition into up to N x N squares, "
                    "one Gaussian each (1 to 16; 1: as gaussian; --method auto measures it per noise instead)")
        ->capture_default_str();
    app->add_option("--masking", args->masking,
                    "Microsurfaces: masking and shadowing correlated by the view's and the light's azimuths "
                    "(correlated) or independent (uncorrelated, the paper's eq. 13)")
        ->capture_default_str();
    app->add_option("--slope-shading", args->slope_shading,
                    "Microsurfaces coloured by slope: each slope weighted by its facet's cosine to the light "
                    "(correlated) or the facets' shading independent of their colour (uncorrelated, the paper's "
                    "eq. 19)")
        ->capture_default_str();
    app->add_flag("--no-edge-coverage", args->no_edge_coverage,
                  "naive, gaussian, exact: take the centre ray's surface for the whole pixel, also on silhouettes "
                  "and horizons");
    app->add_option(
        "--tolerance", args->tolerance,
        "Give every surface the smallest table whose lookup error (CIEDE2000, p99.9 against the exact "
        "filtered colour) is at most DE over that surface's sigma range (default: the scene's "
        "colormap tolerance, else the fixed 256 x 256 table); with --method segments, also the fewest breakpoints whose "
        "mean CIEDE2000 stays within DE at LOD 1-8 (default: every breakpoint of the map)");
    app->add_option("--shortcut", args->shortcut,
                    "gaussian: take C0(mean) directly where sigma is so small that the exact filtered colour is "
                    "within this CIEDE2000 of it (default: a tenth of the tolerance for a fitted table, else off; "
                    "0: off)");
    app->add_option("--aov", args->aov,
                    "Also write PREFIX.mean.exr, PREFIX.sigma.exr and PREFIX.lod.exr (and, for supersample and "
                    "reference on a microsurface, PREFIX.shaded.exr: the fully shaded image)");
    app->add_option("--ocio-config,--colorconfig", args->ocio_config,
                    "OpenColorIO config (default: $OCIO if set, else the built-in config)");
    app->add_option("--threads", args->threads, "Threads (0: all cores)")->capture_default_str();
    app->add_flag("--json", args->json, "Print a machine-readable summary on stdout");
    app->add_flag("-q,--quiet", args->quiet, "Print nothing on success (and no progress)");
    add_measure_lods_option(*app, args->measure_lods, true);
    return {app, [args] { return run(*args); }, render_flags()};
}

}  // namespace cmfilter::cli
