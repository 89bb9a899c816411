// SPDX-License-Identifier: Apache-2.0
// Whole-image operations: `apply` (a driver's filtered colour image at one
// level of detail, by method) and `compare` (RMSE and CIEDE2000 of two
// images, files or arrays).
#include "bindings.h"

#include "cmfilter/ops/filtered_image.h"
#include "cmfilter/ops/method_choice.h"
#include "cmfilter/ops/table_color_pyramid.h"
#include "cmfilter/ops/table_segment_pyramid.h"
#include "cmfilter/ops/image_comparison.h"

#include <pybind11/stl.h>

#include <optional>

namespace cmfilter::python {

namespace {

py::dict summary_dict(const ErrorSummary& s)
{
    py::dict d;
    d["count"] = s.count;
    d["mean"] = s.mean;
    d["p95"] = s.p95;
    d["max"] = s.max;
    return d;
}

FloatArray rgb_image(const py::object& value, const char* what)
{
    FloatArray a = py::cast<FloatArray>(value);
    if (a.ndim() != 3 || a.shape(2) != 3) bad_argument(std::string(what) + " must have shape (H, W, 3)");
    return a;
}

py::dict compare_arrays(const py::object& a_value, const py::object& b_value, int threads)
{
    FloatArray a = rgb_image(a_value, "a"), b = rgb_image(b_value, "b");
    if (a.shape(0) != b.shape(0) || a.shape(1) != b.shape(1))
        bad_argument("a is " + std::to_string(a.shape(1)) + " x " + std::to_string(a.shape(0)) + " but b is " +
                     std::to_string(b.shape(1)) + " x " + std::to_string(b.shape(0)) +
                     "; expected images of the same size");
    for (const FloatArray* x : {&a, &b})
        for (py::ssize_t i = 0; i < x->size(); ++i)
            if (!std::isfinite(x->data()[i]))
                bad_argument(std::string(x == &a ? "a" : "b") + " holds a non-finite value at flat index " +
                             std::to_string(i) + " (expected finite scene-linear RGB)");
    const int w = static_cast<int>(a.shape(1)), h = static_cast<int>(a.shape(0));
    RgbDifference d;
    ErrorSummary summary;
    {
        py::gil_scoped_release release;
        d = measure_rgb_difference(a.data(), b.data(), w, h, threads);
        summary = summarize_errors(d.de2000);
    }
    py::dict out;
    out["width"] = w;
    out["height"] = h;
    out["rmse"] = d.rmse;
    out["rmse_rgb"] = py::make_tuple(d.rmse_rgb[0], d.rmse_rgb[1], d.rmse_rgb[2]);
    out["de2000"] = summary_dict(summary);
    out["de2000_pixels"] = owning_array(std::move(d.de2000), {h, w});
    return out;
}

py::dict compare_files(const std::string& a, const std::string& b, const std::string& colorspace_a,
                       const std::string& colorspace_b, const std::optional<std::string>& heatmap, double heatmap_max,
                       const std::string& ocio_config, int threads)
{
    ImageComparisonOptions options;
    options.path_a = a;
    options.path_b = b;
    options.colorspace_a = colorspace_a;
    options.colorspace_b = colorspace_b;
    options.heatmap_path = heatmap.value_or("");
    options.heatmap_max = heatmap_max;
    options.threads = threads;
    const ColorConfig config = load_config(ocio_config);
    ImageComparison c = [&] {
        py::gil_scoped_release release;
        return unwrap(compare_images(options, config));
    }();
    py::dict out;
    out["width"] = c.width;
    out["height"] = c.height;
    out["rmse"] = c.rmse;
    out["rmse_rgb"] = py::make_tuple(c.rmse_rgb[0], c.rmse_rgb[1], c.rmse_rgb[2]);
    out["de2000"] = summary_dict(c.de2000);
    out["colorspace_a"] = c.a.colorspace;
    out["colorspace_b"] = c.b.colorspace;
    out["heatmap"] = c.heatmap_path;
    return out;
}

}  // namespace

void bind_ops(py::module_& m)
{
    m.def(
        "apply",
        [](const std::string& moments, const std::string& table, double lod, const std::string& method, int width,
           int height, const std::string& colormap, const std::string& driver, const std::string& histograms,
           const std::string& ocio_config, int threads) {
        ApplyOptions options;
        options.moments_path = moments;
        options.table_path = table;
        options.lod = lod;
        options.method = unwrap(parse_filter_method(method));
        options.width = width;
        options.height = height;
        options.map_path = colormap;
        options.driver_path = driver;
        options.histograms_path = histograms;
        options.threads = threads;
        const ColorConfig config = load_config(ocio_config);
        FilteredImage image = [&] {
            py::gil_scoped_release release;
            return unwrap(apply_filter(options, config));
        }();
        warn_all(image.warnings);
        return owning_array(std::move(image.rgb), {image.height, image.width, 3});
        },
        py::arg("moments"), py::arg("table"), py::kw_only(), py::arg("lod") = 0.0, py::arg("method") = "gaussian",
        py::arg("width") = 0, py::arg("height") = 0, py::arg("colormap") = "", py::arg("driver") = "",
        py::arg("histograms") = "", py::arg("ocio_config") = "", py::arg("threads") = 0,
        "The filtered image of a moment pyramid's driver through a table's colour map at level of detail lod, by "
        "naive, gaussian, mixture (an order-4 pyramid), exact, color-pyramid (moments names a colour pyramid, "
        "bake_color_pyramid), segments (moments names a segment pyramid, bake_segment_pyramid) or reference (as `cmfilter apply`): (H, W, 3) float32 scene-linear; warnings "
        "(a clamped lod, lookups outside the table) as Python warnings.");

    m.def(
        "bake_color_pyramid",
        [](const std::string& driver, const std::string& output, const std::string& table, const std::string& colormap,
           const std::string& channel, const std::string& wrap, const std::string& nonfinite,
           const std::string& pixel_type, const std::string& ocio_config, int threads) {
        TableColorPyramidOptions options;
        set_pyramid_bake_options(options.bake, driver, output, channel, wrap, nonfinite, threads);
        options.bake.storage.pixel_type = unwrap(parse_exr_pixel_type(pixel_type));
        options.table_path = table;
        options.map_path = colormap;
        const ColorConfig config = load_config(ocio_config);
        TableColorPyramid baked = [&] {
            py::gil_scoped_release release;
            return unwrap(bake_table_color_pyramid(options, config));
        }();
        warn_all(baked.warnings);
        py::dict out;
        out["output"] = output;
        out["width"] = baked.result.info.width;
        out["height"] = baked.result.info.height;
        out["levels"] = baked.result.info.levels;
        out["map"] = baked.map_path;
        out["map_sha256"] = baked.result.info.map_sha256;
        out["bytes_per_texel"] = baked.result.info.bytes_per_texel();
        return out;
        },
        py::arg("driver"), py::arg("output"), py::kw_only(), py::arg("table"), py::arg("colormap") = "",
        py::arg("channel") = "", py::arg("wrap") = "clamp", py::arg("nonfinite") = "error",
        py::arg("pixel_type") = "float", py::arg("ocio_config") = "", py::arg("threads") = 0,
        "Bakes the colour pyramid of a driver image through the colour map of `table` (C0(f) box-mipped, as "
        "`cmfilter bake-moments --method color-pyramid`) into `output` (.exr, float or half): a dict of what it "
        "wrote; apply(output, table, method='color-pyramid') reads it.");

    m.def(
        "bake_segment_pyramid",
        [](const std::string& driver, const std::string& output, const std::vector<std::string>& tables,
           double tolerance, int max_channels, const std::string& channel, const std::string& wrap,
           const std::string& nonfinite, const std::string& pixel_type, const std::string& ocio_config, int threads) {
        TableSegmentPyramidOptions options;
        set_pyramid_bake_options(options.bake, driver, output, channel, wrap, nonfinite, threads);
        options.bake.storage.pixel_type = unwrap(parse_exr_pixel_type(pixel_type));
        options.bake.tolerance_de = tolerance;
        options.bake.max_channels = max_channels;
        options.table_paths = tables;
        const ColorConfig config = load_config(ocio_config);
        TableSegmentPyramid baked = [&] {
            py::gil_scoped_release release;
            return unwrap(bake_table_segment_pyramid(options, config));
        }();
        warn_all(baked.warnings);
        const SegmentPyramidInfo& info = baked.result.info;
        py::dict out;
        out["output"] = output;
        out["width"] = info.width;
        out["height"] = info.height;
        out["levels"] = info.levels;
        out["breakpoints"] = info.breakpoints;
        out["channels"] = info.channels();
        out["candidates"] = baked.result.selection.candidates;
        out["maps"] = baked.map_paths;
        out["fit_de"] = baked.result.selection.max_de;
        out["mean_de"] = baked.result.selection.mean_de;
        out["bytes_per_texel"] = info.bytes_per_texel();
        return out;
        },
        py::arg("driver"), py::arg("output"), py::kw_only(), py::arg("tables"), py::arg("tolerance") = 0.0,
        py::arg("max_channels") = 0, py::arg("channel") = "", py::arg("wrap") = "clamp", py::arg("nonfinite") = "error",
        py::arg("pixel_type") = "float", py::arg("ocio_config") = "", py::arg("threads") = 0,
        "Bakes the segment pyramid of a driver image for the breakpoints of the colour maps of `tables` (as "
        "`cmfilter bake-moments --segments`; tolerance > 0: the fewest breakpoints within that mean CIEDE2000 "
        "over the driver) into `output` (.exr): a dict of what it wrote; apply(output, table, method='segments') "
        "reads it with any map on those breakpoints.");

    m.def(
        "segment_colors",
        [](const std::string& pyramid, const std::string& table, const std::string& ocio_config) {
        const ColorConfig config = load_config(ocio_config);
        SegmentColors c = unwrap(segment_pyramid_colors(pyramid, table, config));
        warn_all(c.warnings);
        py::array_t<double> colors({static_cast<py::ssize_t>(c.colors.size()), static_cast<py::ssize_t>(3)});
        auto v = colors.mutable_unchecked<2>();
        for (std::size_t k = 0; k < c.colors.size(); ++k)
            for (int ch = 0; ch < 3; ++ch) v(static_cast<py::ssize_t>(k), ch) = c.colors[k][ch];
        py::dict out;
        out["breakpoints"] = c.breakpoints;
        out["colors"] = colors;
        out["fit_de"] = c.fit_de;
        out["mean_fit_de"] = c.mean_fit_de;
        return out;
        },
        py::arg("pyramid"), py::arg("table"), py::kw_only(), py::arg("ocio_config") = "",
        "The colours C_0 .. C_K at the breakpoints of a segment pyramid for the map of `table`, what "
        "shaders/cmfilter_segments.glsl weighs the ramp means by and apply(method='segments') uses: the map's own "
        "colours there, or for a tolerance bake its least-squares colours over the driver: a dict of `breakpoints`, "
        "`colors` ((K + 1, 3) scene-linear), `fit_de` and, for a tolerance bake, `mean_fit_de` (the map's mean "
        "error through them over the driver; a warning when above the baked maps'). A map that does not fit the "
        "breakpoints is refused.");

    m.def(
        "choose_method",
        [](const std::string& moments, const std::string& table, double tolerance, const std::vector<double>& lods,
           const std::vector<std::string>& candidates, const std::string& colormap, const std::string& driver,
           const std::string& histograms, const std::string& color_pyramid, const std::string& segment_pyramid,
           const std::string& ocio_config, int threads) {
        ApplyOptions inputs;
        inputs.moments_path = moments;
        inputs.table_path = table;
        inputs.map_path = colormap;
        inputs.driver_path = driver;
        inputs.histograms_path = histograms;
        inputs.threads = threads;
        MethodChoiceOptions options;
        options.tolerance = tolerance;
        options.lods = lods;
        options.color_pyramid_path = color_pyramid;
        options.segment_pyramid_path = segment_pyramid;
        for (const std::string& c : candidates) options.candidates.push_back(unwrap(parse_filter_method(c)));
        const ColorConfig config = load_config(ocio_config);
        const MethodChoice choice = [&] {
            py::gil_scoped_release release;
            return unwrap(choose_filter_method(inputs, config, options));
        }();
        py::list trials;
        for (const MethodTrial& t : choice.trials) {
            py::dict d;
            d["method"] = to_string(t.method);
            d["bytes_per_texel"] = t.bytes_per_texel;
            d["table_lookups"] = t.table_lookups;
            d["errors"] = t.errors;
            d["worst"] = t.worst;
            d["worst_lod"] = t.worst_lod;
            d["meets"] = t.meets;
            d["time_ms"] = t.time_ms;
            trials.append(std::move(d));
        }
        py::dict out;
        out["tolerance"] = choice.tolerance;
        out["lods"] = choice.lods;
        out["method"] = choice.choice() ? py::object(py::str(to_string(choice.choice()->method))) : py::none();
        out["error"] = choice.choice() ? py::object(py::float_(choice.choice()->worst)) : py::none();
        out["trials"] = trials;
        out["skipped"] = choice.skipped;
        out["reference_ms"] = choice.reference_ms;
        return out;
        },
        py::arg("moments"), py::arg("table"), py::kw_only(), py::arg("tolerance"),
        py::arg("lods") = std::vector<double>{}, py::arg("candidates") = std::vector<std::string>{},
        py::arg("colormap") = "", py::arg("driver") = "", py::arg("histograms") = "", py::arg("color_pyramid") = "",
        py::arg("segment_pyramid") = "", py::arg("ocio_config") = "", py::arg("threads") = 0,
        "The cheapest method (naive, gaussian, color-pyramid with color_pyramid, segments with segment_pyramid, "
        "mixture, exact) whose mean CIEDE2000 against the box reference is at "
        "most tolerance at every LOD in lods (default 1..8), as `cmfilter apply --tolerance`: a dict with the method "
        "(None when nothing meets it), its error, and every candidate's bytes per texel, error per LOD and time.");

    m.def(
        "compare",
        [](const py::object& a, const py::object& b, const std::string& colorspace_a, const std::string& colorspace_b,
           const std::optional<std::string>& heatmap, double heatmap_max, const std::string& ocio_config, int threads) {
        const bool a_path = py::isinstance<py::str>(a) || py::hasattr(a, "__fspath__");
        const bool b_path = py::isinstance<py::str>(b) || py::hasattr(b, "__fspath__");
        if (a_path != b_path) bad_argument("a and b must both be files or both be arrays");
        if (a_path) {
            auto path = [](const py::object& p) { return py::str(py::module_::import("os").attr("fspath")(p)); };
            return compare_files(path(a), path(b), colorspace_a, colorspace_b, heatmap, heatmap_max, ocio_config,
                                 threads);
        }
        if (heatmap) bad_argument("heatmap is written for files only (compare arrays' de2000_pixels instead)");
        return compare_arrays(a, b, threads);
        },
        py::arg("a"), py::arg("b"), py::kw_only(), py::arg("colorspace_a") = "", py::arg("colorspace_b") = "",
        py::arg("heatmap") = py::none(), py::arg("heatmap_max") = 10.0, py::arg("ocio_config") = "",
        py::arg("threads") = 0,
        "RMSE (scene-linear) and per-pixel CIEDE2000 of two images: two files (as `cmfilter compare`, colour "
        "spaces decided alike) or two (H, W, 3) scene-linear arrays (then also de2000_pixels). A dict.");
}

}  // namespace cmfilter::python
