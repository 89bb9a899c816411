// SPDX-License-Identifier: Apache-2.0
// Drivers read as data and their moment pyramids (sec. 4.2): bake, open, and
// the footprint's mean and sigma at any (s, t, lod), or a whole level; over
// anisotropic footprints, by TextureSystem's anisotropic filter or as the
// renderer cuts them into probes (anisotropic_probes.h), coloured as it
// colours them (texture_footprint.h).
#include "bindings.h"

#include "cmfilter/colormap/color_map_loading.h"
#include "cmfilter/io/driver_image.h"
#include "cmfilter/render/render_options.h"
#include "cmfilter/render/texture_footprint.h"
#include "cmfilter/tables/gaussian_color_table_file.h"
#include "cmfilter/texture/moment_pyramid.h"
#include "cmfilter/texture/moment_texture.h"

#include <cstdint>

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

TextureColor parse_texture_color(const std::string& method)
{
    if (method == "none") return TextureColor::None;
    if (method == "naive") return TextureColor::Naive;
    if (method == "gaussian") return TextureColor::Gaussian;
    if (method == "exact") return TextureColor::Exact;
    if (method == "mixture") return TextureColor::Mixture;
    bad_argument("method '" + method + "' is unknown (expected none, naive, gaussian, mixture or exact)");
}

// The colour layer a method needs: C0 for naive and exact, T for gaussian
// and mixture (without the small-sigma shortcut; mixture also four moments),
// the histograms for exact.
ColorLayer footprint_layer(TextureColor colour, const LoadedColorMap* colormap, const LoadedGaussianColorTable* table,
                           const HistogramTexture* histograms, const MomentTexture& moments)
{
    ColorLayer layer;
    if ((colour == TextureColor::Naive || colour == TextureColor::Exact) && !colormap)
        bad_argument(std::string("method ") + (colour == TextureColor::Naive ? "naive" : "exact") +
                     " needs colormap (a ColorMap)");
    if (colour == TextureColor::Gaussian && !table) bad_argument("method gaussian needs table (a ColorTable)");
    if (colour == TextureColor::Mixture) {
        if (!table) bad_argument("method mixture needs table (a ColorTable)");
        if (moments.info().order != 4)
            bad_argument("method mixture needs a moment pyramid of order 4 (MomentPyramid.bake(..., order=4)); this "
                         "one holds " +
                         std::to_string(moments.info().order) + " moments");
    }
    if (colour == TextureColor::Exact) {
        if (!histograms) bad_argument("method exact needs histograms (the driver's HistogramPyramid)");
        const HistogramPyramidInfo& h = histograms->info();
        if (h.width != moments.info().width || h.height != moments.info().height)
            bad_argument("histograms are " + std::to_string(h.width) + " x " + std::to_string(h.height) +
                         " but the moment pyramid is " + std::to_string(moments.info().width) + " x " +
                         std::to_string(moments.info().height) + " (expected the same driver's)");
    }
    if (colormap) layer.map = colormap->map;
    if (table) layer.table = table->table;
    return layer;
}

// filter_texture_footprint at every element: the footprint c + s e1 + t e2
// (s, t in [-1/2, 1/2]) of e1 = (du_dx, dv_dx), e2 = (du_dy, dv_dy).
py::dict footprints(const MomentTexture& moments, const std::vector<py::object>& coordinates, int probes,
                    const std::string& footprint, const std::string& method, const LoadedColorMap* colormap,
                    const LoadedGaussianColorTable* table, const HistogramTexture* histograms, int threads)
{
    check(check_render_probes(probes));
    const FootprintWidth width = unwrap(parse_footprint_width(footprint));
    const TextureColor colour = parse_texture_color(method);
    const ColorLayer layer = footprint_layer(colour, colormap, table, histograms, moments);
    std::vector<Rgb> bin_colors;
    if (colour == TextureColor::Exact)
        for (double v : histograms->info().values) bin_colors.push_back(layer.map.evaluate(v));
    const FilteredTexture texture = unwrap(FilteredTexture::create(moments, std::nullopt));
    Broadcast b = broadcast(coordinates);
    const std::size_t n = b.size;
    std::vector<double> albedo(colour == TextureColor::None ? 0 : 3 * n), mean(n), sigma(n), lod(n);
    std::vector<std::int32_t> count(n);
    for_each_element(n, threads, [&](std::size_t i) {
        SurfaceHit h;
        h.u = b.arrays[0].data()[i];
        h.v = b.arrays[1].data()[i];
        h.du_dx = b.arrays[2].data()[i];
        h.dv_dx = b.arrays[3].data()[i];
        h.du_dy = b.arrays[4].data()[i];
        h.dv_dy = b.arrays[5].data()[i];
        std::vector<float> weights;
        const TextureFootprint f =
            filter_texture_footprint(layer, texture, histograms, h, colour, width, probes, bin_colors, weights);
        mean[i] = f.mean;
        sigma[i] = f.sigma;
        lod[i] = f.lod;
        count[i] = f.probes;
        if (!albedo.empty()) {
            albedo[3 * i] = f.albedo.r;
            albedo[3 * i + 1] = f.albedo.g;
            albedo[3 * i + 2] = f.albedo.b;
        }
    });
    py::dict d;
    d["mean"] = owning_array(std::move(mean), b.shape);
    d["sigma"] = owning_array(std::move(sigma), b.shape);
    d["lod"] = owning_array(std::move(lod), b.shape);
    d["probes"] = owning_array(std::move(count), b.shape);
    if (colour != TextureColor::None) d["albedo"] = owning_array(std::move(albedo), with_trailing(b.shape, {3}));
    return d;
}

}  // namespace

