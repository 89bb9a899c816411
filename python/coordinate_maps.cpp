// SPDX-License-Identifier: Apache-2.0
// Coordinate maps of synthesised surfaces (sec. 4.2 of the second paper):
// read, made from arrays, written, viewed as arrays, and rendered through at
// any level of detail.
#include "bindings.h"

#include "cmfilter/synthesis/coordinate_lookup.h"
#include "cmfilter/synthesis/coordinate_map_file.h"

#include <pybind11/stl.h>

namespace cmfilter::python {

namespace {

const CoordinateLevel& level_of(const CoordinateMap& map, int level)
{
    if (level < 0 || level >= static_cast<int>(map.levels.size()))
        bad_argument("level " + std::to_string(level) + " is invalid (expected 0 .. " +
                     std::to_string(map.levels.size() - 1) + ")");
    return map.levels[static_cast<std::size_t>(level)];
}

CoordinateMap map_from_array(const py::array_t<std::int32_t, py::array::c_style | py::array::forcecast>& coords,
                             std::pair<int, int> sample_size, const std::string& sample_kind, bool sample_periodic)
{
    if (sample_kind != "image" && sample_kind != "stack" && sample_kind != "btf")
        bad_argument("sample_kind '" + sample_kind + "' is unknown (expected image, stack or btf)");
    if (coords.ndim() != 3 || coords.shape(2) != 2)
        bad_argument("coords must have shape (H, W, 2): the sample texel (x, y) of each output texel");
    CoordinateLevel level;
    level.height = static_cast<int>(coords.shape(0));
    level.width = static_cast<int>(coords.shape(1));
    level.sample_width = sample_size.first;
    level.sample_height = sample_size.second;
    level.coords.assign(coords.data(), coords.data() + coords.size());
    for (std::size_t t = 0; t < level.texels(); ++t)
        if (level.x(t) < 0 || level.x(t) >= level.sample_width || level.y(t) < 0 || level.y(t) >= level.sample_height)
            bad_argument("coords at texel " + std::to_string(t) + " is (" + std::to_string(level.x(t)) + ", " +
                         std::to_string(level.y(t)) + "), outside the " + std::to_string(level.sample_width) + " x " +
                         std::to_string(level.sample_height) + " sample");
    CoordinateMap map;
    map.info.levels = 1;
    map.info.sample_kind = sample_kind;
    // Not synthesised: recorded as the smallest synthesis the file format
    // reads back (k and neighbourhood >= 1).
    map.info.k = 1;
    map.info.neighbourhood = 1;
    map.info.sample_periodic = sample_periodic;
    map.levels.push_back(std::move(level));
    return map;
}

}  // namespace

void bind_coordinate_maps(py::module_& m)
{
    py::class_<CoordinateMap>(m, "CoordinateMap",
                              "A synthesised surface as, per output texel, the sample texel it copies.")
        .def(py::init(&map_from_array), py::arg("coords"), py::arg("sample_size"), py::kw_only(),
             py::arg("sample_kind") = "image", py::arg("sample_periodic") = false,
             "A one-level map from coords (H, W, 2) int32 sample texels (x, y) into a sample of sample_size "
             "(width, height), an image, stack or btf.")
        .def_static(
            "read",
            [](const std::string& path) {
        py::gil_scoped_release release;
        return unwrap(read_coordinate_map_exr(path));
            },
            py::arg("path"), "Reads a coordinate-map EXR (cmfilter synth).")
        .def(
            "write",
            [](const CoordinateMap& map, const std::string& path) {
        py::gil_scoped_release release;
        check(write_coordinate_map_exr(path, map));
            },
            py::arg("path"))
        .def(
            "coords",
            [](py::object self, int level) {
        const CoordinateLevel& l = level_of(self.cast<const CoordinateMap&>(), level);
        return view_array(l.coords.data(), {l.height, l.width, 2}, self);
            },
            py::arg("level") = 0, "(H, W, 2) int32 sample texels (x, y) of a level (a read-only view)")
        .def(
            "uv",
            [](const CoordinateMap& map, int level) {
        const CoordinateLevel& l = level_of(map, level);
        std::vector<float> uv(l.coords.size());
        for (std::size_t t = 0; t < l.texels(); ++t) {
            uv[2 * t] = (static_cast<float>(l.x(t)) + 0.5f) / static_cast<float>(l.sample_width);
            uv[2 * t + 1] = (static_cast<float>(l.y(t)) + 0.5f) / static_cast<float>(l.sample_height);
        }
        return owning_array(std::move(uv), {l.height, l.width, 2});
            },
            py::arg("level") = 0, "(H, W, 2) float32 texture coordinates of the copied texels' centres, as the file")
        .def(
            "sample_size",
            [](const CoordinateMap& map, int level) {
        const CoordinateLevel& l = level_of(map, level);
        return py::make_tuple(l.sample_width, l.sample_height);
            },
            py::arg("level") = 0)
        .def(
            "render",
            [](const CoordinateMap& map, const FloatArray& sample, int lod, const std::string& method, int patches,
               bool periodic, int threads) {
        if (sample.ndim() != 2 && sample.ndim() != 3) bad_argument("sample must have shape (H, W) or (H, W, C)");
        SampleImage image;
        image.height = static_cast<int>(sample.shape(0));
        image.width = static_cast<int>(sample.shape(1));
        image.channels = sample.ndim() == 3 ? static_cast<int>(sample.shape(2)) : 1;
        image.pixels.assign(sample.data(), sample.data() + sample.size());
        image.periodic = periodic;
        LodOptions options;
        options.lod = lod;
        options.method = unwrap(parse_lod_method(method));
        options.patches = patches;
        options.threads = threads;
        OutputImage out = [&] {
            py::gil_scoped_release release;
            return unwrap(render_at_lod(map, image, options));
        }();
        return owning_array(std::move(out.pixels), {out.height, out.width, out.channels});
            },
            py::arg("sample"), py::kw_only(), py::arg("lod") = 0, py::arg("method") = "patches", py::arg("patches") = 4,
            py::arg("periodic") = false, py::arg("threads") = 0,
            "The surface at level of detail lod (footprints of 2^lod texels) through the map from a sample image "
            "(H, W[, C]) by reference, naive, point, levels or patches: (h, w, C) float32.")
        .def_property_readonly("width", &CoordinateMap::width)
        .def_property_readonly("height", &CoordinateMap::height)
        .def_property_readonly("level_count", [](const CoordinateMap& map) { return map.levels.size(); })
        .def_property_readonly("info", [](const CoordinateMap& map) {
            py::dict d;
            d["sample_path"] = map.info.sample_path;
            d["sample_kind"] = map.info.sample_kind;
            d["sample_periodic"] = map.info.sample_periodic;
            d["k"] = map.info.k;
            d["neighbourhood"] = map.info.neighbourhood;
            d["levels"] = map.info.levels;
            d["toroidal"] = map.info.toroidal;
            d["seed"] = map.info.seed;
            return d;
        });
}

}  // namespace cmfilter::python
