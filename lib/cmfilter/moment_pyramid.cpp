#include "cmfilter/moment_pyramid.h"

#include "cmfilter/atomic_output.h"
#include "cmfilter/box_pyramid.h"
#include "cmfilter/sha256.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <chrono>
#include <future>
#include <vector>

namespace cmfilter {

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

}  // namespace

int moment_level_extent(int extent, int level) { return box_level_extent(extent, level); }

int moment_level_count(int width, int height) { return box_level_count(width, height); }

Expected<MomentBakeResult> bake_moment_pyramid(const MomentBakeOptions& options)
{
    if (options.tile_size < 1)
        return bad_input("tile size " + std::to_string(options.tile_size) + " is invalid (expected >= 1)");
    auto out = AtomicOutput::begin(options.output_path);
    if (!out) return out.error();
    const auto progress = [&](double f) {
        if (options.progress) options.progress(f);
    };

    // The source hash reads the file a second time; do it beside the decode.
    auto hash = std::async(std::launch::async, sha256_file_hex, options.driver_path);
    MomentBakeResult result;
    auto t0 = Clock::now();
    DriverReadOptions read;
    read.path = options.driver_path;
    read.channel = options.channel;
    read.nonfinite = options.nonfinite;
    read.threads = options.threads;
    auto driver = read_driver(read);
    if (!driver) return driver.error();
    auto digest = hash.get();
    if (!digest) return digest.error();
    result.read_ms = ms_since(t0);

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

    OIIO::ImageSpec spec(W, H, 2, OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"m1", "m2"};
    spec.tile_width = spec.tile_height = options.tile_size;
    spec.tile_depth = 1;
    spec.attribute("compression", options.compression);
    spec.attribute("textureformat", "Plain Texture");
    spec.attribute("openexr:levelmode", 1);     // MIPMAP_LEVELS
    spec.attribute("openexr:roundingmode", 0);  // ROUND_DOWN: level k is max(1, W >> k)
    set_moment_pyramid_metadata(spec, info);
    auto writer = OIIO::ImageOutput::create(out->temp_path());
    if (!writer) return runtime_error("OpenImageIO cannot write EXR: " + OIIO::geterror());
    if (!writer->supports("mipmap") || !writer->supports("tiles"))
        return runtime_error("OpenImageIO's EXR writer cannot write tiled MIP-maps");
    const auto write_failed = [&]() {
        return io_error("cannot write '" + options.output_path + "': " + writer->geterror());
    };
    if (!writer->open(out->temp_path(), spec)) return write_failed();

    // Upper levels, accumulated while level 0 streams past.
    BoxPyramidAccumulator upper(W, H, 2, options.threads);
    const double c = info.reference;
    const int tile = options.tile_size;
    std::vector<float> tile_row(static_cast<std::size_t>(W) * tile * 2);
    const float* f = driver->values.data();

    for (int y0 = 0; y0 < H; y0 += tile) {
        const int y1 = std::min(H, y0 + tile);
        auto t_build = Clock::now();
        // Level 0 (into the tile row) and the channels f - c, (f - c)^2 of every row.
        upper.add_rows(y0, y1, [&](int y, int, double* planes) {
            const float* src = f + static_cast<std::size_t>(y) * W;
            float* dst = tile_row.data() + static_cast<std::size_t>(y - y0) * W * 2;
            double* g1 = planes;
            double* g2 = planes + W;
            for (int x = 0; x < W; ++x) {
                const double d = static_cast<double>(src[x]) - c;
                g1[x] = d;
                g2[x] = d * d;
                dst[2 * x] = static_cast<float>(d);
                dst[2 * x + 1] = static_cast<float>(d * d);
            }
        });
        result.build_ms += ms_since(t_build);
        auto t_write = Clock::now();
        if (!writer->write_tiles(0, W, y0, y1, 0, 1, OIIO::TypeDesc::FLOAT, tile_row.data()))
            return write_failed();
        result.write_ms += ms_since(t_write);
        progress(0.9 * y1 / H);
    }
    driver->values = {};  // the upper levels are complete; the driver is no longer needed

    auto t_write = Clock::now();
    for (int k = 1; k < upper.levels(); ++k) {
        OIIO::ImageSpec level = spec;
        level.width = level.full_width = upper.level_width(k);
        level.height = level.full_height = upper.level_height(k);
        const std::vector<float> texels = upper.take_level(k);
        if (!writer->open(out->temp_path(), level, OIIO::ImageOutput::AppendMIPLevel) ||
            !writer->write_image(OIIO::TypeDesc::FLOAT, texels.data()))
            return write_failed();
        progress(0.9 + 0.1 * k / (upper.levels() - 1));
    }
    if (!writer->close()) return write_failed();
    result.write_ms += ms_since(t_write);
    if (auto st = out->commit(); !st) return st.error();
    progress(1.0);
    return result;
}

}  // namespace cmfilter
