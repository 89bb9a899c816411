// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/texture/histogram_pyramid.h"

#include "cmfilter/io/recorded_path.h"
#include "cmfilter/util/version.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace cmfilter {

void set_histogram_pyramid_metadata(OIIO::ImageSpec& spec, const HistogramPyramidInfo& info, const std::string& path)
{
    const std::string wrap = to_string(info.wrap);
    spec.attribute("wrapmodes", wrap + "," + wrap);
    spec.attribute("cmfilter:kind", kHistogramPyramidKind);
    spec.attribute("cmfilter:format_version", kHistogramPyramidFormatVersion);
    spec.attribute("cmfilter:version", version());
    spec.attribute("cmfilter:equation",
                   "channel b: box mean of [f == v_b] per level; filtered colour = sum_b h_b C(v_b) "
                   "(Heitz et al. 2013, sec. 4.1)");
    spec.attribute("cmfilter:layout", "level k is max(1, W >> k) x max(1, H >> k); texel (x, y) of level k is the "
                                      "box mean over level-0 [x W / w_k, (x+1) W / w_k) x [y H / h_k, (y+1) H / h_k)");
    // The values are float32 driver values: 9 significant digits round-trip them.
    std::string values;
    char buf[32];
    for (double v : info.values) {
        std::snprintf(buf, sizeof buf, "%.9g", v);
        values += (values.empty() ? "" : " ") + std::string(buf);
    }
    spec.attribute("cmfilter:values", values);
    spec.attribute("cmfilter:bins", static_cast<int>(info.values.size()));
    spec.attribute("cmfilter:levels", info.levels);
    spec.attribute("cmfilter:wrap", wrap);
    spec.attribute("cmfilter:channel", info.channel);
    spec.attribute("cmfilter:source", path_for_record(info.source, path));
    spec.attribute("cmfilter:source_sha256", info.source_sha256);
    spec.attribute("cmfilter:source_size", std::to_string(info.width) + "x" + std::to_string(info.height));
    spec.attribute("cmfilter:nonfinite_replaced", std::to_string(info.nonfinite_replaced));
}

Expected<HistogramPyramidInfo> get_histogram_pyramid_metadata(const OIIO::ImageSpec& spec, const std::string& path)
{
    const std::string kind = spec.get_string_attribute("cmfilter:kind");
    if (kind != kHistogramPyramidKind)
        return bad_input("'" + path + "' is not a cmfilter histogram pyramid (cmfilter:kind is '" + kind +
                         "', expected '" + kHistogramPyramidKind + "')");
    const int version = spec.get_int_attribute("cmfilter:format_version", 0);
    if (version != kHistogramPyramidFormatVersion)
        return bad_input("'" + path + "' has histogram pyramid format version " + std::to_string(version) +
                         ", this cmfilter reads version " + std::to_string(kHistogramPyramidFormatVersion));
    HistogramPyramidInfo info;
    info.width = spec.width;
    info.height = spec.height;
    info.levels = spec.get_int_attribute("cmfilter:levels", 0);
    std::istringstream values(spec.get_string_attribute("cmfilter:values"));
    for (double v; values >> v;) info.values.push_back(v);
    info.channel = spec.get_string_attribute("cmfilter:channel");
    info.source = path_from_record(spec.get_string_attribute("cmfilter:source"), path);
    info.source_sha256 = spec.get_string_attribute("cmfilter:source_sha256");
    info.nonfinite_replaced =
        std::strtoull(spec.get_string_attribute("cmfilter:nonfinite_replaced").c_str(), nullptr, 10);
    info.baked_by = spec.get_string_attribute("cmfilter:version");
    auto wrap = parse_texture_wrap(spec.get_string_attribute("cmfilter:wrap"));
    const int bins = static_cast<int>(info.values.size());
    bool finite = true;
    for (double v : info.values) finite = finite && std::isfinite(v);
    if (!wrap || info.levels < 1 || bins < 1 || bins > kHistogramMaxValues || !finite ||
        bins != spec.get_int_attribute("cmfilter:bins", -1) || spec.nchannels != bins)
        return bad_input("'" + path +
                         "' has inconsistent cmfilter metadata (wrap, level count, "
                         "values or channel count missing or invalid)");
    info.wrap = *wrap;
    return info;
}

}  // namespace cmfilter
