// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/texture/color_pyramid_file.h"

#include "cmfilter/colormap/color_map_digest.h"
#include "cmfilter/io/linear_space_attributes.h"
#include "cmfilter/io/recorded_path.h"
#include "cmfilter/texture/box_pyramid.h"
#include "cmfilter/texture/box_pyramid_file.h"
#include "cmfilter/util/atomic_output.h"
#include "cmfilter/util/stopwatch.h"
#include "cmfilter/util/version.h"

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

}  // namespace

void set_color_pyramid_metadata(OIIO::ImageSpec& spec, const ColorPyramidInfo& info, const std::string& path)
{
    const std::string wrap = to_string(info.wrap);
    spec.attribute("wrapmodes", wrap + "," + wrap);
    spec.attribute("cmfilter:kind", kColorPyramidKind);
    spec.attribute("cmfilter:format_version", kColorPyramidFormatVersion);
    spec.attribute("cmfilter:version", version());
    spec.attribute("cmfilter:equation", "level k: box mean of C0(f) over each texel's footprint (Heitz et al. 2013, "
                                        "sec. 3, eq. 1 with a box kernel)");
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
    spec.attribute("cmfilter:map_sha256", info.map_sha256);
    spec.attribute("cmfilter:map_source", info.map_source.empty() ? "" : path_for_record(info.map_source, path));
    spec.attribute("cmfilter:map_domain", number_text(info.map_vmin) + " " + number_text(info.map_vmax));
    if (info.method_choice) {
        MethodToleranceRecord r = *info.method_choice;
        r.table = path_for_record(r.table, path);
        set_method_tolerance_metadata(spec, r);
    }
}

Expected<ColorPyramidInfo> get_color_pyramid_metadata(const OIIO::ImageSpec& spec, const std::string& path)
{
    const std::string kind = spec.get_string_attribute("cmfilter:kind");
    if (kind != kColorPyramidKind)
        return bad_input("'" + path + "' is not a cmfilter colour pyramid (cmfilter:kind is '" + kind +
                         "', expected '" + kColorPyramidKind + "')");
    const int version = spec.get_int_attribute("cmfilter:format_version", 0);
    if (version != kColorPyramidFormatVersion)
        return bad_input("'" + path + "' has colour pyramid format version " + std::to_string(version) +
                         ", this cmfilter reads version " + std::to_string(kColorPyramidFormatVersion));
    ColorPyramidInfo info;
    info.width = spec.width;
    info.height = spec.height;
    info.levels = spec.get_int_attribute("cmfilter:levels", 0);
    info.pixel_type = spec.format == OIIO::TypeDesc::HALF ? ExrPixelType::Half : ExrPixelType::Float;
    info.linear_space = spec.get_string_attribute("cmfilter:linear_space");
    info.channel = spec.get_string_attribute("cmfilter:channel");
    info.channel_index = spec.get_int_attribute("cmfilter:channel_index", 0);
    info.driver_min = std::strtod(spec.get_string_attribute("cmfilter:driver_min").c_str(), nullptr);
    info.driver_max = std::strtod(spec.get_string_attribute("cmfilter:driver_max").c_str(), nullptr);
    info.source = path_from_record(spec.get_string_attribute("cmfilter:source"), path);
    info.source_sha256 = spec.get_string_attribute("cmfilter:source_sha256");
    info.nonfinite_replaced =
        std::strtoull(spec.get_string_attribute("cmfilter:nonfinite_replaced").c_str(), nullptr, 10);
    info.map_sha256 = spec.get_string_attribute("cmfilter:map_sha256");
    const std::string map_source = spec.get_string_attribute("cmfilter:map_source");
    info.map_source = map_source.empty() ? "" : path_from_record(map_source, path);
    std::istringstream domain(spec.get_string_attribute("cmfilter:map_domain"));
    const bool has_domain = static_cast<bool>(domain >> info.map_vmin >> info.map_vmax);
    info.baked_by = spec.get_string_attribute("cmfilter:version");
    info.method_choice = get_method_tolerance_metadata(spec);
    if (info.method_choice) info.method_choice->table = path_from_record(info.method_choice->table, path);
    auto wrap = parse_texture_wrap(spec.get_string_attribute("cmfilter:wrap"));
    if (!wrap || info.levels != box_level_count(info.width, info.height) || spec.nchannels != 3 ||
        info.map_sha256.size() != 64 || !has_domain)
        return bad_input("'" + path +
                         "' has inconsistent cmfilter metadata (wrap, level count, map digest or domain missing or "
                         "invalid, or not 3 channels)");
    info.wrap = *wrap;
    return info;
}

