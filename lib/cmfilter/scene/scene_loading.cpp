// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/scene/scene_loading.h"

#include "cmfilter/io/json_document.h"
#include "cmfilter/io/json_reading.h"
#include "cmfilter/noise/noise_spec.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <tuple>

namespace cmfilter {

namespace {

namespace fs = std::filesystem;

// Two vectors whose angle has a sine below this count as parallel.
constexpr double kParallelSine = 1e-6;

bool is_zero(const Vec3& v) { return v.x == 0 && v.y == 0 && v.z == 0; }

// v scaled so that its largest component is +-1: its length and cross
// products neither overflow nor underflow. v is non-zero.
Vec3 rescaled(const Vec3& v) { return v / std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}); }

bool nearly_parallel(const Vec3& a, const Vec3& b)
{
    const Vec3 ra = rescaled(a), rb = rescaled(b);
    return !(length(cross(ra, rb)) > kParallelSine * length(ra) * length(rb));
}

std::string vector_text(const Vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}).dump(); }

// "<pointer>/<key>: expected <expectation>, got <v>" for a vector member that
// may be absent (its default).
Error vector_error(const JsonObject& object, const std::string& key, const Vec3& v, const std::string& expectation)
{
    return object.value().member_error(key, "expected " + expectation + ", got " + vector_text(v) +
                                                (object.has(key) ? "" : " (the default)"));
}

// ---- values -----------------------------------------------------------------

Expected<Vec3> read_vec3(const JsonValue& value)
{
    auto numbers = read_numbers(value, 3);
    if (!numbers) return numbers.error();
    return Vec3{(*numbers)[0], (*numbers)[1], (*numbers)[2]};
}

Expected<Vec3> read_nonzero_vec3(const JsonValue& value)
{
    auto v = read_vec3(value);
    if (v && is_zero(*v)) return value.expected("a non-zero vector");
    return v;
}

// A non-zero vector, normalised.
Expected<Vec3> read_direction(const JsonValue& value)
{
    auto v = read_nonzero_vec3(value);
    if (!v) return v;
    return normalize(rescaled(*v));
}

Expected<Rgb> read_color(const JsonValue& value)
{
    auto numbers = read_numbers(value, 3);
    if (!numbers) return numbers.error();
    const std::vector<double>& c = *numbers;
    if (!(c[0] >= 0 && c[1] >= 0 && c[2] >= 0)) return value.expected("a colour of 3 numbers >= 0");
    return Rgb{c[0], c[1], c[2]};
}

Expected<double> read_positive(const JsonValue& value)
{
    auto number = read_number(value);
    if (number && !(*number > 0)) return value.expected("a number > 0");
    return number;
}

Expected<double> read_fov_degrees(const JsonValue& value)
{
    auto number = read_number(value);
    if (number && !(*number > 0 && *number < 180)) return value.expected("a number of degrees in (0, 180)");
    return number;
}

// An existing file named relative to the scene's folder (or absolute): the
// folder joined with the name, as the scene's own path names the folder.
Expected<std::string> read_file_path(const JsonValue& value, const fs::path& scene_folder)
{
    auto name = read_string(value);
    if (!name) return name;
    if (name->empty()) return value.expected("a file path");
    const fs::path resolved = scene_folder / *name;
    std::error_code ec;
    const fs::file_status status = fs::status(resolved, ec);
    if (!fs::exists(status)) return value.error("file not found: " + resolved.string());
    if (fs::is_directory(status)) return value.error("expected a file, got a directory: " + resolved.string());
    return resolved.string();
}

// ---- camera -----------------------------------------------------------------

