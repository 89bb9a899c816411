// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/io/driver_image.h"

#include "cmfilter/util/sha256.h"

#include "cmfilter/io/image_reading.h"
#include "cmfilter/util/parallel_for.h"

#include <algorithm>
#include <optional>
#include <thread>
#include <cmath>
#include <limits>
#include <sstream>

namespace cmfilter {

namespace {

std::string channel_list(const OIIO::ImageSpec& spec)
{
    std::string names;
    for (int c = 0; c < spec.nchannels; ++c) {
        if (c) names += ", ";
        names += c < static_cast<int>(spec.channelnames.size()) ? spec.channelnames[c] : std::to_string(c);
    }
    return names;
}

// The channel `wanted` names (a name, else a 0-based index) in spec.
Expected<int> select_channel(const std::string& path, const OIIO::ImageSpec& spec, const std::string& wanted)
{
    const std::string channels = "(channels: " + channel_list(spec) + ")";
    if (wanted.empty()) {
        if (spec.nchannels == 1) return 0;
        return bad_input("'" + path + "' has " + std::to_string(spec.nchannels) + " channels " + channels +
                             "; a driver is one channel: choose it with DriverReadOptions::channel NAME or INDEX",
                         "DriverReadOptions::channel");
    }
    for (int c = 0; c < static_cast<int>(spec.channelnames.size()); ++c)
        if (spec.channelnames[c] == wanted) return c;
    if (std::all_of(wanted.begin(), wanted.end(), [](unsigned char ch) { return std::isdigit(ch); })) {
        const long index = wanted.size() > 9 ? -1 : std::stol(wanted);
        if (index >= 0 && index < spec.nchannels) return static_cast<int>(index);
        return bad_input("channel index " + wanted + " is outside '" + path + "' (expected 0.." +
                         std::to_string(spec.nchannels - 1) + ") " + channels);
    }
    return bad_input("'" + path + "' has no channel '" + wanted + "' " + channels);
}

struct RowScan {
    std::size_t nonfinite = 0;
    long first_bad = -1;  // index within the row
    float first_bad_value = 0;
    double sum = 0;
    double min = std::numeric_limits<double>::infinity();
    double max = -std::numeric_limits<double>::infinity();
};

}  // namespace

const char* to_string(NonFinitePolicy policy) { return policy == NonFinitePolicy::Zero ? "zero" : "error"; }

Expected<NonFinitePolicy> parse_non_finite_policy(const std::string& name)
{
    if (name == "error") return NonFinitePolicy::Error;
    if (name == "zero") return NonFinitePolicy::Zero;
    return bad_input("unknown non-finite policy '" + name + "' (expected error or zero)");
}

Expected<DriverImage> read_driver(const DriverReadOptions& options)
{
    const std::string& path = options.path;
    // Drivers are data: keep alpha-bearing files (PNG, TIFF) unpremultiplied.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto opened = open_image_input(path, &config);
    if (!opened) return opened.error();
    auto& in = *opened;
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.deep || spec.depth > 1)
        return bad_input("'" + path + "' is a " + std::string(spec.deep ? "deep" : "volume") +
                         " image; a driver is a flat 2-D image");
    auto channel = select_channel(path, spec, options.channel);
    if (!channel) return channel.error();

    DriverImage d;
    d.width = spec.width;
    d.height = spec.height;
    d.channel_index = *channel;
    if (*channel < static_cast<int>(spec.channelnames.size())) d.channel = spec.channelnames[*channel];
    d.pixel_type = spec.format.c_str();
    if (auto fits = check_image_allocation(spec, path, 1); !fits) return fits.error();
    d.values.resize(static_cast<std::size_t>(d.width) * d.height);
    if (!read_float_pixels(*in, 0, 0, *channel, *channel + 1, d.values.data()))
        return io_error("cannot read the pixels of '" + path + "': " + in->geterror());
    in.reset();

    // One pass: non-finite texels, sum, min and max, per row in parallel.
    std::vector<RowScan> rows(d.height);
    const bool replace = options.nonfinite == NonFinitePolicy::Zero;
    parallel_for(d.height, options.threads, [&](int y) {
        RowScan& r = rows[y];
        float* row = d.values.data() + static_cast<std::size_t>(y) * d.width;
        for (int x = 0; x < d.width; ++x) {
            if (!std::isfinite(row[x])) {
                if (r.first_bad < 0) r.first_bad = x, r.first_bad_value = row[x];
                ++r.nonfinite;
                if (!replace) continue;
                row[x] = 0.0f;
            }
            const double v = row[x];
            r.sum += v;
            r.min = std::min(r.min, v);
            r.max = std::max(r.max, v);
        }
    });
    RowScan total;
    std::size_t first_bad_row = 0;
    for (int y = 0; y < d.height; ++y) {
        const RowScan& r = rows[y];
        if (r.first_bad >= 0 && total.first_bad < 0)
            total.first_bad = r.first_bad, total.first_bad_value = r.first_bad_value, first_bad_row = y;
        total.nonfinite += r.nonfinite;
        total.sum += r.sum;
        total.min = std::min(total.min, r.min);
        total.max = std::max(total.max, r.max);
    }
    if (total.nonfinite > 0 && !replace) {
        std::ostringstream msg;
        msg << "'" << path << "' has " << total.nonfinite << " non-finite texel" << (total.nonfinite == 1 ? "" : "s")
            << " (first at (" << total.first_bad << ", " << first_bad_row << "): " << total.first_bad_value
            << "); expected finite values (DriverReadOptions::nonfinite zero replaces them with 0)";
        return bad_input(msg.str(), "DriverReadOptions::nonfinite");
    }
    d.nonfinite_replaced = total.nonfinite;
    d.mean = total.sum / static_cast<double>(d.values.size());
    d.min = total.min;
    d.max = total.max;
    return d;
}

Expected<HashedDriver> read_driver_and_hash(const DriverReadOptions& options)
{
    // The hash reads the file a second time; do it beside the decode, on a
    // thread joined before the digest is read (a synchronisation
    // ThreadSanitizer sees, as a future's wait is not).
    std::optional<Expected<std::string>> digest;
    std::thread hash([&]() { digest.emplace(sha256_file_hex(options.path)); });
    auto driver = read_driver(options);
    hash.join();
    if (!driver) return driver.error();
    if (!*digest) return digest->error();
    return HashedDriver{std::move(*driver), std::move(**digest)};
}

}  // namespace cmfilter
