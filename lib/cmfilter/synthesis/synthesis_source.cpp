// SPDX-License-Identifier: Apache-2.0
// What synth-apply renders through a coordinate map (sec. 4.2: "one more
// texture lookup" into the sample, or into a fit of it, sec. 5): one image
// of an image, a stack or a BTF, or a fit relit at a light.
#include "cmfilter/synthesis/synthesis_source.h"

#include "cmfilter/stack/stack_encoding.h"

#include "cmfilter/io/image_reading.h"
#include "cmfilter/stack/btf_manifest.h"
#include "cmfilter/stack/fit_file.h"
#include "cmfilter/stack/image_stack.h"
#include "cmfilter/stack/lafortune_file.h"
#include "cmfilter/stack/light_file.h"
#include "cmfilter/stack/stack_fit.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <variant>
#include <vector>

namespace cmfilter {

namespace {

// Directions are taken as the same within this distance (unit vectors).
constexpr double kDirectionTolerance = 1e-3;

std::string number(double v)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

std::string direction_text(const Vec3& d) { return "(" + number(d.x) + ", " + number(d.y) + ", " + number(d.z) + ")"; }

std::string lower_extension(const std::string& path)
{
    const auto slash = path.find_last_of("/\\");
    const auto dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    std::string ext = path.substr(dot + 1);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

// A direction given by the user, unit; BadInput naming `field` when zero,
// non-finite, or (`above` > 0: strictly; else z >= 0) below the horizon.
Expected<Vec3> unit_direction(const Vec3& d, const char* field, bool strictly_above)
{
    const double len = length(d);
    if (!std::isfinite(len) || len <= 0)
        return bad_input(std::string(field) + " " + direction_text(d) + " is invalid: expected a non-zero direction",
                         field);
    const Vec3 u = normalize(d);
    if (strictly_above ? u.z <= 0 : u.z < 0)
        return bad_input(std::string(field) + " " + direction_text(d) + " is below the horizon: expected z " +
                             (strictly_above ? "> 0" : ">= 0"),
                         field);
    return u;
}

bool same_direction(const Vec3& a, const Vec3& b) { return length(a - b) <= kDirectionTolerance; }

// The kind of file `path` names, by extension, and an EXR by its
// cmfilter:kind (a fit's kinds; any other EXR is an image).
enum class SourceKind { Image, Stack, Btf, Fit };

Expected<SourceKind> source_kind(const std::string& path)
{
    const std::string ext = lower_extension(path);
    if (ext == "lp") return SourceKind::Stack;
    if (ext == "json") return SourceKind::Btf;
    if (ext == "ptm" || ext == "rti") return SourceKind::Fit;
    if (ext == "exr") {
        auto in = open_image_input(path);
        if (!in) return in.error();
        const std::string kind = (*in)->spec().get_string_attribute("cmfilter:kind");
        (*in)->close();
        if (kind == kLinearFitKind || kind == kLafortuneFitKind) return SourceKind::Fit;
    }
    return SourceKind::Image;
}

// One slot of the sample: its light file's images (a BTF: one view's).
struct Slot {
    LightFile lights;
    Vec3 view{0, 0, 1};
};

SampleImage to_sample_image(ImageData&& data, bool periodic)
{
    SampleImage image;
    image.width = data.width;
    image.height = data.height;
    image.channels = data.channels;
    image.pixels = std::move(data.pixels);
    image.periodic = periodic;
    return image;
}

Expected<SourceImage> load_fit_source(const SourceOptions& options, const ColorConfig& config)
{
    if (options.image >= 0)
        return bad_input("SourceOptions::image " + std::to_string(options.image) + " cannot be read from the fit '" +
                             options.path + "': a fit is relit at a light (expected a light, or no image index)",
                         "SourceOptions::image");
    Vec3 light{0, 0, 1};
    if (options.light) {
        auto u = unit_direction(*options.light, "SourceOptions::light", false);
        if (!u) return u.error();
        light = *u;
    }
    std::optional<Vec3> view;
    if (options.view) {
        auto u = unit_direction(*options.view, "SourceOptions::view", true);
        if (!u) return u.error();
        view = *u;
    }
    auto fit = load_stack_fit(options.path);
    if (!fit) return fit.error();
    if (view && std::holds_alternative<LinearFit>(*fit) && !same_direction(*view, Vec3{0, 0, 1}))
        return bad_input("SourceOptions::view " + direction_text(*options.view) + " cannot be rendered from the " +
                             stack_fit_model_name(*fit) + " fit '" + options.path +
                             "': a PTM/HSH holds one view, (0, 0, 1) (a Lafortune fit renders other views)",
                         "SourceOptions::view");
    if (std::holds_alternative<LinearFit>(*fit)) view.reset();
    auto pixels = relight_stack_fit(*fit, light, view, options.threads);
    if (!pixels) return prefixed("'" + options.path + "': ", pixels.error());
    SourceImage source;
    source.image.width = stack_fit_width(*fit);
    source.image.height = stack_fit_height(*fit);
    source.image.channels = stack_fit_channels(*fit);
    // Display-encoded fits (.ptm, .rti) are decoded: a source is always
    // scene-linear, so that filtering through the map averages light.
    if (auto st = convert_stack_encoding(*pixels, stack_fit_channels(*fit), stack_fit_encoding(*fit),
                                         StackEncoding::SceneLinear, config);
        !st)
        return prefixed("'" + options.path + "': ", st.error());
    source.image.pixels = std::move(*pixels);
    source.image.periodic = options.periodic;
    source.is_fit = true;
    source.colorspace = stack_fit_encoding(*fit) == StackEncoding::SceneLinear
                            ? std::visit([](const auto& f) { return f.colorspace; }, *fit)
                            : config.scene_linear_name();
    source.description = stack_fit_model_name(*fit) + " " + options.path + " relit at " + direction_text(light);
    if (view) source.description += " seen from " + direction_text(*view);
    return source;
}

Expected<SourceImage> load_plain_image(const SourceOptions& options, const ColorConfig& config)
{
    if (options.image > 0)
        return bad_input("SourceOptions::image " + std::to_string(options.image) + " is outside the sample '" +
                             options.path + "': an image is one image (expected 0)",
                         "SourceOptions::image");
    if (options.light)
        return bad_input("SourceOptions::light " + direction_text(*options.light) + " cannot be chosen in '" +
                             options.path + "': one image has no lights (expected a .lp, a BTF manifest or a fit)",
                         "SourceOptions::light");
    if (options.view)
        return bad_input("SourceOptions::view " + direction_text(*options.view) + " cannot be chosen in '" +
                             options.path + "': one image has one view (expected a BTF manifest or a Lafortune fit)",
                         "SourceOptions::view");
    StackLoadOptions load;
    load.colorspace = options.colorspace;
    load.threads = options.threads;
    auto image = load_stack_image(options.path, load, config);
    if (!image) return image.error();
    SourceImage source;
    source.colorspace = stack_colorspace(image->space, load, config);
    source.image = to_sample_image(std::move(image->data), options.periodic);
    source.description = "image " + options.path;
    return source;
}

Expected<SourceImage> load_slot_image(const SourceOptions& options, const ColorConfig& config)
{
    const bool btf = lower_extension(options.path) == "json";
    std::vector<Slot> slots;
    if (btf) {
        auto manifest = read_btf_manifest(options.path);
        if (!manifest) return manifest.error();
        for (std::size_t v = 0; v < manifest->views.size(); ++v) {
            auto lights = read_light_file(manifest->light_file_path(v));
            if (!lights) return lights.error();
            slots.push_back({std::move(*lights), manifest->views[v].view});
        }
    } else {
        auto lights = read_light_file(options.path);
        if (!lights) return lights.error();
        slots.push_back({std::move(*lights), Vec3{0, 0, 1}});
    }
    std::size_t total = 0;
    for (const Slot& s : slots) total += s.lights.lights.size();

    std::size_t slot = 0, index = 0;
    if (options.image >= 0) {
        if (static_cast<std::size_t>(options.image) >= total)
            return bad_input("SourceOptions::image " + std::to_string(options.image) + " is outside the sample '" +
                                 options.path + "': it has " + std::to_string(total) + " images (expected 0 .. " +
                                 std::to_string(total - 1) + ")",
                             "SourceOptions::image");
        index = static_cast<std::size_t>(options.image);
        while (index >= slots[slot].lights.lights.size()) index -= slots[slot++].lights.lights.size();
    } else {
        if (options.view) {
            auto view = unit_direction(*options.view, "SourceOptions::view", true);
            if (!view) return view.error();
            const auto found =
                std::find_if(slots.begin(), slots.end(), [&](const Slot& s) { return same_direction(s.view, *view); });
            if (found == slots.end())
                return bad_input("SourceOptions::view " + direction_text(*options.view) + " is none of the views of '" +
                                     options.path + "' (within " + number(kDirectionTolerance) + ")",
                                 "SourceOptions::view");
            slot = static_cast<std::size_t>(found - slots.begin());
        }
        if (options.light) {
            auto light = unit_direction(*options.light, "SourceOptions::light", false);
            if (!light) return light.error();
            const auto& entries = slots[slot].lights.lights;
            const auto found = std::find_if(entries.begin(), entries.end(),
                                            [&](const LightEntry& e) { return same_direction(e.direction, *light); });
            if (found == entries.end())
                return bad_input("SourceOptions::light " + direction_text(*options.light) +
                                     " is none of the lights of '" + slots[slot].lights.path + "' (within " +
                                     number(kDirectionTolerance) + ")",
                                 "SourceOptions::light");
            index = static_cast<std::size_t>(found - entries.begin());
        }
    }
    const Slot& chosen = slots[slot];
    StackLoadOptions load;
    load.light_file = chosen.lights.path;
    load.colorspace = options.colorspace;
    load.threads = options.threads;
    const std::string image_path = chosen.lights.image_path(index);
    auto image = load_stack_image(image_path, load, config);
    if (!image) return image.error();
    std::size_t across = index;
    for (std::size_t s = 0; s < slot; ++s) across += slots[s].lights.lights.size();
    SourceImage source;
    source.colorspace = stack_colorspace(image->space, load, config);
    source.image = to_sample_image(std::move(image->data), options.periodic);
    source.description = "image " + std::to_string(across) + " of " + options.path + " (light " +
                         direction_text(chosen.lights.lights[index].direction);
    if (btf) source.description += ", view " + direction_text(chosen.view);
    source.description += ")";
    return source;
}

}  // namespace

Expected<SourceImage> load_source_image(const SourceOptions& options, const ColorConfig& config)
{
    if (options.path.empty())
        return bad_input("SourceOptions::path is empty: expected an image, a .lp, a BTF manifest or a fit",
                         "SourceOptions::path");
    if (options.image < -1)
        return bad_input("SourceOptions::image " + std::to_string(options.image) +
                             " is invalid: expected an image index >= 0, or -1 to choose by light",
                         "SourceOptions::image");
    auto kind = source_kind(options.path);
    if (!kind) return kind.error();
    switch (*kind) {
    case SourceKind::Fit: return load_fit_source(options, config);
    case SourceKind::Image: return load_plain_image(options, config);
    case SourceKind::Stack:
    case SourceKind::Btf: return load_slot_image(options, config);
    }
    return runtime_error("unknown source kind");
}

Expected<bool> is_fit_source(const std::string& path)
{
    auto kind = source_kind(path);
    if (!kind) return kind.error();
    return *kind == SourceKind::Fit;
}

}  // namespace cmfilter
