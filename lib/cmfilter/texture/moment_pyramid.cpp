// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/texture/moment_pyramid.h"

#include "cmfilter/util/atomic_output.h"
#include "cmfilter/texture/box_pyramid.h"
#include "cmfilter/texture/box_pyramid_file.h"
#include "cmfilter/util/stopwatch.h"
#include "cmfilter/util/sha256.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <future>
#include <vector>

namespace cmfilter {

int moment_level_extent(int extent, int level) { return box_level_extent(extent, level); }

int moment_level_count(int width, int height) { return box_level_count(width, height); }

namespace {

// What can be refused before the driver is read.
Status check_bake_options(const MomentBakeOptions& options)
{
    if (auto st = check_exr_output_options(options.storage, "MomentBakeOptions::storage"); !st) return st;
    if (options.order != 2 && options.order != 4)
        return bad_input("MomentBakeOptions::order is " + std::to_string(options.order) + " (expected 2 or 4)",
                         "MomentBakeOptions::order");
    return check_output_path(options.output_path, "");
}

}  // namespace

Expected<MomentBakeResult> bake_moment_pyramid(const MomentBakeOptions& options)
{
    if (auto st = check_bake_options(options); !st) return st.error();
    const Stopwatch t0;
    auto hashed = read_driver_and_hash(options.driver_read());
    if (!hashed) return hashed.error();
    const double read_ms = t0.elapsed_ms();
    auto result = bake_moment_pyramid(options, *hashed);
    if (result) result->read_ms = read_ms;
    return result;
}

Expected<MomentBakeResult> bake_moment_pyramid(const MomentBakeOptions& options, const HashedDriver& hashed)
{
    if (auto st = check_bake_options(options); !st) return st.error();
    auto out = AtomicOutput::begin(options.output_path);
    if (!out) return out.error();
    MomentBakeResult result;
    const DriverImage* driver = &hashed.image;
    const std::string* digest = &hashed.sha256;

    const int W = driver->width, H = driver->height;
    MomentPyramidInfo& info = result.info;
    info.width = W;
    info.height = H;
    info.levels = moment_level_count(W, H);
    info.reference = driver->mean;
    info.driver_min = driver->min;
    info.driver_max = driver->max;
    info.channel = driver->channel.empty() ? std::to_string(driver->channel_index) : driver->channel;
    info.channel_index = driver->channel_index;
    info.wrap = options.wrap;
    info.source = options.driver_path;
    info.source_sha256 = *digest;
    info.source_pixel_type = driver->pixel_type;
    info.nonfinite_replaced = driver->nonfinite_replaced;
    info.order = options.order;
    info.method_choice = options.method_choice;

    BoxPyramidFileOptions file;
    file.path = out->temp_path();
    file.name = options.output_path;
    file.width = W;
    file.height = H;
    file.channel_names = {"m1", "m2"};
    if (info.order == 4) file.channel_names.insert(file.channel_names.end(), {"m3", "m4"});
    file.storage = options.storage;
    file.threads = options.threads;
    file.set_metadata = [&](OIIO::ImageSpec& spec) { set_moment_pyramid_metadata(spec, info, options.output_path); };
    file.progress = options.progress;
    // Level 0's channels: (f - c)^k, k = 1 .. order, about the reference value c.
    const double c = info.reference;
    const float* f = driver->values.data();
    const int order = info.order;
    auto written = write_box_pyramid_file(file, [&](int y, int, double* planes) {
        const float* src = f + static_cast<std::size_t>(y) * W;
        for (int x = 0; x < W; ++x) {
            const double d = static_cast<double>(src[x]) - c;
            double power = d;
            for (int k = 0; k < order; ++k, power *= d) planes[static_cast<std::size_t>(k) * W + x] = power;
        }
    });
    if (!written) return written.error();
    result.build_ms = written->build_ms;
    result.write_ms = written->write_ms;
    if (auto st = out->commit(); !st) return st.error();
    return result;
}

}  // namespace cmfilter