Expected<ColorPyramidBakeResult> bake_color_pyramid(const ColorPyramidBakeOptions& options)
{
    const Stopwatch t0;
    auto hashed = read_driver_and_hash(options.driver_read());
    if (!hashed) return hashed.error();
    const double read_ms = t0.elapsed_ms();
    auto result = bake_color_pyramid(options, *hashed);
    if (result) result->read_ms = read_ms;
    return result;
}

Expected<ColorPyramidBakeResult> bake_color_pyramid(const ColorPyramidBakeOptions& options, const HashedDriver& hashed)
{
    if (auto st = check_exr_output_options(options.storage, "ColorPyramidBakeOptions::storage"); !st) return st.error();
    if (!options.map)
        return bad_input("ColorPyramidBakeOptions::map is missing (expected the colour map C0 the pyramid bakes in)",
                         "ColorPyramidBakeOptions::map");
    if (auto st = validate(*options.map, "ColorPyramidBakeOptions::map"); !st) return st.error();
    auto out = AtomicOutput::begin(options.output_path);
    if (!out) return out.error();
    const DriverImage& driver = hashed.image;
    const ColorMap& map = *options.map;
    const int W = driver.width, H = driver.height;

    ColorPyramidBakeResult result;
    ColorPyramidInfo& info = result.info;
    info.width = W;
    info.height = H;
    info.levels = box_level_count(W, H);
    info.pixel_type = options.storage.pixel_type;
    info.linear_space = options.linear_space;
    info.channel = driver.channel.empty() ? std::to_string(driver.channel_index) : driver.channel;
    info.channel_index = driver.channel_index;
    info.wrap = options.wrap;
    info.driver_min = driver.min;
    info.driver_max = driver.max;
    info.source = options.driver_path;
    info.source_sha256 = hashed.sha256;
    info.nonfinite_replaced = driver.nonfinite_replaced;
    info.map_sha256 = color_map_sha256(map);
    info.map_source = options.map_source;
    info.map_vmin = map.vmin;
    info.map_vmax = map.vmax;
    info.method_choice = options.method_choice;

    BoxPyramidFileOptions file;
    file.path = out->temp_path();
    file.name = options.output_path;
    file.width = W;
    file.height = H;
    file.channel_names = {"R", "G", "B"};
    file.storage = options.storage;
    file.threads = options.threads;
    file.set_metadata = [&](OIIO::ImageSpec& spec) {
        set_color_pyramid_metadata(spec, info, options.output_path);
        set_linear_space_attributes(spec, options.linear_space, options.linear_interop_id);
    };
    file.progress = options.progress;
    // Level 0: C0(f) per texel, in double; every level above is its box mean.
    const float* f = driver.values.data();
    auto written = write_box_pyramid_file(file, [&](int y, int, double* planes) {
        const float* row = f + static_cast<std::size_t>(y) * W;
        for (int x = 0; x < W; ++x) {
            const Rgb c = map.evaluate(row[x]);
            planes[x] = c.r;
            planes[static_cast<std::size_t>(W) + x] = c.g;
            planes[2 * static_cast<std::size_t>(W) + x] = c.b;
        }
    });
    if (!written) return written.error();
    result.build_ms = written->build_ms;
    result.write_ms = written->write_ms;
    if (auto st = out->commit(); !st) return st.error();
    return result;
}

Status check_color_pyramid_map(const ColorPyramidInfo& info, const std::string& pyramid_path, const ColorMap& map,
                               const std::string& map_name)
{
    const std::string digest = color_map_sha256(map);
    if (digest == info.map_sha256) return ok();
    std::string how;
    if (map.vmin != info.map_vmin || map.vmax != info.map_vmax)
        how = "its domain [" + number_text(map.vmin) + ", " + number_text(map.vmax) + "] is not the pyramid's [" +
              number_text(info.map_vmin) + ", " + number_text(info.map_vmax) + "]";
    else how = "its colours or wrap differ";
    return bad_input("colour pyramid '" + pyramid_path + "' was baked through another colour map" +
                     (info.map_source.empty() ? std::string() : " ('" + info.map_source + "')") + " than " + map_name +
                     ": " + how + " (map digest " + digest.substr(0, 12) + ", the pyramid's " +
                     info.map_sha256.substr(0, 12) +
                     "); re-bake it with bake-moments --method color-pyramid, or bake moments for a map that changes "
                     "(gaussian, mixture)");
}

}  // namespace cmfilter