Status read_resolution(const JsonObject& camera_object, SceneCamera& camera)
{
    const auto value = camera_object.find("resolution");
    if (!value) return ok();
    auto numbers = read_numbers(*value, 2);
    if (!numbers) return numbers.error();
    const std::string side_limit = " in 1.." + std::to_string(kMaxImageSide) + " (an integer)";
    for (std::size_t i = 0; i < 2; ++i) {
        const double side = (*numbers)[i];
        if (!(side >= 1 && side <= kMaxImageSide && side == std::floor(side)))
            return value->element(i).expected((i == 0 ? "a width" : "a height") + side_limit);
    }
    const int width = static_cast<int>((*numbers)[0]), height = static_cast<int>((*numbers)[1]);
    const long long pixels = static_cast<long long>(width) * height;
    if (pixels > kMaxImagePixels)
        return value->error("expected width * height <= " + std::to_string(kMaxImagePixels) + " pixels, got " +
                            std::to_string(width) + " x " + std::to_string(height) + " = " + std::to_string(pixels));
    camera.width = width;
    camera.height = height;
    return ok();
}

// The view direction look_at - position is finite and non-zero, and up is not
// parallel to it.
Status check_view(const JsonObject& camera_object, const SceneCamera& camera)
{
    const Vec3 view = camera.look_at - camera.position;
    if (!std::isfinite(view.x) || !std::isfinite(view.y) || !std::isfinite(view.z))
        return camera_object.value().member("look_at").expected("a point at a finite distance from position");
    if (is_zero(view))
        return camera_object.value().member("look_at").expected(
            "a point other than position (the view direction look_at - position is zero)");
    if (nearly_parallel(camera.up, view))
        return vector_error(camera_object, "up", camera.up,
                            "a vector not parallel to the view direction look_at - position = " + vector_text(view));
    return ok();
}

Expected<SceneCamera> read_camera(const JsonValue& value)
{
    auto object = JsonObject::read(value, {"position", "look_at", "up", "fov_degrees", "resolution"});
    if (!object) return object.error();
    SceneCamera camera;
    Status status = object->read_required("position", camera.position, read_vec3);
    if (status) status = object->read_required("look_at", camera.look_at, read_vec3);
    if (status) status = object->read_optional("up", camera.up, read_nonzero_vec3);
    if (status) status = object->read_optional("fov_degrees", camera.fov_degrees, read_fov_degrees);
    if (status) status = read_resolution(*object, camera);
    if (status) status = check_view(*object, camera);
    if (!status) return status.error();
    return camera;
}

// ---- light ------------------------------------------------------------------

Expected<SceneLight> read_light(const JsonValue& value)
{
    auto object = JsonObject::read(value, {"direction", "radiance", "ambient"});
    if (!object) return object.error();
    SceneLight light;
    Status status = object->read_optional("direction", light.direction, read_direction);
    if (status) status = object->read_optional("radiance", light.radiance, read_color);
    if (status) status = object->read_optional("ambient", light.ambient, read_color);
    if (!status) return status.error();
    return light;
}

// ---- material ---------------------------------------------------------------

Expected<WrapMode> read_wrap(const JsonValue& value)
{
    auto name = read_string(value);
    if (!name) return name.error();
    auto wrap = parse_wrap_mode(*name);
    if (!wrap) return value.error(wrap.error().message);
    return wrap;
}

Expected<std::pair<double, double>> read_domain(const JsonValue& value)
{
    auto numbers = read_numbers(value, 2);
    if (!numbers) return numbers.error();
    if (!((*numbers)[0] < (*numbers)[1])) return value.expected("[min, max] with min < max");
    return std::pair((*numbers)[0], (*numbers)[1]);
}

Expected<std::string> read_colorspace(const JsonValue& value)
{
    auto name = read_string(value);
    if (name && name->empty()) return value.expected("a colour space name");
    return name;
}

