// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/texture/segment_pyramid_file.h"

#include "cmfilter/color/ciede2000.h"
#include "cmfilter/io/recorded_path.h"
#include "cmfilter/texture/box_pyramid.h"
#include "cmfilter/texture/box_pyramid_file.h"
#include "cmfilter/util/atomic_output.h"
#include "cmfilter/util/stopwatch.h"
#include "cmfilter/util/version.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace cmfilter {

namespace {

std::string number_text(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

std::string short_number(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

std::string joined(const std::vector<std::string>& parts, const char* sep)
{
    std::string s;
    for (std::size_t i = 0; i < parts.size(); ++i) s += (i ? sep : "") + parts[i];
    return s;
}

std::vector<std::string> split(const std::string& s, char sep)
{
    std::vector<std::string> out;
    if (s.empty()) return out;
    std::string part;
    std::istringstream in(s);
    while (std::getline(in, part, sep)) out.push_back(part);
    return out;
}

// The mean CIEDE2000 between the box means of C0(f) and of its interpolant
// through `breakpoints` at each level 1 .. min(8, top) of the driver's
// pyramid (the level geometry of box_pyramid.h): what apply would measure
// against the reference at those LODs.
std::vector<double> filtered_fit_errors(const ColorMap& map, const std::vector<double>& breakpoints,
                                        const DriverWeights* weights, const DriverImage& driver, int threads)
{
    const int W = driver.width, H = driver.height;
    const std::vector<Rgb> colors = breakpoint_colors(map, breakpoints, weights);
    BoxPyramidAccumulator acc(W, H, 6, threads);
    acc.add_rows(0, H, [&](int y, int, double* planes) {
        const float* row = driver.values.data() + static_cast<std::size_t>(y) * W;
        for (int x = 0; x < W; ++x) {
            const Rgb c = map.evaluate(row[x]), i = breakpoint_curve(breakpoints, colors, row[x]);
            const double v[6] = {c.r, c.g, c.b, i.r, i.g, i.b};
            for (int ch = 0; ch < 6; ++ch) planes[static_cast<std::size_t>(ch) * W + x] = v[ch];
        }
    });
    std::vector<double> out;
    for (int k = 1; k < std::min(acc.levels(), 9); ++k) {
        const std::vector<float>& t = acc.level(k);
        const std::size_t n = t.size() / 6;
        double sum = 0;
        for (std::size_t p = 0; p < n; ++p) {
            const float* q = t.data() + 6 * p;
            sum += ciede2000_linear_rgb({q[0], q[1], q[2]}, {q[3], q[4], q[5]});
        }
        out.push_back(n > 0 ? sum / static_cast<double>(n) : 0.0);
    }
    return out;
}

struct CheckedSelection {
    BreakpointSelection selection;
    double filtered_de = 0;  // the largest of filtered_fit_errors over the maps
};

double worst_filtered(const SegmentPyramidBakeOptions& options, const BreakpointSelection& sel,
                      const DriverImage& driver)
{
    double worst = 0;
    for (const ColorMap* map : options.maps)
        for (double e : filtered_fit_errors(*map, sel.breakpoints, sel.weights(), driver, options.threads))
            worst = std::max(worst, e);
    return worst;
}

// The breakpoints for the tolerance, measured: chosen for the mean over
// level 0, then checked at every level 1 .. 8 (box means of C0 and of its
// interpolant), and chosen again for a smaller level-0 mean while a level
// is over (CIEDE2000 is not linear: a level's mean colour can be further from
// the reference than its texels on average).
Expected<CheckedSelection> select_within(const SegmentPyramidBakeOptions& options, const DriverImage& driver)
{
    BreakpointSelectionOptions so;
    so.maps = options.maps;
    so.lo = driver.min;
    so.hi = driver.max;
    so.driver = &driver.values;
    so.tolerance_de = options.tolerance_de;
    so.fit_colors = true;
    const int limit = options.max_channels > 0 ? std::min(options.max_channels, kSegmentPyramidMaxChannels)
                                               : kSegmentPyramidMaxChannels;
    so.max_breakpoints = static_cast<std::size_t>(limit) + 1;
    auto sel = select_breakpoints(so);
    if (!sel) return sel.error();
    CheckedSelection out;
    if (options.tolerance_de > 0) {
        out.filtered_de = worst_filtered(options, *sel, driver);
        for (int round = 0; round < 12 && out.filtered_de > options.tolerance_de; ++round) {
            const double worst = std::max({out.filtered_de, sel->max_mean_de, 1e-300});
            so.tolerance_de *= std::min(0.8, options.tolerance_de / worst);
            auto again = select_breakpoints(so);
            if (!again) return again.error();
            const bool capped = again->breakpoints.size() >= so.max_breakpoints;
            sel = std::move(again);
            out.filtered_de = worst_filtered(options, *sel, driver);
            if (capped) break;
        }
    }
    // Within the limit only by going past the tolerance: refused, naming what
    // the limit reaches (the closest).
    const double reached = std::max(sel->max_mean_de, out.filtered_de);
    const bool met = options.tolerance_de > 0 ? reached <= options.tolerance_de
                                              : sel->breakpoints.size() == sel->candidates || sel->candidates < 2;
    if (met) {
        out.selection = std::move(*sel);
        return out;
    }
    return bad_input("the maps need more than " + std::to_string(limit) + " channels over the driver range [" +
                         short_number(driver.min) + ", " + short_number(driver.max) + "] at " +
                         (options.tolerance_de > 0
                              ? "tolerance " + short_number(options.tolerance_de)
                              : "every exact breakpoint (" + std::to_string(sel->candidates) + " breakpoints)") +
                         ", and SegmentPyramidBakeOptions::max_channels allows " + std::to_string(limit) +
                         "; the closest within " + std::to_string(limit) + " channels reaches a mean CIEDE2000 of " +
                         short_number(reached) + " (SegmentPyramidBakeOptions::tolerance_de " + short_number(reached) +
                         " or more meets it)",
                     "SegmentPyramidBakeOptions::max_channels");
}

}  // namespace

void set_segment_pyramid_metadata(OIIO::ImageSpec& spec, const SegmentPyramidInfo& info, const std::string& path)
{
    const std::string wrap = to_string(info.wrap);
    spec.attribute("wrapmodes", wrap + "," + wrap);
    spec.attribute("cmfilter:kind", kSegmentPyramidKind);
    spec.attribute("cmfilter:format_version", kSegmentPyramidFormatVersion);
    spec.attribute("cmfilter:version", version());
    spec.attribute("cmfilter:equation",
                   "channel k of level j: box mean of r_k(f) = clamp((f - t_{k-1}) / (t_k - t_{k-1}), 0, 1); mean C(f) "
                   "= c_0 + sum_k (c_k - c_{k-1}) R_k, c_k = C(t_k) for any map linear between the breakpoints t_k "
                   "(cmfilter:segment_colors interpolated), or the least-squares colours of the map over the driver "
                   "weights cmfilter:segment_weight_values and _shares (least-squares) (Heitz et al. 2013, sec. 3, "
                   "eq. 1 with a box kernel)");
    spec.attribute("cmfilter:layout", "level k is max(1, W >> k) x max(1, H >> k); texel (x, y) of level k is the "
                                      "box mean over level-0 [x W / w_k, (x+1) W / w_k) x [y H / h_k, (y+1) H / h_k)");
    spec.attribute("cmfilter:levels", info.levels);
    spec.attribute("cmfilter:wrap", wrap);
    spec.attribute("cmfilter:channel", info.channel);
    spec.attribute("cmfilter:channel_index", info.channel_index);
    spec.attribute("cmfilter:driver_min", number_text(info.driver_min));
    spec.attribute("cmfilter:driver_max", number_text(info.driver_max));
    spec.attribute("cmfilter:source", path_for_record(info.source, path));
    spec.attribute("cmfilter:source_sha256", info.source_sha256);
    spec.attribute("cmfilter:source_size", std::to_string(info.width) + "x" + std::to_string(info.height));
    spec.attribute("cmfilter:nonfinite_replaced", std::to_string(info.nonfinite_replaced));
    std::vector<std::string> t;
    for (double v : info.breakpoints) t.push_back(number_text(v));
    spec.attribute("cmfilter:breakpoints", joined(t, " "));
    spec.attribute("cmfilter:segment_tolerance", number_text(info.tolerance_de));
    spec.attribute("cmfilter:segment_fit", number_text(info.fit_de));
    spec.attribute("cmfilter:segment_mean_fit", number_text(info.mean_fit_de));
    spec.attribute("cmfilter:segment_filtered_fit", number_text(info.filtered_fit_de));
    std::vector<std::string> maps;
    for (const std::string& m : info.map_sources) maps.push_back(m.empty() ? m : path_for_record(m, path));
    spec.attribute("cmfilter:map_sources", joined(maps, ";"));
    if (!info.color_weights.empty()) {
        std::vector<std::string> v, w;
        for (double x : info.color_weights.values) v.push_back(number_text(x));
        for (double x : info.color_weights.shares) w.push_back(number_text(x));
        spec.attribute("cmfilter:segment_colors", "least-squares");
        spec.attribute("cmfilter:segment_weight_values", joined(v, " "));
        spec.attribute("cmfilter:segment_weight_shares", joined(w, " "));
    } else {
        spec.attribute("cmfilter:segment_colors", "interpolated");
    }
    if (info.method_choice) {
        MethodToleranceRecord r = *info.method_choice;
        r.table = path_for_record(r.table, path);
        set_method_tolerance_metadata(spec, r);
    }
}

Expected<SegmentPyramidInfo> get_segment_pyramid_metadata(const OIIO::ImageSpec& spec, const std::string& path)
{
    const std::string kind = spec.get_string_attribute("cmfilter:kind");
    if (kind != kSegmentPyramidKind)
        return bad_input("'" + path + "' is not a cmfilter segment pyramid (cmfilter:kind is '" + kind +
                         "', expected '" + kSegmentPyramidKind + "')");
    const int version = spec.get_int_attribute("cmfilter:format_version", 0);
    if (version != kSegmentPyramidFormatVersion && version != 1)
        return bad_input("'" + path + "' has segment pyramid format version " + std::to_string(version) +
                         ", this cmfilter reads version " + std::to_string(kSegmentPyramidFormatVersion));
    SegmentPyramidInfo info;
    info.width = spec.width;
    info.height = spec.height;
    info.levels = spec.get_int_attribute("cmfilter:levels", 0);
    info.pixel_type = spec.format == OIIO::TypeDesc::HALF ? ExrPixelType::Half : ExrPixelType::Float;
    info.channel = spec.get_string_attribute("cmfilter:channel");
    info.channel_index = spec.get_int_attribute("cmfilter:channel_index", 0);
    info.driver_min = std::strtod(spec.get_string_attribute("cmfilter:driver_min").c_str(), nullptr);
    info.driver_max = std::strtod(spec.get_string_attribute("cmfilter:driver_max").c_str(), nullptr);
    info.source = path_from_record(spec.get_string_attribute("cmfilter:source"), path);
    info.source_sha256 = spec.get_string_attribute("cmfilter:source_sha256");
    info.nonfinite_replaced =
        std::strtoull(spec.get_string_attribute("cmfilter:nonfinite_replaced").c_str(), nullptr, 10);
    std::istringstream t(spec.get_string_attribute("cmfilter:breakpoints"));
    for (double v; t >> v;) info.breakpoints.push_back(v);
    info.tolerance_de = std::strtod(spec.get_string_attribute("cmfilter:segment_tolerance").c_str(), nullptr);
    info.fit_de = std::strtod(spec.get_string_attribute("cmfilter:segment_fit").c_str(), nullptr);
    info.mean_fit_de = std::strtod(spec.get_string_attribute("cmfilter:segment_mean_fit").c_str(), nullptr);
    info.filtered_fit_de = std::strtod(spec.get_string_attribute("cmfilter:segment_filtered_fit").c_str(), nullptr);
    for (const std::string& m : split(spec.get_string_attribute("cmfilter:map_sources"), ';'))
        info.map_sources.push_back(m.empty() ? m : path_from_record(m, path));
    info.baked_by = spec.get_string_attribute("cmfilter:version");
    info.method_choice = get_method_tolerance_metadata(spec);
    if (info.method_choice) info.method_choice->table = path_from_record(info.method_choice->table, path);
    const std::string colors = spec.get_string_attribute("cmfilter:segment_colors", "interpolated");
    bool weights_ok = colors == "interpolated";
    if (colors == "least-squares") {
        std::istringstream v(spec.get_string_attribute("cmfilter:segment_weight_values"));
        std::istringstream w(spec.get_string_attribute("cmfilter:segment_weight_shares"));
        for (double x; v >> x;) info.color_weights.values.push_back(x);
        for (double x; w >> x;) info.color_weights.shares.push_back(x);
        weights_ok = !info.color_weights.empty() &&
                     info.color_weights.values.size() == info.color_weights.shares.size();
        for (std::size_t i = 0; weights_ok && i < info.color_weights.values.size(); ++i)
            weights_ok = std::isfinite(info.color_weights.values[i]) && std::isfinite(info.color_weights.shares[i]) &&
                         info.color_weights.shares[i] >= 0;
    }
    if (!weights_ok)
        return bad_input("'" + path + "' has cmfilter:segment_colors '" + colors +
                         "' without valid driver weights (expected 'interpolated', or 'least-squares' with as many "
                         "finite cmfilter:segment_weight_values as non-negative cmfilter:segment_weight_shares)");
    bool ascending = info.breakpoints.size() >= 2;
    for (std::size_t k = 0; k < info.breakpoints.size(); ++k)
        ascending = ascending && std::isfinite(info.breakpoints[k]) &&
                    (k == 0 || info.breakpoints[k] > info.breakpoints[k - 1]);
    auto wrap = parse_texture_wrap(spec.get_string_attribute("cmfilter:wrap"));
    if (!wrap || info.levels != box_level_count(info.width, info.height) || !ascending ||
        spec.nchannels != info.channels() || !std::isfinite(info.tolerance_de) || info.tolerance_de < 0)
        return bad_input("'" + path +
                         "' has inconsistent cmfilter metadata (wrap, level count, breakpoints or tolerance missing "
                         "or invalid, or not one channel per breakpoint after the first: " +
                         std::to_string(spec.nchannels) + " channels, " + std::to_string(info.breakpoints.size()) +
                         " breakpoints)");
    info.wrap = *wrap;
    return info;
}

Expected<SegmentPyramidBakeResult> bake_segment_pyramid(const SegmentPyramidBakeOptions& options)
{
    const Stopwatch t0;
    auto hashed = read_driver_and_hash(options.driver_read());
    if (!hashed) return hashed.error();
    const double read_ms = t0.elapsed_ms();
    auto result = bake_segment_pyramid(options, *hashed);
    if (result) result->read_ms = read_ms;
    return result;
}

Expected<SegmentPyramidBakeResult> bake_segment_pyramid(const SegmentPyramidBakeOptions& options,
                                                        const HashedDriver& hashed)
{
    if (auto st = check_exr_output_options(options.storage, "SegmentPyramidBakeOptions::storage"); !st)
        return st.error();
    if (options.maps.empty())
        return bad_input("SegmentPyramidBakeOptions::maps is empty (expected the colour maps whose breakpoints the "
                         "pyramid holds)",
                         "SegmentPyramidBakeOptions::maps");
    for (std::size_t m = 0; m < options.maps.size(); ++m) {
        const std::string what = "SegmentPyramidBakeOptions::maps[" + std::to_string(m) + "]";
        if (!options.maps[m]) return bad_input(what + " is missing", "SegmentPyramidBakeOptions::maps");
        if (auto st = validate(*options.maps[m], what); !st) return st.error();
    }
    if (!std::isfinite(options.tolerance_de) || options.tolerance_de < 0)
        return bad_input("SegmentPyramidBakeOptions::tolerance_de " + short_number(options.tolerance_de) +
                             " is invalid (expected a CIEDE2000 >= 0; 0: every exact breakpoint)",
                         "SegmentPyramidBakeOptions::tolerance_de");
    if (options.max_channels < 0)
        return bad_input("SegmentPyramidBakeOptions::max_channels " + std::to_string(options.max_channels) +
                             " is invalid (expected >= 1, or 0 for no limit)",
                         "SegmentPyramidBakeOptions::max_channels");
    const DriverImage& driver = hashed.image;
    const Stopwatch ts;
    auto selection = select_within(options, driver);
    if (!selection) return selection.error();
    const double select_ms = ts.elapsed_ms();
    auto out = AtomicOutput::begin(options.output_path);
    if (!out) return out.error();
    const int W = driver.width, H = driver.height;

    SegmentPyramidBakeResult result;
    result.select_ms = select_ms;
    result.selection = std::move(selection->selection);
    result.filtered_fit_de = selection->filtered_de;
    SegmentPyramidInfo& info = result.info;
    info.width = W;
    info.height = H;
    info.levels = box_level_count(W, H);
    info.pixel_type = options.storage.pixel_type;
    info.channel = driver.channel.empty() ? std::to_string(driver.channel_index) : driver.channel;
    info.channel_index = driver.channel_index;
    info.wrap = options.wrap;
    info.driver_min = driver.min;
    info.driver_max = driver.max;
    info.source = options.driver_path;
    info.source_sha256 = hashed.sha256;
    info.nonfinite_replaced = driver.nonfinite_replaced;
    info.breakpoints = result.selection.breakpoints;
    info.tolerance_de = options.tolerance_de;
    info.fit_de = result.selection.max_de;
    info.mean_fit_de = result.selection.max_mean_de;
    info.filtered_fit_de = result.filtered_fit_de;
    info.map_sources = options.map_sources;
    info.map_sources.resize(options.maps.size());
    info.color_weights = result.selection.color_weights;
    info.method_choice = options.method_choice;

    const int K = info.channels();
    BoxPyramidFileOptions file;
    file.path = out->temp_path();
    file.name = options.output_path;
    file.width = W;
    file.height = H;
    for (int k = 1; k <= K; ++k) {
        char name[16];
        std::snprintf(name, sizeof name, "s%03d", k);  // sorted as OpenEXR stores them
        file.channel_names.push_back(name);
    }
    file.storage = options.storage;
    file.threads = options.threads;
    file.set_metadata = [&](OIIO::ImageSpec& spec) { set_segment_pyramid_metadata(spec, info, options.output_path); };
    file.progress = options.progress;
    // Level 0: r_k(f) per texel; every level above is its box mean.
    const float* f = driver.values.data();
    const std::vector<double>& t = info.breakpoints;
    auto written = write_box_pyramid_file(file, [&](int y, int, double* planes) {
        const float* row = f + static_cast<std::size_t>(y) * W;
        for (int k = 1; k <= K; ++k) {
            double* plane = planes + static_cast<std::size_t>(k - 1) * W;
            const double a = t[k - 1], width = t[k] - t[k - 1];
            for (int x = 0; x < W; ++x) plane[x] = std::clamp((row[x] - a) / width, 0.0, 1.0);  // r_k(f)
        }
    });
    if (!written) return written.error();
    result.build_ms = written->build_ms;
    result.write_ms = written->write_ms;
    if (auto st = out->commit(); !st) return st.error();
    return result;
}

Expected<BreakpointFit> check_segment_pyramid_map(const SegmentPyramidInfo& info, const std::string& pyramid_path,
                                                  const ColorMap& map, const std::string& map_name)
{
    if (auto st = validate(map, map_name); !st) return st.error();
    const BreakpointFit fit = breakpoint_fit(map, info.breakpoints, info.driver_min, info.driver_max, info.weights());
    const double allowed = std::max(0.0, info.fit_de) + 1e-3;
    if (fit.max_de <= allowed) return fit;
    std::string lacks;
    if (auto own = map_breakpoints(map, info.driver_min, info.driver_max)) {
        const double eps = 1e-9 * std::max(1.0, info.driver_max - info.driver_min);
        std::vector<std::string> missing;
        std::size_t count = 0;
        for (double v : *own) {
            auto it = std::lower_bound(info.breakpoints.begin(), info.breakpoints.end(), v - eps);
            if (it != info.breakpoints.end() && *it <= v + eps) continue;
            if (++count <= 4) missing.push_back(short_number(v));
        }
        if (count > 0)
            lacks = "; it breaks at " + std::to_string(count) + " values the pyramid lacks (" + joined(missing, ", ") +
                    (count > 4 ? ", ..." : "") + ")";
    }
    return bad_input(
        "segment pyramid '" + pyramid_path + "' holds " + std::to_string(info.breakpoints.size()) +
        " breakpoints in [" + short_number(info.breakpoints.front()) + ", " + short_number(info.breakpoints.back()) +
        "], and " + map_name + " does not fit them: through them it is off by CIEDE2000 " + short_number(fit.max_de) +
        " at f = " + short_number(fit.worst_f) + " (expected at most " + short_number(allowed) +
        ", as the maps it was baked for)" + lacks + "; re-bake with bake-moments --segments naming this map's table");
}

std::optional<std::string> segment_recolour_warning(const SegmentPyramidInfo& info, const std::string& pyramid_path,
                                                    const BreakpointFit& fit, const std::string& map_name)
{
    if (!info.weights() || fit.mean_de <= info.mean_fit_de + 1e-3) return std::nullopt;
    return map_name + " fits the breakpoints of segment pyramid '" + pyramid_path +
           "' worse on average than the maps it was baked for: mean CIEDE2000 " + short_number(fit.mean_de) +
           " over the driver's values, against their " + short_number(info.mean_fit_de) + " (--tolerance " +
           short_number(info.tolerance_de) + " kept their filtered error within " + short_number(info.filtered_fit_de) +
           " at LOD 1-8); expect more here, or re-bake with bake-moments --segments naming this map's table";
}

}  // namespace cmfilter
