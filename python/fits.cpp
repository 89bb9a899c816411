// SPDX-License-Identifier: Apache-2.0
// Relighting fits of image stacks: the linear models (PTM, HSH) in one SVD
// solve and per-texel Lafortune lobes, fitted to arrays or to a stack's
// files, read and written, and relit at arrays of light directions.
#include "bindings.h"

#include "cmfilter/stack/fit_file.h"
#include "cmfilter/stack/fit_loading.h"
#include "cmfilter/stack/image_stack.h"
#include "cmfilter/stack/lafortune_file.h"
#include "cmfilter/stack/lafortune_fit.h"
#include "cmfilter/stack/linear_fit.h"

#include <pybind11/stl.h>

#include <optional>

namespace cmfilter::python {

namespace {

Vec3 vec3(const double* d) { return {d[0], d[1], d[2]}; }

// An in-memory stack: images (N, H, W) or (N, H, W, C) of scene-linear values
// and lights (N, 3).
ImageStack stack_from_arrays(const FloatArray& images, const py::object& lights)
{
    if (images.ndim() != 3 && images.ndim() != 4)
        bad_argument("images has " + std::to_string(images.ndim()) +
                     " dimensions (expected (N, H, W) or (N, H, W, C))");
    Directions l = directions(lights, "lights");
    ImageStack stack;
    const auto n = static_cast<std::size_t>(images.shape(0));
    if (l.single || l.count() != n)
        bad_argument("lights holds " + std::to_string(l.single ? 1 : l.count()) + " directions for " +
                     std::to_string(n) + " images (expected one (x, y, z) per image)");
    stack.height = static_cast<int>(images.shape(1));
    stack.width = static_cast<int>(images.shape(2));
    stack.channels = images.ndim() == 4 ? static_cast<int>(images.shape(3)) : 1;
    stack.encoding = StackEncoding::SceneLinear;
    for (std::size_t k = 0; k < n; ++k) {
        Vec3 d = vec3(l.at(k));
        const double len = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        if (!(len > 0) || !std::isfinite(len) || d.z < 0)
            bad_argument("lights[" + std::to_string(k) + "] is invalid (expected a finite direction with z >= 0)");
        stack.lights.push_back({d.x / len, d.y / len, d.z / len});
        stack.images.push_back("images[" + std::to_string(k) + "]");
    }
    stack.pixels.assign(images.data(), images.data() + images.size());
    return stack;
}

ImageStack stack_from_file(const std::string& light_file, const std::string& encoding, const std::string& colorspace,
                           const std::string& ocio_config, int threads)
{
    StackLoadOptions options;
    options.light_file = light_file;
    options.colorspace = colorspace;
    if (encoding == "display") options.encoding = StackEncoding::DisplayEncoded;
    else if (encoding != "linear") bad_argument("encoding '" + encoding + "' is unknown (expected linear or display)");
    options.threads = threads;
    const ColorConfig config = load_config(ocio_config);
    py::gil_scoped_release release;
    return unwrap(load_image_stack(options, config));
}

LinearFit fit_linear_stack(const ImageStack& stack, const std::string& model, double singular_threshold, int threads)
{
    LinearFitOptions options;
    auto parsed = parse_linear_model(model);
    if (!parsed) bad_argument("model '" + model + "' is unknown (expected ptm-rgb, ptm-lrgb, hsh2 or hsh3)");
    options.model = *parsed;
    options.singular_threshold = singular_threshold;
    options.threads = threads;
    py::gil_scoped_release release;
    return unwrap(fit_linear(stack, options));
}

LafortuneFit fit_lafortune_stack(const ImageStack& stack, const std::string& variant, int lobes, bool auto_lobes,
                                 const py::object& view, double spacing_cap, double density_radius, int max_iterations,
                                 int threads)
{
    LafortuneFitOptions options;
    auto parsed = parse_lafortune_variant(variant);
    if (!parsed) bad_argument("variant '" + variant + "' is unknown (expected rgb or luminance)");
    options.variant = *parsed;
    options.lobes = lobes;
    options.auto_lobes = auto_lobes;
    Directions v = directions(view, "view");
    if (!v.single) bad_argument("view must be one (x, y, z) direction");
    options.view = vec3(v.at(0));
    options.spacing_cap = spacing_cap;
    options.density_radius = density_radius;
    options.max_iterations = max_iterations;
    options.threads = threads;
    py::gil_scoped_release release;
    return unwrap(fit_lafortune(stack, options));
}

// Relights `count` lights into (N, H, W, C), or (H, W, C) for a single one.
template <typename Relight>
py::array_t<float> relight_all(const Directions& lights, int width, int height, int channels, Relight&& relight)
{
    const std::size_t image = static_cast<std::size_t>(width) * height * channels;
    std::vector<float> out(image * lights.count());
    {
        py::gil_scoped_release release;
        for (std::size_t k = 0; k < lights.count(); ++k) {
            const std::vector<float> one = relight(vec3(lights.at(k)));
            std::copy(one.begin(), one.end(), out.begin() + static_cast<std::ptrdiff_t>(k * image));
        }
    }
    if (lights.single) return owning_array(std::move(out), {height, width, channels});
    return owning_array(std::move(out), {static_cast<py::ssize_t>(lights.count()), height, width, channels});
}

}  // namespace

void bind_fits(py::module_& m)
{
    py::class_<LinearFit>(m, "LinearFit", "A linear relighting fit (PTM, HSH) of an image stack: one SVD solve.")
        .def_static(
            "fit",
            [](const FloatArray& images, const py::object& lights, const std::string& model, double singular_threshold,
               int threads) {
        return fit_linear_stack(stack_from_arrays(images, lights), model, singular_threshold, threads);
            },
            py::arg("images"), py::arg("lights"), py::kw_only(), py::arg("model") = "ptm-rgb",
            py::arg("singular_threshold") = 1e-6, py::arg("threads") = 0,
            "Fits images (N, H, W[, C]) taken under lights (N, 3) with model ptm-rgb, ptm-lrgb, hsh2 or hsh3.")
        .def_static(
            "fit_stack",
            [](const std::string& light_file, const std::string& model, const std::string& encoding,
               const std::string& colorspace, double singular_threshold, const std::string& ocio_config, int threads) {
        return fit_linear_stack(stack_from_file(light_file, encoding, colorspace, ocio_config, threads), model,
                                singular_threshold, threads);
            },
            py::arg("light_file"), py::kw_only(), py::arg("model") = "ptm-rgb", py::arg("encoding") = "linear",
            py::arg("colorspace") = "", py::arg("singular_threshold") = 1e-6, py::arg("ocio_config") = "",
            py::arg("threads") = 0, "Fits the stack a .lp light file names (as `cmfilter fit`).")
        .def_static(
            "read",
            [](const std::string& path) {
        py::gil_scoped_release release;
        return unwrap(load_fit(path));
            },
            py::arg("path"), "Reads a fit: cmfilter's float .exr, a .ptm or an .rti.")
        .def(
            "write",
            [](const LinearFit& fit, const std::string& path, const std::string& source) {
        FitFileInfo info;
        info.source = source;
        py::gil_scoped_release release;
        check(write_fit_exr(path, fit, info));
            },
            py::arg("path"), py::arg("source") = "", "Writes cmfilter's float OpenEXR fit file, atomically.")
        .def(
            "relight",
            [](const LinearFit& fit, const py::object& lights, int threads) {
        return relight_all(directions(lights, "lights"), fit.width, fit.height, fit.channels,
                           [&](const Vec3& l) { return relight(fit, l, threads); });
            },
            py::arg("lights"), py::arg("threads") = 0,
            "The model at one light (3,) -> (H, W, C), or at N lights (N, 3) -> (N, H, W, C), float32.")
        .def_property_readonly(
            "coefficients",
            [](py::object self) {
        const auto& fit = self.cast<const LinearFit&>();
        return view_array(fit.coefficients.data(), {fit.height, fit.width, fit.stride()}, self);
            },
            "(H, W, stride) float32 per-texel coefficients (a read-only view; layout in stack/linear_fit.h)")
        .def_property_readonly("model", [](const LinearFit& f) { return std::string(to_string(f.model)); })
        .def_readonly("width", &LinearFit::width)
        .def_readonly("height", &LinearFit::height)
        .def_readonly("channels", &LinearFit::channels)
        .def_property_readonly("terms", &LinearFit::terms)
        .def_property_readonly("condition_number", [](const LinearFit& f) { return f.conditioning.condition_number; });

    py::class_<LafortuneFit>(m, "LafortuneFit", "Per-texel Lafortune lobes fitted to an image stack.")
        .def_static(
            "fit",
            [](const FloatArray& images, const py::object& lights, const std::string& variant, int lobes,
               bool auto_lobes, const py::object& view, double spacing_cap, double density_radius, int max_iterations,
               int threads) {
        return fit_lafortune_stack(stack_from_arrays(images, lights), variant, lobes, auto_lobes, view, spacing_cap,
                                   density_radius, max_iterations, threads);
            },
            py::arg("images"), py::arg("lights"), py::kw_only(), py::arg("variant") = "luminance", py::arg("lobes") = 2,
            py::arg("auto_lobes") = false, py::arg("view") = py::make_tuple(0.0, 0.0, 1.0),
            py::arg("spacing_cap") = 2.0, py::arg("density_radius") = 0.0, py::arg("max_iterations") = 20,
            py::arg("threads") = 0,
            "Fits images (N, H, W[, C]) taken under lights (N, 3) (as `cmfilter fit --model lafortune`).")
        .def_static(
            "read",
            [](const std::string& path) {
        py::gil_scoped_release release;
        return unwrap(read_lafortune_exr(path));
            },
            py::arg("path"))
        .def(
            "write",
            [](const LafortuneFit& fit, const std::string& path, const std::string& source) {
        py::gil_scoped_release release;
        check(write_lafortune_exr(path, fit, source));
            },
            py::arg("path"), py::arg("source") = "")
        .def(
            "relight",
            [](const LafortuneFit& fit, const py::object& lights, const py::object& view, int threads) {
        Vec3 v = fit.view;
        if (!view.is_none()) {
            Directions d = directions(view, "view");
            if (!d.single) bad_argument("view must be one (x, y, z) direction");
            v = vec3(d.at(0));
        }
        return relight_all(directions(lights, "lights"), fit.width, fit.height, fit.channels,
                           [&](const Vec3& l) { return relight_lafortune(fit, l, v, threads); });
            },
            py::arg("lights"), py::arg("view") = py::none(), py::arg("threads") = 0,
            "The lobes at one light (3,) -> (H, W, C), or N lights (N, 3) -> (N, H, W, C), float32; at the fitted "
            "view unless given.")
        .def_property_readonly(
            "parameters",
            [](py::object self) {
        const auto& fit = self.cast<const LafortuneFit&>();
        return view_array(fit.parameters.data(), {fit.height, fit.width, fit.stride()}, self);
            },
            "(H, W, stride) float32 per-texel parameters (a read-only view; layout in stack/lafortune_model.h)")
        .def_property_readonly("variant", [](const LafortuneFit& f) { return std::string(to_string(f.variant)); })
        .def_readonly("width", &LafortuneFit::width)
        .def_readonly("height", &LafortuneFit::height)
        .def_readonly("channels", &LafortuneFit::channels)
        .def_readonly("lobes", &LafortuneFit::lobes)
        .def_property_readonly("view",
                               [](const LafortuneFit& f) { return py::make_tuple(f.view.x, f.view.y, f.view.z); });
}

}  // namespace cmfilter::python
