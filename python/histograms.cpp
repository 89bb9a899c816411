// SPDX-License-Identifier: Apache-2.0
// Histogram pyramids, the exact method's data (sec. 4.1, "exact solutions"):
// bake one from a driver with few distinct values, open it, and look up the
// fraction of a footprint at each value at any (s, t, lod), or a whole level.
#include "bindings.h"

#include "cmfilter/texture/histogram_pyramid.h"
#include "cmfilter/texture/moment_pyramid.h"
#include "cmfilter/texture/texture_lod.h"

#include <tuple>

namespace cmfilter::python {

namespace {

HistogramTexture open_histograms(const std::string& path)
{
    py::gil_scoped_release release;
    return unwrap(HistogramTexture::open(path));
}

// The bins() weights per element of `count`, looked up at `at(i)` = (s, t,
// lod): (shape..., bins) float32.
template <typename At>
py::array_t<float> weights_per_element(const HistogramTexture& h, std::size_t count, std::vector<py::ssize_t> shape,
                                       int threads, At&& at)
{
    const auto bins = static_cast<std::size_t>(h.bins());
    std::vector<float> weights(count * bins);
    for_each_element(count, threads, [&](std::size_t i) {
        const auto [s, t, lod] = at(i);
        h.lookup(s, t, lod, weights.data() + i * bins);
    });
    return owning_array(std::move(weights), with_trailing(std::move(shape), {static_cast<py::ssize_t>(bins)}));
}

}  // namespace

void bind_histograms(py::module_& m)
{
    py::class_<HistogramTexture>(m, "HistogramPyramid",
                                 "A histogram pyramid (sec. 4.1): per level and texel the fraction of its box "
                                 "footprint at each distinct driver value, looked up through OpenImageIO's "
                                 "TextureSystem as a moment pyramid is. The exact method's data.")
        .def_static(
            "bake",
            [](const std::string& driver, const std::string& output, const std::string& channel,
               const std::string& wrap, const std::string& nonfinite, int threads) {
        HistogramBakeOptions options;
        set_pyramid_bake_options(options, driver, output, channel, wrap, nonfinite, threads);
        {
            py::gil_scoped_release release;
            unwrap(bake_histogram_pyramid(options));
        }
        return open_histograms(output);
            },
            py::arg("driver"), py::arg("output"), py::kw_only(), py::arg("channel") = "", py::arg("wrap") = "clamp",
            py::arg("nonfinite") = "error", py::arg("threads") = 0,
            "Bakes the histogram pyramid of a driver of at most 256 distinct values into `output` (.exr, as "
            "bake-moments --histograms) and opens it.")
        .def_static("open", &open_histograms, py::arg("path"), "Opens a histogram pyramid file.")
        .def(
            "lookup",
            [](const HistogramTexture& h, py::object s, py::object tc, py::object lod, int threads) {
        Broadcast b = broadcast({s, tc, lod});
        const double *ss = b.arrays[0].data(), *ts = b.arrays[1].data(), *ls = b.arrays[2].data();
        return weights_per_element(h, b.size, b.shape, threads, [&](std::size_t i) {
            return std::tuple<float, float, float>(static_cast<float>(ss[i]), static_cast<float>(ts[i]),
                                                   static_cast<float>(ls[i]));
        });
            },
            py::arg("s"), py::arg("t"), py::arg("lod"), py::arg("threads") = 0,
            "Trilinear lookups at (s, t, lod) (MomentPyramid.lookup's conventions) on arrays that broadcast "
            "together: (..., bins) float32, the fraction of the footprint at each of `values` (none negative, "
            "summing to 1 up to rounding). The exact colour is weights @ colormap.evaluate(values).")
        .def(
            "level",
            [](const HistogramTexture& h, int level, int threads) {
        const HistogramPyramidInfo& info = h.info();
        const int reachable = reachable_texture_levels(info.width, info.height, info.levels);
        if (level < 0 || level >= reachable)
            bad_argument("level " + std::to_string(level) + " is invalid (expected 0 .. " +
                         std::to_string(reachable - 1) + ")");
        const int w = moment_level_extent(info.width, level);
        const int ht = moment_level_extent(info.height, level);
        return weights_per_element(h, static_cast<std::size_t>(w) * ht, {ht, w}, threads, [&](std::size_t i) {
            return std::tuple<float, float, float>((static_cast<float>(i % w) + 0.5f) / static_cast<float>(w),
                                                   (static_cast<float>(i / w) + 0.5f) / static_cast<float>(ht),
                                                   static_cast<float>(level));
        });
            },
            py::arg("level"), py::arg("threads") = 0,
            "Every texel of a level, at its centre: (height_k, width_k, bins) float32.")
        .def_property_readonly(
            "values",
            [](const HistogramTexture& h) {
        std::vector<double> v = h.info().values;
        const auto n = static_cast<py::ssize_t>(v.size());
        return owning_array(std::move(v), {n});
            },
            "(bins,) float64: the driver's distinct values v_b, ascending")
        .def_property_readonly("bins", &HistogramTexture::bins)
        .def_property_readonly("width", [](const HistogramTexture& h) { return h.info().width; })
        .def_property_readonly("height", [](const HistogramTexture& h) { return h.info().height; })
        .def_property_readonly("levels", [](const HistogramTexture& h) { return h.info().levels; })
        .def_property_readonly("wrap", [](const HistogramTexture& h) { return std::string(to_string(h.info().wrap)); })
        .def_property_readonly("channel", [](const HistogramTexture& h) { return h.info().channel; })
        .def_property_readonly("source", [](const HistogramTexture& h) { return h.info().source; });
}

}  // namespace cmfilter::python