void set_pyramid_bake_options(PyramidBakeOptions& options, const std::string& driver, const std::string& output,
                              const std::string& channel, const std::string& wrap, const std::string& nonfinite,
                              int threads)
{
    options.driver_path = driver;
    options.output_path = output;
    options.channel = channel;
    options.wrap = unwrap(parse_texture_wrap(wrap));
    options.nonfinite = unwrap(parse_non_finite_policy(nonfinite));
    options.threads = threads;
}

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
               const std::string& wrap, const std::string& nonfinite, int threads, int order) {
        MomentBakeOptions options;
        set_pyramid_bake_options(options, driver, output, channel, wrap, nonfinite, threads);
        options.order = order;
        {
            py::gil_scoped_release release;
            unwrap(bake_moment_pyramid(options));
        }
        return open_moments(output);
            },
            py::arg("driver"), py::arg("output"), py::kw_only(), py::arg("channel") = "", py::arg("wrap") = "clamp",
            py::arg("nonfinite") = "error", py::arg("threads") = 0, py::arg("order") = 2,
            "Bakes the moment pyramid of a driver image into `output` (.exr, as bake-moments) and opens it; "
            "order 4 adds the means of (f - c)^3 and (f - c)^4 for apply's mixture method.")
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
            "lookup_anisotropic",
            [](const MomentTexture& t, py::object s, py::object tc, py::object dsdx, py::object dtdx, py::object dsdy,
               py::object dtdy, int threads) {
        Broadcast b = broadcast({s, tc, dsdx, dtdx, dsdy, dtdy});
        const auto at = [&](int k, std::size_t i) { return static_cast<float>(b.arrays[k].data()[i]); };
        return moments_per_element(b.size, b.shape, threads, [&](std::size_t i) {
            return t.lookup(at(0, i), at(1, i), at(2, i), at(3, i), at(4, i), at(5, i));
        });
            },
            py::arg("s"), py::arg("t"), py::arg("dsdx"), py::arg("dtdx"), py::arg("dsdy"), py::arg("dtdy"),
            py::arg("threads") = 0,
            "TextureSystem's anisotropic lookups (bilinear probes along the major axis) over the footprints spanned "
            "by the derivatives of (s, t), on arrays that broadcast together: (mean, sigma) float64 arrays.")
        .def(
            "lookup_footprint",
            [](const MomentTexture& t, py::object u, py::object v, py::object du_dx, py::object dv_dx, py::object du_dy,
               py::object dv_dy, int probes, const std::string& footprint, const std::string& method,
               const LoadedColorMap* colormap, const LoadedGaussianColorTable* table,
               const HistogramTexture* histograms, int threads) {
        return footprints(t, {u, v, du_dx, dv_dx, du_dy, dv_dy}, probes, footprint, method, colormap, table, histograms,
                          threads);
            },
            py::arg("u"), py::arg("v"), py::arg("du_dx"), py::arg("dv_dx"), py::arg("du_dy"), py::arg("dv_dy"),
            py::kw_only(), py::arg("probes") = 16, py::arg("footprint") = "rms", py::arg("method") = "none",
            py::arg("colormap") = py::none(), py::arg("table") = py::none(), py::arg("histograms") = py::none(),
            py::arg("threads") = 0,
            "The parallelogram footprints c + s e1 + t e2 (s, t in [-1/2, 1/2]; c = (u, v), e1 = (du_dx, dv_dx), "
            "e2 = (du_dy, dv_dy), texture repeats) as `render` filters them: cut along the major edge into up to "
            "`probes` pieces, each a square of the `footprint` width (rms, area, major, minor) looked up "
            "trilinearly. A dict of arrays of the broadcast shape: mean and sigma (the probes' means), lod (of one "
            "probe's width, log2 in level-0 texels), probes (int32); with method naive (C0(mean_j), needs "
            "colormap), gaussian (T(mean_j, sigma_j), needs table), mixture (two Gaussians from each probe's four "
            "moments, needs table and an order-4 pyramid) or exact (sum_b h_b C0(v_b), needs colormap and "
            "histograms) also albedo (..., 3), the mean of the probes' colours.")
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