Expected<ColorMapSource> read_colormap(const JsonValue& value, const fs::path& scene_folder)
{
    auto object = JsonObject::read(value, {"table", "image", "domain", "wrap", "colorspace", "tolerance"});
    if (!object) return object.error();
    const auto read_path = [&](const JsonValue& v) { return read_file_path(v, scene_folder); };
    ColorMapSource colormap;
    Status status = object->require_one_of({"table", "image"});
    if (status && object->has("table")) {
        status = object->reject_any_of({"domain", "wrap", "colorspace", "tolerance"},
                                       "applies only to an image colour map, not to a table");
        if (status) status = object->read_required("table", colormap.table_path, read_path);
    } else if (status) {
        std::pair<double, double> domain;
        status = object->read_required("image", colormap.image_path, read_path);
        if (status) status = object->read_required("domain", domain, read_domain);
        if (status) status = object->read_optional("wrap", colormap.wrap, read_wrap);
        if (status) status = object->read_optional("colorspace", colormap.colorspace, read_colorspace);
        if (status) status = object->read_optional("tolerance", colormap.tolerance, read_positive);
        if (status) std::tie(colormap.domain_min, colormap.domain_max) = domain;
    }
    if (!status) return status.error();
    return colormap;
}

// The spec text as written, once parse_noise_spec accepts it.
Expected<std::string> read_noise_spec(const JsonValue& value)
{
    auto text = read_string(value);
    if (!text) return text;
    if (auto spec = parse_noise_spec(*text); !spec)
        return value.error("expected a noise spec (docs/noise.md), got " + value.json().dump() + ": " +
                           spec.error().message);
    return text;
}

Expected<DriverSource> read_driver(const JsonValue& value, const fs::path& scene_folder)
{
    auto object = JsonObject::read(value, {"noise", "sigma_table", "moments", "image", "segments"});
    if (!object) return object.error();
    const auto read_path = [&](const JsonValue& v) { return read_file_path(v, scene_folder); };
    DriverSource driver;
    Status status = object->require_one_of({"noise", "moments", "image"});
    if (!status) return status.error();
    if (object->has("noise")) {
        driver.kind = DriverKind::Noise;
        status = object->reject_any_of({"segments"}, "applies only to a texture driver (moments or image), not to "
                                                     "a noise");
        if (status) status = object->read_required("noise", driver.noise_spec, read_noise_spec);
        if (status) status = object->read_optional("sigma_table", driver.sigma_table_path, read_path);
    } else {
        const bool moments = object->has("moments");
        driver.kind = moments ? DriverKind::Moments : DriverKind::Image;
        status = object->reject_any_of({"sigma_table"}, std::string("applies only to a noise driver, not to ") +
                                                            (moments ? "moments" : "an image"));
        if (status && moments) status = object->read_required("moments", driver.moments_path, read_path);
        if (status && !moments) status = object->read_required("image", driver.image_path, read_path);
        if (status) status = object->read_optional("segments", driver.segments_path, read_path);
    }
    if (!status) return status.error();
    return driver;
}

Expected<double> read_non_negative(const JsonValue& value)
{
    auto number = read_number(value);
    if (number && !(*number >= 0)) return value.expected("a number >= 0");
    return number;
}

Expected<int> read_cosine_count(const JsonValue& value)
{
    const nlohmann::json& j = value.json();
    if (!j.is_number_integer() || j.get<long long>() < 1 || j.get<long long>() > kMaxMicrosurfaceCosines)
        return value.expected("an integer from 1 to " + std::to_string(kMaxMicrosurfaceCosines));
    return static_cast<int>(j.get<long long>());
}

Expected<std::uint64_t> read_seed(const JsonValue& value)
{
    const nlohmann::json& j = value.json();
    if (!j.is_number_unsigned() && !(j.is_number_integer() && j.get<long long>() >= 0))
        return value.expected("an integer >= 0");
    return j.get<std::uint64_t>();
}

