// SPDX-License-Identifier: Apache-2.0
// Procedural noise and its sigma tables (sec. 4.2): point values and
// filtered means on arrays, noise images, sigma tables baked, read and
// looked up per LOD.
#include "bindings.h"

#include "cmfilter/noise/noise_image.h"
#include "cmfilter/noise/noise_sigma_bake.h"
#include "cmfilter/noise/noise_sigma_table_file.h"
#include "cmfilter/noise/noise_spec.h"

#include <pybind11/stl.h>

#include <optional>

namespace cmfilter::python {

namespace {

struct Noise {
    NoiseSpec spec;
    FractalNoise noise;
};

Noise make_noise_from_text(const std::string& text)
{
    NoiseSpec spec = unwrap(parse_noise_spec(text));
    py::gil_scoped_release release;  // turbulence measures its mean |n|
    FractalNoise noise = unwrap(make_noise(spec));
    return {spec, std::move(noise)};
}

template <typename Value>
py::array_t<double> per_element(const Broadcast& b, int threads, Value&& value)
{
    std::vector<double> out(b.size);
    for_each_element(b.size, threads, [&](std::size_t i) { out[i] = value(i); });
    return owning_array(std::move(out), b.shape);
}

FootprintShape parse_shape(const std::string& name)
{
    if (name == "box") return FootprintShape::Box;
    if (name == "gaussian") return FootprintShape::Gaussian;
    bad_argument("footprint shape '" + name + "' is unknown (expected box or gaussian)");
}

py::array_t<double> doubles(std::vector<double> v)
{
    const auto n = static_cast<py::ssize_t>(v.size());
    return owning_array(std::move(v), {n});
}

}  // namespace

void bind_noise(py::module_& m)
{
    py::class_<Noise>(m, "Noise", "A procedural noise from its spec text (docs/noise.md), e.g. 'fbm:octaves=6,seed=7'.")
        .def(py::init(&make_noise_from_text), py::arg("spec"))
        .def(
            "__call__",
            [](const Noise& n, py::object x, py::object y, int threads) {
        Broadcast b = broadcast({x, y});
        const double *xs = b.arrays[0].data(), *ys = b.arrays[1].data();
        return per_element(b, threads, [&](std::size_t i) { return n.noise(xs[i], ys[i]); });
            },
            py::arg("x"), py::arg("y"), py::arg("threads") = 0, "Point values f(x, y): float64 array.")
        .def(
            "mean_over_footprint",
            [](const Noise& n, py::object x, py::object y, py::object width, int threads) {
        Broadcast b = broadcast({x, y, width});
        const double *xs = b.arrays[0].data(), *ys = b.arrays[1].data(), *ws = b.arrays[2].data();
        return per_element(b, threads, [&](std::size_t i) { return n.noise.mean_over_footprint(xs[i], ys[i], ws[i]); });
            },
            py::arg("x"), py::arg("y"), py::arg("width"), py::arg("threads") = 0,
            "The filtered mean over a square footprint of `width` noise units centred at (x, y).")
        .def_property_readonly("spec", [](const Noise& n) { return to_string(n.spec); })
        .def_property_readonly("base_period", [](const Noise& n) { return n.noise.base_period(); })
        .def_property_readonly("octaves", [](const Noise& n) { return n.noise.options().octaves; });

    m.def(
        "noise_image",
        [](const std::string& spec, int width, int height, double scale, int threads) {
        NoiseImageOptions options;
        options.spec = unwrap(parse_noise_spec(spec));
        options.width = width;
        options.height = height;
        options.scale = scale;
        options.threads = threads;
        std::vector<float> values = [&] {
            py::gil_scoped_release release;
            return unwrap(render_noise_image(options));
        }();
        return owning_array(std::move(values), {height, width});
        },
        py::arg("spec"), py::kw_only(), py::arg("width") = 256, py::arg("height") = 256, py::arg("scale") = 1.0 / 16,
        py::arg("threads") = 0,
        "The noise at pixel centres, `scale` noise units per pixel (noise-image): (height, width) float32.");

    py::class_<LoadedNoiseSigmaTable>(m, "NoiseSigmaTable",
                                      "A noise's sigma per level of detail (bake-noise), one footprint shape.")
        .def_static(
            "read",
            [](const std::string& path, const std::string& shape) {
        const FootprintShape s = parse_shape(shape);
        py::gil_scoped_release release;
        return unwrap(read_noise_sigma_table(path, s));
            },
            py::arg("path"), py::arg("shape") = "box")
        .def(
            "sigma_at",
            [](const LoadedNoiseSigmaTable& t, py::object lod) {
        Broadcast b = broadcast({lod});
        const double* ls = b.arrays[0].data();
        return per_element(b, 1, [&](std::size_t i) { return t.table.sigma_at(ls[i]); });
            },
            py::arg("lod"), "sigma(LOD), linear between nodes, the end values beyond.")
        .def_property_readonly(
            "lods",
            [](const LoadedNoiseSigmaTable& t) {
        std::vector<double> l(t.table.sigmas().size());
        for (std::size_t k = 0; k < l.size(); ++k)
            l[k] = t.table.lod_first() + t.table.lod_step() * static_cast<double>(k);
        return doubles(std::move(l));
            })
        .def_property_readonly("sigmas", [](const LoadedNoiseSigmaTable& t) { return doubles(t.table.sigmas()); })
        .def_property_readonly("noise_spec", [](const LoadedNoiseSigmaTable& t) { return t.noise_spec; })
        .def_property_readonly("base_period", [](const LoadedNoiseSigmaTable& t) { return t.base_period; });

    m.def(
        "bake_noise_sigma",
        [](const std::string& spec_text, std::optional<std::string> output, double lod_step, double lod_last,
           int samples_per_footprint, int initial_footprints, int max_footprints, double relative_half_width,
           int global_samples, std::uint64_t seed, int threads) {
        Noise n = make_noise_from_text(spec_text);
        NoiseSigmaBakeOptions options;
        options.lod_step = lod_step;
        options.lod_last = lod_last;
        options.samples_per_footprint = samples_per_footprint;
        options.initial_footprints = initial_footprints;
        options.max_footprints = max_footprints;
        options.relative_half_width = relative_half_width;
        options.global_samples = global_samples;
        options.seed = seed;
        options.threads = threads;
        NoiseSigmaBake bake = [&] {
            py::gil_scoped_release release;
            NoiseSigmaBake b = unwrap(bake_noise_sigma(n.noise, options));
            if (output) check(write_noise_sigma_table(*output, b, to_string(n.spec), n.noise.base_period()));
            return b;
        }();
        std::vector<double> lods, box, box_hw, gauss, gauss_hw, footprints;
        for (const auto& row : bake.rows) {
            lods.push_back(row.lod);
            box.push_back(row.box.sigma);
            box_hw.push_back(row.box.half_width);
            gauss.push_back(row.gaussian.sigma);
            gauss_hw.push_back(row.gaussian.half_width);
            footprints.push_back(row.box.footprints);
        }
        py::dict d;
        d["lods"] = doubles(std::move(lods));
        d["box_sigma"] = doubles(std::move(box));
        d["box_half_width"] = doubles(std::move(box_hw));
        d["gaussian_sigma"] = doubles(std::move(gauss));
        d["gaussian_half_width"] = doubles(std::move(gauss_hw));
        d["box_footprints"] = doubles(std::move(footprints));
        d["mean"] = bake.global.mean;
        d["sigma"] = bake.global.sigma;
        d["base_period"] = n.noise.base_period();
        return d;
        },
        py::arg("spec"), py::kw_only(), py::arg("output") = py::none(), py::arg("lod_step") = 0.25,
        py::arg("lod_last") = 2.0, py::arg("samples_per_footprint") = 64, py::arg("initial_footprints") = 1024,
        py::arg("max_footprints") = 1 << 16, py::arg("relative_half_width") = 0.005,
        py::arg("global_samples") = 1 << 20, py::arg("seed") = 1, py::arg("threads") = 0,
        "Bakes a noise's sigma per LOD by Monte-Carlo (bake-noise), writing `output` (.exr) when given: a dict of "
        "float64 arrays lods, box_sigma, box_half_width, gaussian_sigma, gaussian_half_width, box_footprints and "
        "the noise's mean, sigma and base_period.");
}

}  // namespace cmfilter::python
