// SPDX-License-Identifier: Apache-2.0
// Colour maps C0 and the prefiltered Gaussian colour table T(v, sigma) of
// eq. 10: load a map, evaluate it and its exact convolution, bake, read and
// write tables, and look them up on arrays of (mean, sigma).
#include "bindings.h"

#include "cmfilter/colormap/color_map_loading.h"
#include "cmfilter/tables/gaussian_color_table_file.h"
#include "cmfilter/tables/gaussian_convolution.h"
#include "cmfilter/tables/table_color_map.h"

#include <pybind11/stl.h>

#include <optional>

namespace cmfilter::python {

namespace {

static_assert(sizeof(Rgb) == 3 * sizeof(double), "Rgb is viewed as three doubles");

// fill(i, out + 3 i) for every element: the (..., 3) result.
template <typename Fill>
py::array_t<double> rgb_per_element(const Broadcast& b, int threads, Fill&& fill)
{
    std::vector<double> out(3 * b.size);
    for_each_element(b.size, threads, [&](std::size_t i) { fill(i, out.data() + 3 * i); });
    return owning_array(std::move(out), with_trailing(b.shape, {3}));
}

void store(const Rgb& c, double* out)
{
    out[0] = c.r;
    out[1] = c.g;
    out[2] = c.b;
}

// C0(v) on an array: (..., 3).
py::array_t<double> map_colors(const ColorMap& map, const py::object& v)
{
    Broadcast b = broadcast({v});
    const double* vs = b.arrays[0].data();
    return rgb_per_element(b, 1, [&](std::size_t i, double* out) { store(map.evaluate(vs[i]), out); });
}

// The exact T(v, sigma) of eq. 10 on arrays that broadcast: (..., 3), one
// convolution built per run of equal sigmas.
py::array_t<double> exact_colors(const ColorMap& map, const py::object& v, const py::object& sigma)
{
    Broadcast b = broadcast({v, sigma});
    const double *vs = b.arrays[0].data(), *ss = b.arrays[1].data();
    for (std::size_t i = 0; i < b.size; ++i)
        if (!(ss[i] >= 0)) bad_argument("sigma " + std::to_string(ss[i]) + " is invalid (expected >= 0)");
    std::vector<double> out(3 * b.size);
    {
        py::gil_scoped_release release;
        std::optional<GaussianConvolution> conv;
        double conv_sigma = -1;
        for (std::size_t i = 0; i < b.size; ++i) {
            if (ss[i] == 0) {
                store(map.evaluate(vs[i]), out.data() + 3 * i);
                continue;
            }
            if (!conv || ss[i] != conv_sigma) conv.emplace(map, conv_sigma = ss[i]);
            store((*conv)(vs[i]), out.data() + 3 * i);
        }
    }
    return owning_array(std::move(out), with_trailing(b.shape, {3}));
}

// T(mean, sigma) looked up bilinearly in the table, on arrays that broadcast.
py::array_t<double> table_colors(const LoadedGaussianColorTable& t, const py::object& mean, const py::object& sigma,
                                 int threads)
{
    Broadcast b = broadcast({mean, sigma});
    const double *ms = b.arrays[0].data(), *ss = b.arrays[1].data();
    return rgb_per_element(b, threads, [&](std::size_t i, double* out) { store(t.table.lookup(ms[i], ss[i]), out); });
}

// The colour map a table was baked from, from its metadata.
LoadedColorMap table_map(const LoadedGaussianColorTable& t, const std::string& map_override,
                         const std::string& ocio_config)
{
    TableColorMapOptions options;
    options.table_path = "table of " + t.info.source.path;
    options.map_override = map_override;
    const ColorConfig config = load_config(ocio_config);
    TableColorMap map = [&] {
        py::gil_scoped_release release;
        return unwrap(load_table_color_map(t, options, config));
    }();
    warn_all(map.warnings);
    return std::move(map.map);
}

py::dict provenance_dict(const ColorMapProvenance& p)
{
    py::dict d;
    d["path"] = p.path;
    d["sha256"] = p.sha256;
    d["image_size"] = py::make_tuple(p.image_width, p.image_height);
    d["selection"] = p.selection;
    d["colorspace"] = p.colorspace;
    d["colorspace_rule"] = p.colorspace_rule;
    d["linear_space"] = p.linear_space;
    d["ocio_config"] = p.ocio_config;
    return d;
}

LoadedColorMap load_map(const std::string& path, double vmin, double vmax, const std::string& wrap,
                        std::optional<int> row, std::optional<int> column, const std::string& colorspace,
                        const std::string& ocio_config)
{
    ColorMapLoadOptions options;
    options.path = path;
    options.vmin = vmin;
    options.vmax = vmax;
    options.wrap = unwrap(parse_wrap_mode(wrap));
    options.row = row;
    options.column = column;
    options.colorspace = colorspace;
    const ColorConfig config = load_config(ocio_config);
    py::gil_scoped_release release;
    return unwrap(load_color_map(options, config));
}

LoadedGaussianColorTable bake_table(const LoadedColorMap& map, int values, int sigmas, std::optional<double> sigma_max,
                                    const std::string& spacing, std::optional<double> margin, int threads)
{
    GaussianColorTableOptions options;
    options.values = values;
    options.sigmas = sigmas;
    options.sigma_max = sigma_max;
    options.spacing = unwrap(parse_sigma_spacing(spacing));
    options.margin = margin;
    options.threads = threads;
    LoadedGaussianColorTable out;
    py::gil_scoped_release release;
    out.table = unwrap(GaussianColorTable::bake(map.map, options));
    out.info.source = map.provenance;
    return out;
}

}  // namespace

void bind_tables(py::module_& m)
{
    py::class_<LoadedColorMap>(m, "ColorMap",
                               "The continuous colour map C0 (sec. 4): a scene-linear gradient over [vmin, vmax].")
        .def_static("load", &load_map, py::arg("path"), py::kw_only(), py::arg("vmin") = 0.0, py::arg("vmax") = 1.0,
                    py::arg("wrap") = "clamp", py::arg("row") = py::none(), py::arg("column") = py::none(),
                    py::arg("colorspace") = "", py::arg("ocio_config") = "",
                    "Reads a colour-map image (one row or column of it), converted to scene-linear with "
                    "OpenColorIO (bake-colormap's rules).")
        .def_property_readonly(
            "texels",
            [](py::object self) {
        const auto& map = self.cast<const LoadedColorMap&>().map;
        return view_array(reinterpret_cast<const double*>(map.texels.data()),
                          {static_cast<py::ssize_t>(map.texels.size()), 3}, self);
            },
            "(n, 3) float64 scene-linear texels (a read-only view)")
        .def_property_readonly("vmin", [](const LoadedColorMap& c) { return c.map.vmin; })
        .def_property_readonly("vmax", [](const LoadedColorMap& c) { return c.map.vmax; })
        .def_property_readonly("wrap", [](const LoadedColorMap& c) { return std::string(to_string(c.map.wrap)); })
        .def_property_readonly("provenance", [](const LoadedColorMap& c) { return provenance_dict(c.provenance); })
        .def(
            "evaluate", [](const LoadedColorMap& c, py::object v) { return map_colors(c.map, v); }, py::arg("v"),
            "C0(v): (..., 3) float64")
        .def(
            "convolve",
            [](const LoadedColorMap& c, py::object v, py::object sigma) { return exact_colors(c.map, v, sigma); },
            py::arg("v"), py::arg("sigma"),
            "The exact T(v, sigma) = (C0 * N(0, sigma^2))(v) of eq. 10, no table: (..., 3) float64. "
            "Fastest when equal sigmas are adjacent.");

    py::class_<LoadedGaussianColorTable>(m, "ColorTable",
                                         "The prefiltered Gaussian colour table T(v, sigma) of eq. 10.")
        .def_static("bake", &bake_table, py::arg("colormap"), py::kw_only(), py::arg("values") = 256,
                    py::arg("sigmas") = 256, py::arg("sigma_max") = py::none(), py::arg("spacing") = "sqrt",
                    py::arg("margin") = py::none(), py::arg("threads") = 0,
                    "Bakes the table of a ColorMap (bake-colormap's options).")
        .def_static(
            "read",
            [](const std::string& path) {
        py::gil_scoped_release release;
        return unwrap(read_gaussian_color_table(path));
            },
            py::arg("path"), "Reads a table file (docs/table-format.md).")
        .def(
            "write",
            [](const LoadedGaussianColorTable& t, const std::string& path) {
        GaussianColorTableInfo info = t.info;
        py::gil_scoped_release release;
        check(write_gaussian_color_table(path, t.table, info));
            },
            py::arg("path"), "Writes the table as a float OpenEXR with its cmfilter:* metadata, atomically.")
        .def("lookup", &table_colors, py::arg("mean"), py::arg("sigma"), py::arg("threads") = 0,
             "Bilinear T(mean, sigma) on arrays that broadcast together: (..., 3) float64.")
        .def("colormap", &table_map, py::kw_only(), py::arg("map_override") = "", py::arg("ocio_config") = "",
             "The colour map C0 the table was baked from, rebuilt from its metadata (the source image, checked by "
             "its SHA-256), or from map_override.")
        .def(
            "color",
            [](const LoadedGaussianColorTable& t, const py::object& mean, const py::object& sigma,
               const std::string& method, const LoadedColorMap* colormap, int threads) {
        if (method == "gaussian") return table_colors(t, mean, sigma, threads);
        if (method != "naive" && method != "gaussian-exact")
            bad_argument("method '" + method + "' is unknown (expected naive, gaussian or gaussian-exact)");
        const LoadedColorMap map = colormap ? *colormap : table_map(t, "", "");
        Broadcast b = broadcast({mean, sigma});
        if (method == "naive") return map_colors(map.map, b.arrays[0]);
        return exact_colors(map.map, b.arrays[0], b.arrays[1]);
            },
            py::arg("mean"), py::arg("sigma"), py::kw_only(), py::arg("method") = "gaussian",
            py::arg("colormap") = py::none(), py::arg("threads") = 0,
            "The colour of footprints of (mean, sigma) by a method: naive C0(mean), gaussian T(mean, sigma) from "
            "the table, gaussian-exact the exact convolution (eq. 10); C0 is `colormap`, else the table's own "
            "(colormap()). (..., 3) float64.")
        .def_property_readonly(
            "data",
            [](py::object self) {
        const auto& t = self.cast<const LoadedGaussianColorTable&>().table;
        return view_array(t.data().data(), {t.axes().sigmas, t.axes().values, 3}, self);
            },
            "(sigmas, values, 3) float32 nodes, row j at sigma_nodes[j] (a read-only view)")
        .def_property_readonly(
            "value_nodes",
            [](const LoadedGaussianColorTable& t) {
        std::vector<double> v(t.table.axes().values);
        for (int i = 0; i < t.table.axes().values; ++i) v[i] = t.table.axes().value_at(i);
        return owning_array(std::move(v), {t.table.axes().values});
            })
        .def_property_readonly(
            "sigma_nodes",
            [](const LoadedGaussianColorTable& t) {
        std::vector<double> s(t.table.axes().sigmas);
        for (int j = 0; j < t.table.axes().sigmas; ++j) s[j] = t.table.axes().sigma_at(j);
        return owning_array(std::move(s), {t.table.axes().sigmas});
            })
        .def_property_readonly("vmin", [](const LoadedGaussianColorTable& t) { return t.table.axes().vmin; })
        .def_property_readonly("vmax", [](const LoadedGaussianColorTable& t) { return t.table.axes().vmax; })
        .def_property_readonly("wrap", [](const LoadedGaussianColorTable& t) { return to_string(t.table.axes().wrap); })
        .def_property_readonly("sigma_max", [](const LoadedGaussianColorTable& t) { return t.table.axes().sigma_max; })
        .def_property_readonly("margin", [](const LoadedGaussianColorTable& t) { return t.table.axes().margin; })
        .def_property_readonly("spacing",
                               [](const LoadedGaussianColorTable& t) { return to_string(t.table.axes().spacing); })
        .def_property_readonly("source",
                               [](const LoadedGaussianColorTable& t) { return provenance_dict(t.info.source); });
}

}  // namespace cmfilter::python