// A Gaussian microsurface (gaussian_microsurface.h); the tile defaults to 8
// longest wavelengths.
Expected<GaussianMicrosurfaceOptions> read_microsurface(const JsonValue& value)
{
    auto object = JsonObject::read(value, {"sigma_h", "min_wavelength", "max_wavelength", "cosines", "seed", "tile"});
    if (!object) return object.error();
    GaussianMicrosurfaceOptions o;
    o.tile = -1;
    Status status = object->read_required("sigma_h", o.sigma_h, read_non_negative);
    if (status) status = object->read_required("min_wavelength", o.min_wavelength, read_positive);
    if (status) status = object->read_required("max_wavelength", o.max_wavelength, read_positive);
    if (status && o.max_wavelength < o.min_wavelength)
        return value.member("max_wavelength")
            .expected("a number >= min_wavelength " + std::to_string(o.min_wavelength));
    if (status) status = object->read_optional("cosines", o.cosines, read_cosine_count);
    if (status) status = object->read_optional("seed", o.seed, read_seed);
    if (status) status = object->read_optional("tile", o.tile, read_positive);
    if (!status) return status.error();
    if (o.tile < 0) o.tile = kMicrosurfaceTileWavelengths * o.max_wavelength;
    if (o.tile < o.max_wavelength)
        return value.member("tile").expected("a period >= max_wavelength " + std::to_string(o.max_wavelength));
    return o;
}

// A slope colour map (scene.h): a gradient over degrees, or an image over
// the slope plane.
Expected<SlopeColorMapSource> read_slope_colormap(const JsonValue& value, const fs::path& scene_folder)
{
    auto object = JsonObject::read(value, {"image", "by", "domain", "wrap", "max_slope", "colorspace"});
    if (!object) return object.error();
    SlopeColorMapSource map;
    Status status = object->read_required("by", map.kind, [](const JsonValue& v) {
        return read_choice<SlopeMapKind>(v, {{"steepness", SlopeMapKind::Steepness}, {"vector", SlopeMapKind::Vector}});
    });
    if (status)
        status = object->read_required("image", map.image_path,
                                       [&](const JsonValue& v) { return read_file_path(v, scene_folder); });
    if (status) status = object->read_optional("colorspace", map.colorspace, read_colorspace);
    if (status && map.kind == SlopeMapKind::Steepness) {
        std::pair<double, double> domain{map.domain_min, map.domain_max};
        status = object->reject_any_of({"max_slope"}, "applies only to a slope-vector map (\"by\": \"vector\")");
        if (status) status = object->read_optional("domain", domain, read_domain);
        if (status) status = object->read_optional("wrap", map.wrap, read_wrap);
        std::tie(map.domain_min, map.domain_max) = domain;
    } else if (status) {
        status = object->reject_any_of({"domain", "wrap"},
                                       "applies only to a steepness map (\"by\": \"steepness\"); a slope-vector "
                                       "map lies over [-max_slope, max_slope]^2 and clamps beyond");
        if (status) status = object->read_required("max_slope", map.max_slope, read_positive);
    }
    if (!status) return status.error();
    return map;
}

// A base layer: C0 over a driver (its colour map takes no tolerance: the
// default table serves it).
Expected<BaseLayerSource> read_base_layer(const JsonValue& value, const fs::path& scene_folder)
{
    auto object = JsonObject::read(value, {"colormap", "driver"});
    if (!object) return object.error();
    BaseLayerSource base;
    Status status = object->read_required("colormap", base.colormap,
                                          [&](const JsonValue& v) { return read_colormap(v, scene_folder); });
    if (status && base.colormap.tolerance)
        return value.member("colormap")
            .member_error("tolerance", "a base layer's colour map takes the default "
                                       "table (tolerance applies to the height map)");
    if (status)
        status = object->read_required("driver", base.driver,
                                       [&](const JsonValue& v) { return read_driver(v, scene_folder); });
    if (!status) return status.error();
    return base;
}

