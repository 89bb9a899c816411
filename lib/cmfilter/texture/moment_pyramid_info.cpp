// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/texture/moment_pyramid_info.h"

#include "cmfilter/io/recorded_path.h"
#include "cmfilter/io/metadata.h"
#include "cmfilter/util/version.h"

#include <cmath>
#include <cstdlib>

namespace cmfilter {

void set_moment_pyramid_metadata(OIIO::ImageSpec& spec, const MomentPyramidInfo& info, const std::string& path)
{
    const std::string wrap = to_string(info.wrap);
    spec.attribute("wrapmodes", wrap + "," + wrap);
    spec.attribute("cmfilter:kind", kMomentPyramidKind);
    spec.attribute("cmfilter:format_version", kMomentPyramidFormatVersion);
    spec.attribute("cmfilter:version", version());
    spec.attribute("cmfilter:equation",
                   info.order == 4 ? "per level: box means of (f - c)^k, k = 1..4; mean f = c + m1, "
                                     "sigma_f^2 = max(0, m2 - m1^2) (Heitz et al. 2013, sec. 4.2); m3, m4 give the "
                                     "two-Gaussian mixture of docs/moments-format.md"
                                   : "per level: box means of (f - c) and (f - c)^2; mean f = c + m1, "
                                     "sigma_f^2 = max(0, m2 - m1^2) (Heitz et al. 2013, sec. 4.2)");
    spec.attribute("cmfilter:moment_order", info.order);
    spec.attribute("cmfilter:layout", "level k is max(1, W >> k) x max(1, H >> k); texel (x, y) of level k is the "
                                      "box mean over level-0 [x W / w_k, (x+1) W / w_k) x [y H / h_k, (y+1) H / h_k)");
    const auto dbl = [&](const char* name, double v) { set_double_attribute(spec, name, v); };
    dbl("cmfilter:reference", info.reference);
    dbl("cmfilter:driver_min", info.driver_min);
    dbl("cmfilter:driver_max", info.driver_max);
    spec.attribute("cmfilter:levels", info.levels);
    spec.attribute("cmfilter:wrap", wrap);
    spec.attribute("cmfilter:channel", info.channel);
    spec.attribute("cmfilter:channel_index", info.channel_index);
    spec.attribute("cmfilter:source", path_for_record(info.source, path));
    spec.attribute("cmfilter:source_sha256", info.source_sha256);
    spec.attribute("cmfilter:source_size", std::to_string(info.width) + "x" + std::to_string(info.height));
    spec.attribute("cmfilter:source_pixel_type", info.source_pixel_type);
    spec.attribute("cmfilter:nonfinite_replaced", std::to_string(info.nonfinite_replaced));
    if (info.method_choice) {
        MethodToleranceRecord record = *info.method_choice;
        record.table = path_for_record(record.table, path);
        set_method_tolerance_metadata(spec, record);
    }
}

Expected<MomentPyramidInfo> get_moment_pyramid_metadata(const OIIO::ImageSpec& spec, const std::string& path)
{
    const std::string kind = spec.get_string_attribute("cmfilter:kind");
    if (kind != kMomentPyramidKind)
        return bad_input("'" + path + "' is not a cmfilter moment pyramid (cmfilter:kind is '" + kind +
                         "', expected '" + kMomentPyramidKind + "')");
    const int version = spec.get_int_attribute("cmfilter:format_version", 0);
    if (version != kMomentPyramidFormatVersion)
        return bad_input("'" + path + "' has moment pyramid format version " + std::to_string(version) +
                         ", this cmfilter reads version " + std::to_string(kMomentPyramidFormatVersion));
    const auto dbl = [&](const char* name) { return double_attribute(spec, name); };
    MomentPyramidInfo info;
    info.width = spec.width;
    info.height = spec.height;
    info.levels = spec.get_int_attribute("cmfilter:levels", 0);
    info.order = spec.get_int_attribute("cmfilter:moment_order", 2);
    info.reference = dbl("cmfilter:reference");
    info.driver_min = dbl("cmfilter:driver_min");
    info.driver_max = dbl("cmfilter:driver_max");
    info.channel = spec.get_string_attribute("cmfilter:channel");
    info.channel_index = spec.get_int_attribute("cmfilter:channel_index", 0);
    info.source = path_from_record(spec.get_string_attribute("cmfilter:source"), path);
    info.source_sha256 = spec.get_string_attribute("cmfilter:source_sha256");
    info.source_pixel_type = spec.get_string_attribute("cmfilter:source_pixel_type");
    info.nonfinite_replaced =
        std::strtoull(spec.get_string_attribute("cmfilter:nonfinite_replaced").c_str(), nullptr, 10);
    info.baked_by = spec.get_string_attribute("cmfilter:version");
    info.method_choice = get_method_tolerance_metadata(spec);
    if (info.method_choice) info.method_choice->table = path_from_record(info.method_choice->table, path);
    auto wrap = parse_texture_wrap(spec.get_string_attribute("cmfilter:wrap"));
    if (!wrap || !std::isfinite(info.reference) || info.levels < 1 || (info.order != 2 && info.order != 4) ||
        spec.nchannels != info.order)
        return bad_input("'" + path +
                         "' has inconsistent cmfilter metadata (wrap, reference "
                         "value, level count, moment order or channel count missing or invalid)");
    info.wrap = *wrap;
    return info;
}

}  // namespace cmfilter
