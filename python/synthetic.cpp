// SPDX-License-Identifier: Apache-2.0
// Synthetic image stacks with exact ground truth (`cmfilter make-stack`): the
// domes of lights, a scene surface's microsurface tile traced as its
// heightfield, its images under lights in memory, and whole stacks (or BTFs)
// written as make-stack writes them.
#include "bindings.h"

#include "cmfilter/synthetic/light_dome.h"
#include "cmfilter/synthetic/make_stack.h"
#include "cmfilter/synthetic/synthetic_stack.h"
#include "cmfilter/synthetic/synthetic_surface.h"

#include <pybind11/stl.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>

namespace cmfilter::python {

namespace {

Vec3 vec3(const std::array<double, 3>& v) { return {v[0], v[1], v[2]}; }

py::array_t<double> vec3_rows(const std::vector<Vec3>& vectors)
{
    std::vector<double> out;
    out.reserve(3 * vectors.size());
    for (const Vec3& v : vectors) out.insert(out.end(), {v.x, v.y, v.z});
    return owning_array(std::move(out), {static_cast<py::ssize_t>(vectors.size()), 3});
}

std::vector<Vec3> vec3_list(const py::object& value, const char* what)
{
    const Directions d = directions(value, what);
    std::vector<Vec3> out(d.count());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = {d.at(i)[0], d.at(i)[1], d.at(i)[2]};
    return out;
}

DomeOptions dome_options(const std::string& dome, double min_elevation_degrees)
{
    DomeOptions options = unwrap(parse_dome(dome));
    options.min_elevation_degrees = min_elevation_degrees;
    return options;
}

SyntheticSurface load_surface(const std::string& scene, std::size_t surface, const std::string& ocio_config,
                              int threads)
{
    SyntheticSurfaceOptions options;
    options.scene = scene;
    options.surface = surface;
    options.threads = threads;
    const ColorConfig config = load_config(ocio_config);
    py::gil_scoped_release release;
    return unwrap(SyntheticSurface::load(options, config));
}

// The first hits of the rays along -view through (u, v): hit, point, normal,
// colour (zeros where a ray meets nothing).
py::dict trace(const SyntheticSurface& surface, const py::object& u, const py::object& v,
               const std::array<double, 3>& view, int threads)
{
    const Vec3 w = vec3(view);
    if (!(w.z > 0) || !std::isfinite(length(w)))
        bad_argument("view " + std::to_string(w.x) + ", " + std::to_string(w.y) + ", " + std::to_string(w.z) +
                     " is invalid (expected a finite direction above the horizon, z > 0)");
    const Vec3 unit = normalize(w);
    Broadcast b = broadcast({u, v});
    std::vector<std::uint8_t> hit(b.size);
    std::vector<double> point(3 * b.size), normal(3 * b.size), color(3 * b.size);
    for_each_element(b.size, threads, [&](std::size_t i) {
        const std::optional<SyntheticHit> h = surface.trace(b.arrays[0].data()[i], b.arrays[1].data()[i], unit);
        if (!h) return;
        hit[i] = 1;
        double* p = point.data() + 3 * i;
        double* n = normal.data() + 3 * i;
        double* c = color.data() + 3 * i;
        p[0] = h->point.x, p[1] = h->point.y, p[2] = h->point.z;
        n[0] = h->normal.x, n[1] = h->normal.y, n[2] = h->normal.z;
        c[0] = h->color.r, c[1] = h->color.g, c[2] = h->color.b;
    });
    py::dict d;
    d["hit"] = owning_array(std::move(hit), b.shape).attr("astype")("bool");
    d["point"] = owning_array(std::move(point), with_trailing(b.shape, {3}));
    d["normal"] = owning_array(std::move(normal), with_trailing(b.shape, {3}));
    d["color"] = owning_array(std::move(color), with_trailing(b.shape, {3}));
    return d;
}

py::dict render_stack(const SyntheticSurface& surface, const py::object& lights, const std::array<double, 3>& view,
                      int size, int samples, const std::string& specular, std::uint64_t seed, bool albedo, int threads)
{
    SyntheticStackOptions options;
    options.view = vec3(view);
    options.size = size;
    options.samples = samples;
    options.specular = unwrap(parse_specular_lobe(specular));
    options.seed = seed;
    options.albedo = albedo;
    options.threads = threads;
    const std::vector<Vec3> directions = vec3_list(lights, "lights");
    SyntheticStack stack = [&] {
        py::gil_scoped_release release;
        return unwrap(render_synthetic_stack(surface, directions, options));
    }();
    const py::ssize_t s = stack.size, n = static_cast<py::ssize_t>(stack.lights.size());
    py::dict d;
    d["images"] = owning_array(std::move(stack.pixels), {n, s, s, 3});
    d["normals"] = owning_array(std::move(stack.normals), {s, s, 3});
    d["albedo"] = albedo ? py::object(owning_array(std::move(stack.albedo), {s, s, 3})) : py::none();
    d["lights"] = vec3_rows(stack.lights);
    d["view"] = vec3_rows({stack.view}).attr("reshape")(3);
    d["rays"] = stack.rays;
    d["hits"] = stack.hits;
    d["seconds"] = stack.seconds;
    return d;
}

py::dict made_stack(const std::string& scene, const std::string& output, std::size_t surface,
                    const std::optional<py::object>& views, int size, int samples, const std::string& specular,
                    const std::string& dome, double min_elevation_degrees, std::uint64_t seed,
                    const std::string& image_extension, bool albedo, const std::string& ocio_config, int threads)
{
    MakeStackOptions options;
    options.scene = scene;
    options.surface = surface;
    if (views) options.views = vec3_list(*views, "views");
    options.size = size;
    options.samples = samples;
    options.specular = unwrap(parse_specular_lobe(specular));
    options.dome = dome_options(dome, min_elevation_degrees);
    options.seed = seed;
    options.threads = threads;
    options.output = output;
    options.image_extension = image_extension;
    options.albedo = albedo;
    const ColorConfig config = load_config(ocio_config);
    MadeStack made = [&] {
        py::gil_scoped_release release;
        return unwrap(make_stack(options, config));
    }();
    py::dict d;
    d["light_files"] = made.light_files;
    d["records"] = made.records;
    d["manifest"] = made.manifest;
    d["surface_kind"] = to_string(made.kind);
    d["tile"] = made.tile;
    d["lights"] = made.lights;
    d["size"] = made.size;
    d["samples"] = made.samples;
    d["files"] = made.files;
    d["rays"] = made.rays;
    d["render_seconds"] = made.render_seconds;
    d["seconds"] = made.seconds;
    return d;
}

}  // namespace

void bind_synthetic(py::module_& m)
{
    m.def(
        "light_dome",
        [](const std::string& dome, double min_elevation_degrees) {
        const DomeOptions options = dome_options(dome, min_elevation_degrees);
        return vec3_rows(unwrap(make_dome(options)));
        },
        py::arg("dome") = "fibonacci:64", py::kw_only(), py::arg("min_elevation_degrees") = 10.0,
        "The lights of a dome, regular:N, fibonacci:N, stage:N (uneven, as a light stage) or file:PATH.lp, above "
        "min_elevation_degrees (made domes): (N, 3) float64 unit directions towards the lights, stack frame (x "
        "right, y up, z towards the camera), as make-stack --dome.");

    py::class_<SyntheticSurface>(m, "SyntheticSurface",
                                 "One periodic tile of a scene surface's microsurface (a Gaussian microsurface or a "
                                 "textured displacement) as the heightfield `render --method reference` traces, "
                                 "coloured as render colours it.")
        .def_static("load", &load_surface, py::arg("scene"), py::kw_only(), py::arg("surface") = 0,
                    py::arg("ocio_config") = "", py::arg("threads") = 0,
                    "Loads a scene file's surface (docs/scene-format.md) and tabulates its tile.")
        .def("trace", &trace, py::arg("u"), py::arg("v"), py::kw_only(),
             py::arg("view") = std::array<double, 3>{0, 0, 1}, py::arg("threads") = 0,
             "The first hits of the rays along -view through the texture points (u, v) of the mean plane h = 0, on "
             "arrays that broadcast: a dict of hit (bool), point, normal (the bilinear patch's unit micro-normal) "
             "and color (scene-linear), each (..., 3), zeros where a ray meets nothing. Directions and points are "
             "in the heightfield's frame (u, v, h), v growing down the rows: a stack direction (x, y, z) is "
             "(x, -y, z) there.")
        .def("render_stack", &render_stack, py::arg("lights"), py::kw_only(),
             py::arg("view") = std::array<double, 3>{0, 0, 1}, py::arg("size") = 64, py::arg("samples") = 16,
             py::arg("specular") = "none", py::arg("seed") = 0, py::arg("albedo") = false, py::arg("threads") = 0,
             "The tile's images under lights ((N, 3) or (3,) towards the lights, stack frame) seen orthographically "
             "along -view, one texel a pixel, `samples` stratified rays a pixel: V <m, l> (colour + pi f_spec) per "
             "hit, the specular lobe none, blinn-phong:ks=K,n=N or ggx:ks=K,alpha=A. A dict: images (N, size, "
             "size, 3) float32, normals (size, size, 3) the true mean normals (stack frame), albedo (or None), "
             "lights (N, 3), view (3,) (unit), rays, hits, seconds. The same for any thread count.")
        .def_property_readonly("kind", [](const SyntheticSurface& s) { return std::string(to_string(s.kind())); })
        .def_property_readonly("tile", &SyntheticSurface::tile, "The tile's side in texture units")
        .def_property_readonly("surface", &SyntheticSurface::surface);

    m.def("make_stack", &made_stack, py::arg("scene"), py::arg("output"), py::kw_only(), py::arg("surface") = 0,
          py::arg("views") = py::none(), py::arg("size") = 64, py::arg("samples") = 16, py::arg("specular") = "none",
          py::arg("dome") = "fibonacci:64", py::arg("min_elevation_degrees") = 10.0, py::arg("seed") = 0,
          py::arg("image_extension") = ".exr", py::arg("albedo") = false, py::arg("ocio_config") = "",
          py::arg("threads") = 0,
          "Writes a synthetic image stack of a scene surface's tile as `cmfilter make-stack` does: one view "
          "(output: the .lp; images, normals, record beside it) or several, views (N, 3) (output: the BTF "
          "manifest, .json). A dict: light_files, records, manifest, surface_kind, tile, lights, size, samples, "
          "files, rays, render_seconds, seconds.");
}

}  // namespace cmfilter::python
