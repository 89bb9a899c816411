// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/texture/histogram_pyramid.h"

#include "cmfilter/util/atomic_output.h"
#include "cmfilter/texture/box_pyramid.h"
#include "cmfilter/texture/box_pyramid_file.h"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace cmfilter {

Expected<HistogramPyramidInfo> bake_histogram_pyramid(const HistogramBakeOptions& options)
{
    if (auto st = check_exr_output_options(options.storage, "HistogramBakeOptions::storage"); !st) return st.error();
    auto out = AtomicOutput::begin(options.output_path);
    if (!out) return out.error();
    auto hashed = read_driver_and_hash(options.driver_read());
    if (!hashed) return hashed.error();
    DriverImage* driver = &hashed->image;
    const std::string* digest = &hashed->sha256;

    // The distinct values v_b, ascending, and each texel's bin.
    std::vector<float> values = driver->values;
    std::sort(values.begin(), values.end());
    values.erase(std::unique(values.begin(), values.end()), values.end());
    if (values.size() > static_cast<std::size_t>(kHistogramMaxValues))
        return bad_input("driver '" + options.driver_path + "' has " + std::to_string(values.size()) +
                         " distinct values; a histogram pyramid holds at most " + std::to_string(kHistogramMaxValues) +
                         " (quantise the driver, or use the gaussian method)");
    const int W = driver->width, H = driver->height;
    const int B = static_cast<int>(values.size());
    std::vector<unsigned char> bin(driver->values.size());
    for (std::size_t i = 0; i < bin.size(); ++i)
        bin[i] = static_cast<unsigned char>(std::lower_bound(values.begin(), values.end(), driver->values[i]) -
                                            values.begin());
    driver->values = {};

    HistogramPyramidInfo info;
    info.width = W;
    info.height = H;
    info.levels = box_level_count(W, H);
    info.values.assign(values.begin(), values.end());
    info.channel = driver->channel.empty() ? std::to_string(driver->channel_index) : driver->channel;
    info.wrap = options.wrap;
    info.source = options.driver_path;
    info.source_sha256 = *digest;
    info.nonfinite_replaced = driver->nonfinite_replaced;

    BoxPyramidFileOptions file;
    file.path = out->temp_path();
    file.name = options.output_path;
    file.width = W;
    file.height = H;
    // OpenEXR stores channels sorted by name: zero-padded names keep bin order.
    for (int b = 0; b < B; ++b) {
        char name[16];
        std::snprintf(name, sizeof name, "h%03d", b);
        file.channel_names.push_back(name);
    }
    file.storage = options.storage;
    file.threads = options.threads;
    file.set_metadata = [&](OIIO::ImageSpec& spec) { set_histogram_pyramid_metadata(spec, info, options.output_path); };
    // Level 0: the indicator of each texel's value, [f == v_b]; box means of
    // it are the discretised D_f of sec. 4.1 ("exact solutions"), and the
    // filtered colour is the inner product of eq. 8 over the v_b.
    const auto written = write_box_pyramid_file(file, [&](int y, int, double* planes) {
        std::fill(planes, planes + static_cast<std::size_t>(B) * W, 0.0);
        const unsigned char* row = bin.data() + static_cast<std::size_t>(y) * W;
        for (int x = 0; x < W; ++x) planes[static_cast<std::size_t>(row[x]) * W + x] = 1.0;
    });
    if (!written) return written.error();
    if (auto st = out->commit(); !st) return st.error();
    return info;
}

}  // namespace cmfilter