// The combination of a microsurface material's layers; `present` says which
// of base, height and slope the material has.
Expected<ColorCombination> read_combination(const JsonValue& value, const bool (&present)[3])
{
    auto object = JsonObject::read(value, {"mode", "weights"});
    if (!object) return object.error();
    ColorCombination c;
    Status status = object->read_required("mode", c.mode, [](const JsonValue& v) {
        return read_choice<CombineMode>(v, {{"sum", CombineMode::Sum}, {"product", CombineMode::Product}});
    });
    if (status && c.mode == CombineMode::Product)
        status = object->reject_any_of({"weights"}, "applies only to a sum (a product has no weights)");
    if (status && c.mode == CombineMode::Sum) {
        auto weights_value = object->require("weights");
        if (!weights_value) return weights_value.error();
        auto weights = JsonObject::read(*weights_value, {"base", "height", "slope"});
        if (!weights) return weights.error();
        const char* names[3] = {"base", "height", "slope"};
        double* targets[3] = {&c.base, &c.height, &c.slope};
        const char* layers[3] = {"base", "colormap", "slope_colormap"};
        for (int k = 0; k < 3 && status; ++k) {
            if (present[k]) status = weights->read_required(names[k], *targets[k], read_non_negative);
            else if (weights->has(names[k]))
                status = weights_value->member_error(names[k],
                                                     std::string("the material has no ") + layers[k] + " to weigh");
        }
    }
    if (!status) return status.error();
    return c;
}

// A textured displacement (scene.h).
Expected<DisplacementSource> read_displacement(const JsonValue& value, const fs::path& scene_folder)
{
    auto object = JsonObject::read(value, {"image", "channel", "height_scale"});
    if (!object) return object.error();
    DisplacementSource d;
    Status status = object->read_required("image", d.image_path,
                                          [&](const JsonValue& v) { return read_file_path(v, scene_folder); });
    if (status)
        status = object->read_optional("channel", d.channel, [](const JsonValue& v) -> Expected<std::string> {
            if (v.json().is_number_unsigned()) return std::to_string(v.json().get<std::uint64_t>());
            auto name = read_string(v);
            if (name && name->empty()) return v.expected("a channel name or a 0-based index");
            return name;
        });
    if (status) status = object->read_optional("height_scale", d.height_scale, read_non_negative);
    if (!status) return status.error();
    return d;
}

Expected<MaterialSource> read_material(const JsonValue& value, const fs::path& scene_folder)
{
    auto object = JsonObject::read(
        value, {"colormap", "driver", "microsurface", "displacement", "slope_colormap", "base", "combine"});
    if (!object) return object.error();
    MaterialSource material;
    Status status = object->require_one_of({"driver", "microsurface", "displacement"});
    if (status && object->has("driver")) {
        status = object->reject_any_of({"slope_colormap", "base", "combine"},
                                       "needs a microsurface (a driven material has its colormap alone)");
        if (status)
            status = object->read_required("colormap", material.colormap,
                                           [&](const JsonValue& v) { return read_colormap(v, scene_folder); });
        if (status)
            status = object->read_required("driver", material.driver,
                                           [&](const JsonValue& v) { return read_driver(v, scene_folder); });
        if (!status) return status.error();
        return material;
    }
    if (status && object->has("microsurface"))
        status = object->read_required("microsurface", material.microsurface, read_microsurface);
    if (status && object->has("displacement"))
        status = object->read_required("displacement", material.displacement,
                                       [&](const JsonValue& v) { return read_displacement(v, scene_folder); });
    if (status)
        status = object->read_optional("colormap", material.colormap,
                                       [&](const JsonValue& v) { return read_colormap(v, scene_folder); });
    if (status)
        status = object->read_optional("slope_colormap", material.slope_colormap,
                                       [&](const JsonValue& v) { return read_slope_colormap(v, scene_folder); });
    if (status)
        status = object->read_optional("base", material.base,
                                       [&](const JsonValue& v) { return read_base_layer(v, scene_folder); });
    if (!status) return status.error();
    const bool present[3] = {material.base.has_value(), material.has_colormap(), material.slope_colormap.has_value()};
    const int layers = present[0] + present[1] + present[2];
    if (layers == 0)
        return value.error("a microsurface or displacement material needs at least one of colormap (over "
                           "heights), slope_colormap and base");
    if (layers > 1 && !object->has("combine"))
        return value.member_error("combine", "required with more than one of colormap, slope_colormap and base: "
                                             "{\"mode\": \"sum\", \"weights\": {...}} or {\"mode\": \"product\"}");
    if (object->has("combine")) {
        auto combine = read_combination(value.member("combine"), present);
        if (!combine) return combine.error();
        material.combine = *combine;
    }
    return material;
}

