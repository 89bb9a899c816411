// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/ops/filtered_image.h"

#include "cmfilter/texture/box_pyramid.h"
#include "cmfilter/texture/color_pyramid.h"
#include "cmfilter/texture/color_pyramid_texture.h"
#include "cmfilter/colormap/map_breakpoints.h"
#include "cmfilter/texture/segment_pyramid_texture.h"
#include "cmfilter/io/driver_image.h"
#include "cmfilter/tables/gaussian_color_table_file.h"
#include "cmfilter/texture/histogram_pyramid.h"
#include "cmfilter/io/image_reading.h"
#include "cmfilter/texture/moment_source.h"
#include "cmfilter/texture/moment_texture.h"
#include "cmfilter/math/moment_mixture.h"
#include "cmfilter/util/parallel_for.h"
#include "cmfilter/tables/table_color_map.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>
#include <system_error>

namespace cmfilter {

namespace {

std::string format_number(double v)
{
    std::ostringstream s;
    s.precision(9);
    s << v;
    return s.str();
}

// Level-0 driver texels outside [vmin, vmax], from the moments' m1 channel:
// f = c + m1, where float32 storage of f - c leaves an error of at most half
// an ulp of m1 (2^-24 |m1|); a texel counts as outside only beyond that.
Expected<std::size_t> count_outside(const std::string& path, const MomentPyramidInfo& info, double vmin, double vmax)
{
    auto in = open_image_input(path);
    if (!in) return in.error();
    if (auto fits = check_image_allocation((*in)->spec(), path, 1); !fits) return fits.error();
    std::vector<float> m1(static_cast<std::size_t>(info.width) * info.height);
    if (!read_float_pixels(**in, 0, 0, 0, 1, m1.data()))
        return io_error("cannot read level 0 of '" + path + "': " + (*in)->geterror());
    std::size_t outside = 0;
    for (float d : m1) {
        const double f = info.reference + d, slack = 0x1.0p-23 * std::abs(d);
        if (f < vmin - slack || f > vmax + slack) ++outside;
    }
    return outside;
}

// The driver a moment pyramid was baked from (reference), read the same way
// and checked against the recorded hash.
Expected<DriverImage> read_source_driver(const ApplyOptions& options, const MomentPyramidInfo& info, std::string& path,
                                         std::vector<std::string>& warnings, int threads)
{
    const bool overridden = !options.driver_path.empty();
    path = overridden ? options.driver_path : info.source;
    std::error_code ec;
    if (!overridden && !std::filesystem::is_regular_file(path, ec))
        return io_error(
            "cannot read driver '" + path + "' recorded in '" + options.moments_path +
                "' (cmfilter:source): no such file; pass ApplyOptions::driver_path PATH to give its location",
            "ApplyOptions::driver_path");
    auto driver = read_moment_source(path, options.moments_path, info, threads);
    if (!driver) return driver.error();
    if (!is_moment_source(*driver, info)) {
        const std::string what = moment_source_changed(path, *driver, options.moments_path, info);
        if (!overridden)
            return bad_input(what + "; re-bake the moments, or pass ApplyOptions::driver_path PATH to use it anyway",
                             "ApplyOptions::driver_path");
        warnings.push_back(what + "; using it as ApplyOptions::driver_path asks");
    }
    return std::move(driver->image);
}

// The level of detail clamped to [0, top], with its warning; and the output
// size (that of level floor(lod) unless asked).
void set_output_lod(FilteredImage& out, const ApplyOptions& options, int top, int width, int height)
{
    out.top_level = top;
    const float lod = std::clamp(static_cast<float>(options.lod), 0.0f, static_cast<float>(top));
    out.lod = lod;
    out.lod_clamped = static_cast<double>(lod) != options.lod;
    if (out.lod_clamped)
        out.warnings.push_back("ApplyOptions::lod " + format_number(options.lod) + " is outside [0, " +
                               std::to_string(top) + "] for '" + options.moments_path + "' (" + std::to_string(width) +
                               " x " + std::to_string(height) + "); clamped to " + format_number(lod));
    const int base = static_cast<int>(std::floor(lod));
    out.width = options.width > 0 ? options.width : box_level_extent(width, base);
    out.height = options.height > 0 ? options.height : box_level_extent(height, base);
}

// Every output pixel's colour, rows in parallel, progress between batches;
// `shade(s, t, lod, row)` colours one pixel of row `row`.
template <class Shade>
void shade_pixels(FilteredImage& out, const ApplyOptions& options, const Shade& shade)
{
    const int W = out.width, H = out.height;
    const float lod = static_cast<float>(out.lod);
    out.rgb.assign(static_cast<std::size_t>(W) * H * 3, 0.0f);
    const auto shade_row = [&](int y) {
        const float t = static_cast<float>((y + 0.5) / H);
        for (int x = 0; x < W; ++x) {
            const float s = static_cast<float>((x + 0.5) / W);
            const Rgb c = shade(s, t, lod, y);
            float* p = out.rgb.data() + (static_cast<std::size_t>(y) * W + x) * 3;
            p[0] = static_cast<float>(c.r);
            p[1] = static_cast<float>(c.g);
            p[2] = static_cast<float>(c.b);
        }
    };
    const int batch = std::max(1, std::min(H, 4 * resolve_thread_count(options.threads)));
    for (int y0 = 0; y0 < H; y0 += batch) {
        const int n = std::min(batch, H - y0);
        parallel_for(n, options.threads, [&](int i) { shade_row(y0 + i); });
        if (options.progress) options.progress(static_cast<double>(y0 + n) / H);
    }
}

// What every method's image says of its inputs before it is shaded.
FilteredImage image_of(const ApplyOptions& options, const ColorConfig& config)
{
    FilteredImage out;
    out.method = options.method;
    out.linear_space = config.scene_linear_name();
    out.moments_path = options.moments_path;
    out.table_path = options.table_path;
    out.lod_requested = options.lod;
    return out;
}

// What the image records of the driver of a baked colour or segment
// pyramid, as a moment pyramid's info.
template <class Info>
void record_driver(MomentPyramidInfo& moments, const Info& info)
{
    moments.width = info.width;
    moments.height = info.height;
    moments.levels = info.levels;
    moments.wrap = info.wrap;
    moments.channel = info.channel;
    moments.channel_index = info.channel_index;
    moments.driver_min = info.driver_min;
    moments.driver_max = info.driver_max;
    moments.source = info.source;
    moments.source_sha256 = info.source_sha256;
}

// The colour map of a table (TableColorMapOptions), its path and warnings
// recorded in `out`.
Expected<TableColorMap> table_map(const ApplyOptions& options, const LoadedGaussianColorTable& table,
                                  const ColorConfig& config, FilteredImage& out)
{
    TableColorMapOptions mo;
    mo.table_path = options.table_path;
    mo.map_override = options.map_path;
    auto map = load_table_color_map(table, mo, config);
    if (!map) return map.error();
    out.map_path = map->map.provenance.path;
    out.warnings.insert(out.warnings.end(), map->warnings.begin(), map->warnings.end());
    return map;
}

// color-pyramid: the baked box means of C0(f), one RGB lookup a pixel,
// through the map of the table (checked against the pyramid's digest).
Expected<FilteredImage> apply_color_pyramid(const ApplyOptions& options, const ColorConfig& config)
{
    FilteredImage out = image_of(options, config);
    auto pyramid = ColorPyramidTexture::open(options.moments_path);
    if (!pyramid) {
        if (MomentTexture::open(options.moments_path))
            return bad_input("ApplyOptions::method color-pyramid reads a colour pyramid, and '" + options.moments_path +
                                 "' is a moment pyramid (bake one with bake-moments DRIVER --method color-pyramid "
                                 "--table T.exr)",
                             "ApplyOptions::moments_path");
        return pyramid.error();
    }
    const ColorPyramidInfo& info = pyramid->info();
    if (!info.linear_space.empty() && info.linear_space != out.linear_space)
        return bad_input("colour pyramid '" + options.moments_path + "' holds colours in '" + info.linear_space +
                         "', and the OpenColorIO config's scene-linear space is '" + out.linear_space +
                         "' (expected the same: re-bake it under this config)");
    auto table = read_gaussian_color_table(options.table_path);
    if (!table) return table.error();
    auto map = table_map(options, *table, config, out);
    if (!map) return map.error();
    if (auto st = check_color_pyramid_map(info, options.moments_path, map->map.map,
                                          "the map of table '" + options.table_path + "' ('" + out.map_path + "')");
        !st)
        return st.error();
    record_driver(out.moments, info);
    set_output_lod(out, options, pyramid->reachable_levels() - 1, info.width, info.height);
    std::vector<std::size_t> failed(out.height, 0);
    shade_pixels(out, options, [&](float s, float t, float lod, int y) {
        const ColorPyramidSample c = pyramid->lookup(s, t, lod);  // mean C0(f) over the footprint
        if (!c.ok) ++failed[y];
        return c.color;
    });
    for (std::size_t n : failed) out.failed_lookups += n;
    if (out.failed_lookups > 0)
        out.warnings.push_back(std::to_string(out.failed_lookups) + " texture lookups failed and were read as black");
    return out;
}

// segments: the ramp means of the footprint (K lookups of one texture) and
// the table's map at the pyramid's breakpoints, which it must fit:
// mean C = C(t_0) + sum_k (C(t_k) - C(t_{k-1})) R_k (map_breakpoints.h).
Expected<FilteredImage> apply_segments(const ApplyOptions& options, const ColorConfig& config)
{
    FilteredImage out = image_of(options, config);
    auto pyramid = SegmentPyramidTexture::open(options.moments_path);
    if (!pyramid) {
        if (MomentTexture::open(options.moments_path) || ColorPyramidTexture::open(options.moments_path))
            return bad_input("ApplyOptions::method segments reads a segment pyramid, and '" + options.moments_path +
                                 "' is another pyramid (bake one with bake-moments DRIVER --segments T.exr)",
                             "ApplyOptions::moments_path");
        return pyramid.error();
    }
    const SegmentPyramidInfo& info = pyramid->info();
    auto table = read_gaussian_color_table(options.table_path);
    if (!table) return table.error();
    auto map = table_map(options, *table, config, out);
    if (!map) return map.error();
    const std::string map_name = "the map of table '" + options.table_path + "' ('" + out.map_path + "')";
    auto fit = check_segment_pyramid_map(info, options.moments_path, map->map.map, map_name);
    if (!fit) return fit.error();
    out.segment_fit_de = fit->max_de;
    out.segment_mean_fit_de = fit->mean_de;
    if (auto w = segment_recolour_warning(info, options.moments_path, *fit, map_name)) out.warnings.push_back(*w);
    const std::vector<Rgb> colors = ramp_colors(map->map.map, info.breakpoints, info.weights());
    record_driver(out.moments, info);
    set_output_lod(out, options, pyramid->reachable_levels() - 1, info.width, info.height);
    const int H = out.height;
    std::vector<std::size_t> failed(H, 0);
    std::vector<std::vector<float>> row_ramps(H, std::vector<float>(pyramid->channels()));
    shade_pixels(out, options, [&](float s, float t, float lod, int y) {
        float* ramps = row_ramps[y].data();
        if (!pyramid->lookup(s, t, lod, ramps)) ++failed[y];
        return ramp_color(colors, ramps);
    });
    for (std::size_t n : failed) out.failed_lookups += n;
    if (out.failed_lookups > 0)
        out.warnings.push_back(std::to_string(out.failed_lookups) + " texture lookups failed and were read as black");
    return out;
}

}  // namespace

const char* to_string(FilterMethod method)
{
    switch (method) {
    case FilterMethod::Naive: return "naive";
    case FilterMethod::Gaussian: return "gaussian";
    case FilterMethod::Exact: return "exact";
    case FilterMethod::Reference: return "reference";
    case FilterMethod::Mixture: return "mixture";
    case FilterMethod::ColorPyramid: return "color-pyramid";
    case FilterMethod::Segments: return "segments";
    }
    return "?";
}

Expected<FilterMethod> parse_filter_method(const std::string& name)
{
    for (FilterMethod m : {FilterMethod::Naive, FilterMethod::Gaussian, FilterMethod::Exact, FilterMethod::Reference,
                           FilterMethod::Mixture, FilterMethod::ColorPyramid, FilterMethod::Segments})
        if (name == to_string(m)) return m;
    return bad_input("unknown method '" + name +
                     "' (expected naive, gaussian, mixture, exact, color-pyramid, segments or reference)");
}

Expected<FilteredImage> apply_filter(const ApplyOptions& options, const ColorConfig& config)
{
    if (options.width < 0 || options.height < 0 || (options.width == 0) != (options.height == 0))
        return bad_input("output size " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                         " is invalid (expected W, H >= 1)");
    if (!std::isfinite(options.lod))
        return bad_input("ApplyOptions::lod " + format_number(options.lod) + " is invalid (expected a finite number)",
                         "ApplyOptions::lod");
    if (options.method == FilterMethod::Exact && options.histograms_path.empty())
        return bad_input("ApplyOptions::method exact needs ApplyOptions::histograms_path (the driver's histogram "
                         "pyramid, sec. 4.1)",
                         "ApplyOptions::histograms_path");

    if (options.method == FilterMethod::ColorPyramid) return apply_color_pyramid(options, config);
    if (options.method == FilterMethod::Segments) return apply_segments(options, config);

    FilteredImage out = image_of(options, config);

    auto moments = MomentTexture::open(options.moments_path);
    if (!moments) return moments.error();
    const MomentPyramidInfo& info = moments->info();
    out.moments = info;
    if (options.method == FilterMethod::Mixture && info.order != 4)
        return bad_input("ApplyOptions::method mixture needs a moment pyramid of order 4; '" + options.moments_path +
                             "' holds " + std::to_string(info.order) +
                             " moments (re-bake it with MomentBakeOptions::order 4)",
                         "ApplyOptions::moments_path");
    auto table = read_gaussian_color_table(options.table_path);
    if (!table) return table.error();
    const TableAxes& axes = table->table.axes();

    // The driver's range against the map's domain. With clamp, a driver
    // entirely outside would take one end colour everywhere: refused.
    const std::string domain = "[" + format_number(axes.vmin) + ", " + format_number(axes.vmax) + "]";
    if (axes.wrap == WrapMode::Clamp && (info.driver_max < axes.vmin || info.driver_min > axes.vmax))
        return bad_input("the driver range [" + format_number(info.driver_min) + ", " + format_number(info.driver_max) +
                         "] of '" + options.moments_path + "' does not overlap the domain " + domain + " of table '" +
                         options.table_path +
                         "' (expected overlapping ranges; re-bake the table "
                         "with a ColorMapLoadOptions::vmin:vmax that covers the driver)");
    if (info.driver_min < axes.vmin || info.driver_max > axes.vmax) {
        auto outside = count_outside(options.moments_path, info, axes.vmin, axes.vmax);
        if (!outside) return outside.error();
        out.texels_outside_domain = *outside;
        out.fraction_outside_domain = static_cast<double>(*outside) / (static_cast<double>(info.width) * info.height);
        if (axes.wrap == WrapMode::Clamp && *outside > 0)
            out.warnings.push_back(std::to_string(*outside) + " of the driver's texels (" +
                                   format_number(100 * out.fraction_outside_domain) + "%) lie outside the domain " +
                                   domain + " of table '" + options.table_path + "' and take its end colours");
    }

    // The level of detail: TextureSystem can reach levels 0 .. top.
    set_output_lod(out, options, moments->reachable_levels() - 1, info.width, info.height);

    // C0 itself, for the methods that evaluate it exactly.
    std::optional<TableColorMap> map;
    if (options.method != FilterMethod::Gaussian && options.method != FilterMethod::Mixture) {
        TableColorMapOptions mo;
        mo.table_path = options.table_path;
        mo.map_override = options.map_path;
        auto loaded = load_table_color_map(*table, mo, config);
        if (!loaded) return loaded.error();
        map = std::move(*loaded);
        out.map_path = map->map.provenance.path;
        out.warnings.insert(out.warnings.end(), map->warnings.begin(), map->warnings.end());
    }

    std::optional<ColorPyramid> pyramid;
    if (options.method == FilterMethod::Reference) {
        auto driver = read_source_driver(options, info, out.driver_path, out.warnings, options.threads);
        if (!driver) return driver.error();
        ColorPyramidOptions po;
        po.driver = &driver->values;
        po.width = info.width;
        po.height = info.height;
        po.map = &map->map.map;
        po.wrap = info.wrap;
        po.reference = info.reference;
        po.threads = options.threads;
        pyramid = ColorPyramid::build(po);
    }

    std::optional<HistogramTexture> histograms;
    std::vector<Rgb> bin_colors;
    if (options.method == FilterMethod::Exact) {
        auto h = HistogramTexture::open(options.histograms_path);
        if (!h) return h.error();
        if (h->info().width != info.width || h->info().height != info.height)
            return bad_input("histogram pyramid '" + options.histograms_path + "' is " +
                             std::to_string(h->info().width) + " x " + std::to_string(h->info().height) + " but '" +
                             options.moments_path + "' is " + std::to_string(info.width) + " x " +
                             std::to_string(info.height) + " (expected the same driver)");
        for (double v : h->info().values) bin_colors.push_back(map->map.map.evaluate(v));
        out.histograms_path = options.histograms_path;
        histograms = std::move(*h);
    }

    const MomentMixtureOptions mixture_options = pyramid_mixture_options(info.driver_min, info.driver_max);

    // Every output pixel, rows in parallel; progress between batches of rows.
    const int H = out.height;
    std::vector<LookupCounters> counters(H);
    std::vector<std::size_t> failed(H, 0);
    // exact: one row's histogram weights (a row is shaded on one thread).
    std::vector<std::vector<float>> row_weights(bin_colors.empty() ? 0 : H);
    shade_pixels(out, options, [&](float s, float t, float lod, int y) {
        Rgb c;
        if (options.method == FilterMethod::Reference) {
            c = pyramid->lookup(s, t, lod);  // mean C0(f) over the footprint
        } else if (options.method == FilterMethod::Exact) {
            // <C0, D> = sum_b h_b C0(v_b), exact for a box footprint (sec. 4.1).
            std::vector<float>& weights = row_weights[y];
            weights.resize(bin_colors.size());
            if (histograms->lookup(s, t, lod, weights.data()))
                for (std::size_t b = 0; b < weights.size(); ++b) c += weights[b] * bin_colors[b];
            else ++failed[y];
        } else {
            const MomentSample m = moments->lookup(s, t, lod);  // mean f, sigma_f (sec. 4.2)
            if (!m.ok) ++failed[y];
            if (options.method == FilterMethod::Naive) {
                c = map->map.map.evaluate(m.mean);  // C0(mean f)
            } else if (options.method == FilterMethod::Mixture) {
                const MomentMixture mix = moment_mixture(m.mean, m.variance, m.mu3, m.mu4, mixture_options);
                c = mix.weight * table->table.lookup(mix.lower, mix.sigma, &counters[y]);
                if (mix.weight < 1) c += (1 - mix.weight) * table->table.lookup(mix.upper, mix.sigma, &counters[y]);
            } else {
                c = table->table.lookup(m.mean, m.sigma, &counters[y]);  // T(mean, sigma), eq. 10
            }
        }
        return c;
    });
    for (int y = 0; y < H; ++y) {
        out.table_counters.lookups += counters[y].lookups;
        out.table_counters.sigma_clamped += counters[y].sigma_clamped;
        out.table_counters.value_clamped += counters[y].value_clamped;
        out.table_counters.invalid += counters[y].invalid;
        out.failed_lookups += failed[y];
    }
    if (out.failed_lookups > 0)
        out.warnings.push_back(std::to_string(out.failed_lookups) + " texture lookups failed and were read as black");
    return out;
}

}  // namespace cmfilter
