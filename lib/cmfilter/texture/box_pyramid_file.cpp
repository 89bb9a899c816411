// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/texture/box_pyramid_file.h"

#include "cmfilter/io/output_date.h"
#include "cmfilter/texture/box_pyramid.h"
#include "cmfilter/util/stopwatch.h"
#include "cmfilter/util/write_failure.h"

#include <algorithm>
#include <thread>

namespace cmfilter {

Expected<BoxPyramidFileTimes> write_box_pyramid_file(const BoxPyramidFileOptions& options,
                                                     const BoxPyramidRowFill& fill)
{
    const int W = options.width, H = options.height;
    const int C = static_cast<int>(options.channel_names.size());
    const auto progress = [&](double f) {
        if (options.progress) options.progress(f);
    };
    OIIO::ImageSpec spec(W, H, C, OIIO::TypeDesc::FLOAT);
    spec.channelnames = options.channel_names;
    ExrOutputOptions storage = options.storage;
    if (storage.tile_width == 0 && storage.tile_height == 0) storage.tile_width = storage.tile_height = 64;
    apply_exr_output_options(spec, storage);
    spec.attribute("textureformat", "Plain Texture");
    spec.attribute("openexr:levelmode", 1);     // MIPMAP_LEVELS
    spec.attribute("openexr:roundingmode", 0);  // ROUND_DOWN: level k is max(1, W >> k)
    if (options.set_metadata) options.set_metadata(spec);
    auto writer = OIIO::ImageOutput::create(options.path);
    if (!writer) return runtime_error("OpenImageIO cannot write EXR: " + OIIO::geterror());
    if (!writer->supports("mipmap") || !writer->supports("tiles"))
        return runtime_error("OpenImageIO's EXR writer cannot write tiled MIP-maps");
    if (auto st = set_output_date(spec, *writer); !st) return st.error();
    // OpenImageIO keeps a writer's errors per thread: a tile row written on
    // the writing thread leaves its error here.
    std::string row_error;
    const auto write_failed = [&]() -> Error {
        const std::string said = row_error.empty() ? writer->geterror() : row_error;
        return io_error("cannot write '" + options.name + "': " + write_failure_reason(options.path, said));
    };
    if (!writer->open(options.path, spec)) return write_failed();

    BoxPyramidFileTimes times;
    BoxPyramidAccumulator upper(W, H, C, options.threads);
    const int tile = storage.tile_height;  // level 0 goes out a row of tiles at a time
    const int tile_rows = std::min(tile, H);
    std::vector<float> level0[2];
    for (auto& b : level0) b.resize(static_cast<std::size_t>(W) * tile_rows * C);
    // The tile row being written, on a thread of its own that is joined
    // before the next is handed over (a join, unlike a future's wait, is a
    // synchronisation ThreadSanitizer sees). Joined on every way out.
    struct PendingRow {
        std::thread thread;
        bool ok = true;
        ~PendingRow()
        {
            if (thread.joinable()) thread.join();
        }
    } pending;
    const auto wait_pending = [&]() {
        if (!pending.thread.joinable()) return true;
        const Stopwatch t;
        pending.thread.join();
        times.write_ms += t.elapsed_ms();  // the time the build waited for the writer
        return pending.ok;
    };
    for (int y0 = 0, n = 0; y0 < H; y0 += tile, n ^= 1) {
        const int y1 = std::min(H, y0 + tile);
        float* rows = level0[n].data();
        const Stopwatch t;
        upper.add_rows(y0, y1, [&](int y, int thread, double* planes) {
            fill(y, thread, planes);
            float* dst = rows + static_cast<std::size_t>(y - y0) * W * C;
            for (int c = 0; c < C; ++c) {
                const double* src = planes + static_cast<std::size_t>(c) * W;
                for (int x = 0; x < W; ++x) dst[static_cast<std::size_t>(x) * C + c] = static_cast<float>(src[x]);
            }
        });
        times.build_ms += t.elapsed_ms();
        // Half files: a value past a half's range would be stored as an
        // infinity (upper levels are means of level 0: within its range).
        if (auto st = check_half_range(rows, static_cast<std::size_t>(y1 - y0) * W * C, storage, options.name); !st) {
            wait_pending();
            return st.error();
        }
        // The previous row must be out before this one is handed over (one
        // writer, rows in order); its buffer is the one the next row fills.
        if (!wait_pending()) return write_failed();
        pending.thread = std::thread([&writer, &row_error, &pending, W, y0, y1, rows]() {
            pending.ok = writer->write_tiles(0, W, y0, y1, 0, 1, OIIO::TypeDesc::FLOAT, rows);
            if (!pending.ok) row_error = writer->geterror();
        });
        progress(0.9 * y0 / H);
    }
    if (!wait_pending()) return write_failed();
    for (auto& b : level0) b = {};

    const Stopwatch t;
    for (int k = 1; k < upper.levels(); ++k) {
        OIIO::ImageSpec level = spec;
        level.width = level.full_width = upper.level_width(k);
        level.height = level.full_height = upper.level_height(k);
        const std::vector<float> texels = upper.take_level(k);
        // The whole level in one call: fewer waits for a call's last tiles.
        if (!writer->open(options.path, level, OIIO::ImageOutput::AppendMIPLevel) ||
            !writer->write_tiles(0, level.width, 0, level.height, 0, 1, OIIO::TypeDesc::FLOAT, texels.data()))
            return write_failed();
        progress(0.9 + 0.1 * k / (upper.levels() - 1));
    }
    if (!writer->close()) return write_failed();
    times.write_ms += t.elapsed_ms();
    progress(1.0);
    return times;
}

}  // namespace cmfilter