// ---- surfaces ---------------------------------------------------------------

Expected<MappingKind> read_mapping_kind(const JsonValue& value)
{
    return read_choice<MappingKind>(value, {{"planar", MappingKind::Planar}, {"spherical", MappingKind::Spherical}});
}

Status read_planar_axes(const JsonObject& object, TextureMapping& mapping)
{
    Status status = object.read_optional("origin", mapping.origin, read_vec3);
    if (status) status = object.read_optional("u_axis", mapping.u_axis, read_nonzero_vec3);
    if (status) status = object.read_optional("v_axis", mapping.v_axis, read_nonzero_vec3);
    if (status && nearly_parallel(mapping.u_axis, mapping.v_axis))
        return vector_error(object, "v_axis", mapping.v_axis,
                            "a vector not parallel to u_axis " + vector_text(mapping.u_axis));
    return status;
}

MappingKind default_mapping_kind(SurfaceKind surface)
{
    return surface == SurfaceKind::Sphere ? MappingKind::Spherical : MappingKind::Planar;
}

Expected<TextureMapping> read_mapping(const JsonValue& value, SurfaceKind surface)
{
    auto object = JsonObject::read(value);
    if (!object) return object.error();
    TextureMapping mapping;
    mapping.kind = default_mapping_kind(surface);
    Status status = object->read_optional("type", mapping.kind, read_mapping_kind);
    if (status && mapping.kind == MappingKind::Spherical && surface != SurfaceKind::Sphere)
        return value.member("type").expected("\"planar\" (spherical mapping needs a sphere)");
    if (status && mapping.kind == MappingKind::Planar) {
        status = object->allow_only({"type", "origin", "u_axis", "v_axis"});
        if (status) status = read_planar_axes(*object, mapping);
    } else if (status) {
        status = object->allow_only({"type", "u_scale", "v_scale"});
        if (status) status = object->read_optional("u_scale", mapping.u_scale, read_positive);
        if (status) status = object->read_optional("v_scale", mapping.v_scale, read_positive);
    }
    if (!status) return status.error();
    return mapping;
}

// A planar mapping on a plane gives a usable texture only if the plane's
// directions reach every (u, v): u_axis x v_axis must not lie in the plane.
Status check_planar_mapping_on_plane(const JsonObject& surface_object, const Surface& plane)
{
    const TextureMapping& mapping = plane.mapping;
    const Vec3 axes_normal = cross(rescaled(mapping.u_axis), rescaled(mapping.v_axis));
    if (std::fabs(dot(plane.normal, axes_normal)) > kParallelSine * length(axes_normal)) return ok();
    return surface_object.value().member_error(
        "mapping", "expected u_axis and v_axis whose cross product is not parallel to the plane (else the "
                   "texture is constant along a line of the plane), got u_axis " +
                       vector_text(mapping.u_axis) + " and v_axis " + vector_text(mapping.v_axis) +
                       " on a plane of normal " + vector_text(plane.normal) +
                       (surface_object.has("mapping") ? "" : " (the default mapping)"));
}

// A microsurface displaces a plane along its normal, in the units of a
// planar mapping that must be a scaled isometry of the plane (scene.h).
Status check_microsurface_plane(const JsonObject& surface_object, const Surface& surface)
{
    const JsonValue material = surface_object.value().member("material");
    if (surface.kind != SurfaceKind::Plane)
        return material.member_error(surface.material.microsurface ? "microsurface" : "displacement",
                                     "a microsurface needs a plane (it displaces the plane along its "
                                     "normal), not a sphere");
    const TextureMapping& m = surface.mapping;
    const double ku = length(m.u_axis), kv = length(m.v_axis);
    const double tolerance = 1e-6;
    if (std::fabs(dot(m.u_axis, m.v_axis)) > tolerance * ku * kv || std::fabs(ku - kv) > tolerance * std::max(ku, kv) ||
        std::fabs(dot(m.u_axis, surface.normal)) > tolerance * ku ||
        std::fabs(dot(m.v_axis, surface.normal)) > tolerance * kv)
        return surface_object.value().member_error(
            "mapping", "a microsurface needs a planar mapping whose u_axis and v_axis are perpendicular, of equal "
                       "length and in the plane (its heights and wavelengths are in texture units), got u_axis " +
                           vector_text(m.u_axis) + " and v_axis " + vector_text(m.v_axis) + " on a plane of normal " +
                           vector_text(surface.normal));
    return ok();
}

