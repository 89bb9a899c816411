// SPDX-License-Identifier: Apache-2.0
// Drivers read as data and their moment pyramids (sec. 4.2): bake, open, and
// the footprint's mean and sigma at any (s, t, lod), or a whole level.
#include "bindings.h"

#include "cmfilter/io/driver_image.h"
#include "cmfilter/texture/moment_pyramid.h"
#include "cmfilter/texture/moment_texture.h"

namespace cmfilter::python {

namespace {

MomentTexture open_moments(const std::string& path)
{
    py::gil_scoped_release release;
    return unwrap(MomentTexture::open(path));
}

// mean and sigma per element of `count`, looked up by `sample(i)`.
template <typename Sample>
py::tuple moments_per_element(std::size_t count, const std::vector<py::ssize_t>& shape, int threads, Sample&& sample)
{
    std::vector<double> mean(count), sigma(count);
    for_each_element(count, threads, [&](std::size_t i) {
        const MomentSample s = sample(i);
        mean[i] = s.mean;
        sigma[i] = s.sigma;
    });
    return py::make_tuple(owning_array(std::move(mean), shape), owning_array(std::move(sigma), shape));
}

}  // namespace

void bind_moments(py::module_& m)
{
    m.def(
        "read_driver",
        [](const std::string& path, const std::string& channel, const std::string& nonfinite, int threads) {
        DriverReadOptions options;
        options.path = path;
        options.channel = channel;
        options.nonfinite = unwrap(parse_non_finite_policy(nonfinite));
        options.threads = threads;
        DriverImage image = [&] {
            py::gil_scoped_release release;
            return unwrap(read_driver(options));
        }();
        return owning_array(std::move(image.values), {image.height, image.width});
        },
        py::arg("path"), py::kw_only(), py::arg("channel") = "", py::arg("nonfinite") = "error", py::arg("threads") = 0,
        "One channel of an image as data (no colour conversion; 8-bit codes / 255): (height, width) float32.");

    py::class_<MomentTexture>(m, "MomentPyramid",
                              "A moment pyramid (mean f and mean f^2 per level, sec. 4.2) looked up as a renderer "
                              "does, through OpenImageIO's TextureSystem.")
        .def_static(
            "bake",
            [](const std::string& driver, const std::string& output, const std::string& channel,
               const std::string& wrap, const std::string& nonfinite, int threads) {
        MomentBakeOptions options;
        options.driver_path = driver;
        options.output_path = output;
        options.channel = channel;
        options.wrap = unwrap(parse_texture_wrap(wrap));
        options.nonfinite = unwrap(parse_non_finite_policy(nonfinite));
        options.threads = threads;
        {
            py::gil_scoped_release release;
            unwrap(bake_moment_pyramid(options));
        }
        return open_moments(output);
            },
            py::arg("driver"), py::arg("output"), py::kw_only(), py::arg("channel") = "", py::arg("wrap") = "clamp",
            py::arg("nonfinite") = "error", py::arg("threads") = 0,
            "Bakes the moment pyramid of a driver image into `output` (.exr, as bake-moments) and opens it.")
        .def_static("open", &open_moments, py::arg("path"), "Opens a moment pyramid file.")
        .def(
            "lookup",
            [](const MomentTexture& t, py::object s, py::object tc, py::object lod, int threads) {
        Broadcast b = broadcast({s, tc, lod});
        const double *ss = b.arrays[0].data(), *ts = b.arrays[1].data(), *ls = b.arrays[2].data();
        return moments_per_element(b.size, b.shape, threads, [&](std::size_t i) {
            return t.lookup(static_cast<float>(ss[i]), static_cast<float>(ts[i]), static_cast<float>(ls[i]));
        });
            },
            py::arg("s"), py::arg("t"), py::arg("lod"), py::arg("threads") = 0,
            "Trilinear lookups at texture coordinates (s, t) in [0, 1] (t down) and level of detail lod, on "
            "arrays that broadcast together: (mean, sigma) float64 arrays.")
        .def(
            "level",
            [](const MomentTexture& t, int level, int threads) {
        if (level < 0 || level >= t.reachable_levels())
            bad_argument("level " + std::to_string(level) + " is invalid (expected 0 .. " +
                         std::to_string(t.reachable_levels() - 1) + ")");
        const int w = moment_level_extent(t.info().width, level);
        const int h = moment_level_extent(t.info().height, level);
        return moments_per_element(static_cast<std::size_t>(w) * h, {h, w}, threads, [&](std::size_t i) {
            const float s = (static_cast<float>(i % w) + 0.5f) / static_cast<float>(w);
            const float tc = (static_cast<float>(i / w) + 0.5f) / static_cast<float>(h);
            return t.lookup(s, tc, static_cast<float>(level));
        });
            },
            py::arg("level"), py::arg("threads") = 0,
            "Every texel of a level, at its centre: (mean, sigma) float64 arrays of (height_k, width_k).")
        .def_property_readonly("width", [](const MomentTexture& t) { return t.info().width; })
        .def_property_readonly("height", [](const MomentTexture& t) { return t.info().height; })
        .def_property_readonly("levels", [](const MomentTexture& t) { return t.info().levels; })
        .def_property_readonly("reachable_levels", &MomentTexture::reachable_levels)
        .def_property_readonly("reference", &MomentTexture::reference)
        .def_property_readonly("wrap", [](const MomentTexture& t) { return std::string(to_string(t.info().wrap)); })
        .def_property_readonly("source", [](const MomentTexture& t) { return t.info().source; })
        .def_property_readonly("path", &MomentTexture::path);
}

}  // namespace cmfilter::python
