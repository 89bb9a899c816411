// SPDX-License-Identifier: Apache-2.0
// `render`: a scene file seen through its camera, each pixel's colour-mapped
// surface filtered over its footprint by a method, into arrays.
#include "bindings.h"

#include "cmfilter/render/render.h"
#include "cmfilter/scene/scene_loading.h"
#include "cmfilter/scene/scene_materials.h"

#include <pybind11/stl.h>

#include <optional>
#include <utility>

namespace cmfilter::python {

namespace {

template <typename T>
py::array_t<T> plane(std::vector<T>&& values, int height, int width)
{
    return owning_array(std::move(values), {height, width});
}

}  // namespace

void bind_render(py::module_& m)
{
    m.def(
        "render",
        [](const std::string& scene_path, const std::string& method, std::optional<std::pair<int, int>> size,
           std::optional<std::tuple<int, int, int, int>> region, int samples, std::uint64_t seed, int probes,
           int sub_footprints, const std::string& footprint, bool edge_coverage, std::optional<double> tolerance,
           std::optional<double> shortcut, const std::string& masking, const std::string& slope_shading, bool aovs,
           const std::string& ocio_config, int threads, const std::vector<std::string>& microsurface_methods,
           const std::vector<int>& surface_probes) -> py::object {
            RenderOptions options;
            options.method = unwrap(parse_render_method(method));
            options.footprint = unwrap(parse_footprint_width(footprint));
            check(check_render_samples(samples));
            check(check_render_probes(probes));
            if (slope_shading != "uncorrelated" && slope_shading != "correlated")
                bad_argument("slope_shading '" + slope_shading + "' is unknown (expected uncorrelated or correlated)");
            options.samples = samples;
            options.seed = seed;
            options.max_probes = probes;
            options.sub_footprints.max_cells = sub_footprints;
            check(check_sub_footprint_options(options.sub_footprints));
            options.edge_coverage = edge_coverage;
            options.masking = parse_masking(masking, "masking");
            options.slope_shading = slope_shading == "correlated" ? SlopeShading::Correlated
                                                                  : SlopeShading::Uncorrelated;
            options.threads = threads;
            options.surface_indices = aovs;
            for (const std::string& m : microsurface_methods)
                options.microsurface_methods.push_back(unwrap(parse_render_method(m)));
            check(check_microsurface_methods(options.microsurface_methods));
            options.surface_probes = surface_probes;
            check(check_surface_probes(options.surface_probes));
            MaterialOptions material_options;
            material_options.threads = threads;
            set_method_materials(options.method, material_options);
            material_options.segments_tolerance = tolerance.value_or(0.0);
            material_options.tables.tolerance = tolerance;
            material_options.tables.plain_bound = shortcut;
            const ColorConfig config = load_config(ocio_config);
            RenderedImage image = [&] {
                py::gil_scoped_release release;
                Scene scene = unwrap(load_scene(scene_path));
                if (size) {
                    const auto [w, h] = *size;
                    if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide ||
                        static_cast<long long>(w) * h > kMaxImagePixels)
                        bad_argument("size " + std::to_string(w) + " x " + std::to_string(h) +
                                     " is out of range (expected 1 .. " + std::to_string(kMaxImageSide) +
                                     " a side, at most " + std::to_string(kMaxImagePixels) + " pixels)");
                    scene.camera.width = w;
                    scene.camera.height = h;
                }
                if (region) {
                    const auto [x0, y0, x1, y1] = *region;
                    options.region = PixelRegion{x0, y0, x1, y1};
                    check(check_pixel_region(*options.region, scene.camera.width, scene.camera.height));
                }
                std::vector<Material> materials = unwrap(prepare_materials(scene, config, material_options));
                return unwrap(cmfilter::render(scene, materials, options));
            }();
            const int w = image.width, h = image.height;
            py::array_t<float> rgb = owning_array(std::move(image.rgb), {h, w, 3});
            if (!aovs) return std::move(rgb);
            py::dict d;
            d["rgb"] = rgb;
            d["hit"] = plane(std::move(image.hit), h, w);
            d["distance"] = plane(std::move(image.distance), h, w);
            d["mean"] = plane(std::move(image.mean), h, w);
            d["sigma"] = plane(std::move(image.sigma), h, w);
            d["lod"] = plane(std::move(image.lod), h, w);
            d["surface"] = plane(std::move(image.surface), h, w);
            if (!image.shaded.empty()) d["shaded"] = owning_array(std::move(image.shaded), {h, w, 3});
            d["origin"] = py::make_tuple(image.x0, image.y0);
            d["frame_size"] = py::make_tuple(image.frame_width, image.frame_height);
            return std::move(d);
        },
        py::arg("scene"), py::kw_only(), py::arg("method") = "gaussian", py::arg("size") = py::none(),
        py::arg("region") = py::none(), py::arg("samples") = 16, py::arg("seed") = 0, py::arg("probes") = 16,
        py::arg("sub_footprints") = SubFootprintOptions{}.max_cells, py::arg("footprint") = "rms",
        py::arg("edge_coverage") = true, py::arg("tolerance") = py::none(), py::arg("shortcut") = py::none(),
        py::arg("masking") = "correlated", py::arg("slope_shading") = "correlated", py::arg("aovs") = false,
        py::arg("ocio_config") = "", py::arg("threads") = 0,
        py::arg("microsurface_methods") = std::vector<std::string>{}, py::arg("surface_probes") = std::vector<int>{},
        "Renders a scene file (docs/scene-format.md) by naive, gaussian, gaussian-exact, mixture, exact, supersample "
        "or reference, as `cmfilter render` (sub_footprints: mixture's most squares per axis for noise drivers; "
        "microsurface_methods: by surface index, each microsurface's own one-ray method, as --method auto records "
        "them; surface_probes: by surface index, each surface's most probes, 0 for `probes`): (H, W, 3) float32 "
        "scene-linear, or with aovs=True a dict of it (rgb) and the per-pixel hit, distance, mean, sigma, lod and "
        "surface (the index of the surface hit, -1 for none).");
}

}  // namespace cmfilter::python