Expected<SurfaceKind> read_surface_kind(const JsonValue& value)
{
    return read_choice<SurfaceKind>(value, {{"plane", SurfaceKind::Plane}, {"sphere", SurfaceKind::Sphere}});
}

Expected<Surface> read_surface(const JsonValue& value, const fs::path& scene_folder)
{
    auto object = JsonObject::read(value);
    if (!object) return object.error();
    Surface surface;
    Status status = object->read_required("type", surface.kind, read_surface_kind);
    if (status && surface.kind == SurfaceKind::Plane) {
        status = object->allow_only({"type", "point", "normal", "mapping", "material"});
        if (status) status = object->read_required("point", surface.point, read_vec3);
        if (status) status = object->read_required("normal", surface.normal, read_direction);
    } else if (status) {
        status = object->allow_only({"type", "center", "radius", "mapping", "material"});
        if (status) status = object->read_required("center", surface.center, read_vec3);
        if (status) status = object->read_required("radius", surface.radius, read_positive);
    }
    surface.mapping.kind = default_mapping_kind(surface.kind);
    if (status)
        status = object->read_optional("mapping", surface.mapping,
                                       [&](const JsonValue& v) { return read_mapping(v, surface.kind); });
    if (status && surface.kind == SurfaceKind::Plane && surface.mapping.kind == MappingKind::Planar)
        status = check_planar_mapping_on_plane(*object, surface);
    if (status)
        status = object->read_required("material", surface.material,
                                       [&](const JsonValue& v) { return read_material(v, scene_folder); });
    if (status && surface.material.has_microsurface()) status = check_microsurface_plane(*object, surface);
    if (!status) return status.error();
    return surface;
}

Expected<std::vector<Surface>> read_surfaces(const JsonValue& value, const fs::path& scene_folder)
{
    if (!value.json().is_array() || value.json().empty()) return value.expected("a non-empty array of surfaces");
    std::vector<Surface> surfaces;
    for (std::size_t i = 0; i < value.json().size(); ++i) {
        auto surface = read_surface(value.element(i), scene_folder);
        if (!surface) return surface.error();
        surfaces.push_back(std::move(*surface));
    }
    return surfaces;
}

}  // namespace

Expected<Scene> load_scene(const std::string& path)
{
    std::error_code ec;
    if (fs::is_directory(path, ec)) return io_error(path + ": cannot read the scene: it is a directory");
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return io_error(
            path + ": cannot read the scene: " + (fs::exists(path, ec) ? "the file cannot be opened" : "no such file"));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) return io_error(path + ": cannot read the scene: a read failed");
    return parse_scene(text.str(), path);
}

Expected<Scene> parse_scene(const std::string& json_text, const std::string& path)
{
    auto document = parse_json_document(json_text, path);
    if (!document) return document.error();
    auto root = JsonObject::read(JsonValue(*document, path), {"camera", "light", "background", "surfaces"});
    if (!root) return root.error();
    const fs::path scene_folder = fs::path(path).parent_path();
    Scene scene;
    scene.path = path;
    Status status = root->read_required("camera", scene.camera, read_camera);
    if (status) status = root->read_optional("light", scene.light, read_light);
    if (status) status = root->read_optional("background", scene.background, read_color);
    if (status)
        status = root->read_required("surfaces", scene.surfaces,
                                     [&](const JsonValue& v) { return read_surfaces(v, scene_folder); });
    if (!status) return status.error();
    return scene;
}

}  // namespace cmfilter
