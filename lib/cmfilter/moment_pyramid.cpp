#include "cmfilter/moment_pyramid.h"

#include "cmfilter/atomic_output.h"
#include "cmfilter/parallel_for.h"
#include "cmfilter/sha256.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <future>
#include <vector>

namespace cmfilter {

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// Horizontal box integrals of one level-0 row g (piecewise constant, texel i
// spanning [i, i+1)) for a level w texels wide: out[x] is the integral of g
// over [x W / w, (x+1) W / w). prefix[i] = g[0] + ... + g[i-1], i = 0..W.
// Boundaries are kept as exact rationals num / w.
void box_integrals(const double* prefix, const double* g, int W, int w, double* out)
{
    const auto integral_to = [&](std::int64_t num) {
        const std::int64_t i = num / w;
        if (i >= W) return prefix[W];
        return prefix[i] + g[i] * static_cast<double>(num % w) / w;
    };
    double prev = 0;
    for (int x = 0; x < w; ++x) {
        const double next = integral_to(static_cast<std::int64_t>(x + 1) * W);
        out[x] = next - prev;
        prev = next;
    }
}

// One upper level being accumulated from level-0 rows in order. Level-0 row r
// spans [r, r+1), output row y spans [y H / h, (y+1) H / h); in units of 1/h
// these are [r h, (r+1) h) and [y H, (y+1) H), so overlaps are exact integers.
// Since h <= H a level-0 row touches at most two output rows.
struct UpperLevel {
    int w = 0, h = 0;
    std::vector<float> texels;   // w * h * 2: (m1, m2) per texel, top row first
    std::vector<double> acc1, acc2;
    int y = 0;                   // output row being accumulated

    void add_row(int r, int H, double inv_area, const double* h1, const double* h2)
    {
        std::int64_t lo = static_cast<std::int64_t>(r) * h;
        const std::int64_t hi = lo + h;
        while (lo < hi) {
            const std::int64_t end = static_cast<std::int64_t>(y + 1) * H;
            const std::int64_t seg = std::min(hi, end);
            const double weight = static_cast<double>(seg - lo) / h;  // in level-0 rows
            for (int x = 0; x < w; ++x) {
                acc1[x] += weight * h1[x];
                acc2[x] += weight * h2[x];
            }
            lo = seg;
            if (seg == end) {  // output row y is complete: divide by its area
                float* out = texels.data() + static_cast<std::size_t>(y) * w * 2;
                for (int x = 0; x < w; ++x) {
                    out[2 * x] = static_cast<float>(acc1[x] * inv_area);
                    out[2 * x + 1] = static_cast<float>(acc2[x] * inv_area);
                }
                std::fill(acc1.begin(), acc1.end(), 0.0);
                std::fill(acc2.begin(), acc2.end(), 0.0);
                ++y;
            }
        }
    }
};

}  // namespace

int moment_level_extent(int extent, int level)
{
    return level >= 31 ? 1 : std::max(1, extent >> level);
}

int moment_level_count(int width, int height)
{
    int levels = 1;
    for (int e = std::max(width, height); e > 1; e >>= 1) ++levels;
    return levels;
}

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
    std::vector<UpperLevel> upper(info.levels - 1);
    std::vector<std::size_t> offset(upper.size() + 1, 0);  // of each level in a row's scratch
    for (std::size_t k = 0; k < upper.size(); ++k) {
        UpperLevel& L = upper[k];
        L.w = moment_level_extent(W, static_cast<int>(k) + 1);
        L.h = moment_level_extent(H, static_cast<int>(k) + 1);
        L.texels.assign(static_cast<std::size_t>(L.w) * L.h * 2, 0.0f);
        L.acc1.assign(L.w, 0.0);
        L.acc2.assign(L.w, 0.0);
        offset[k + 1] = offset[k] + 2 * static_cast<std::size_t>(L.w);
    }
    const std::size_t row_scratch = offset.back();

    const double c = info.reference;
    const int tile = options.tile_size;
    // Level 0 goes out one tile row per write_tiles call, encoded on a writer
    // thread (OpenEXR compresses a call's tiles on its own thread pool) while
    // this thread computes the next row; two row buffers alternate. Batches of
    // several tile rows measured slower (more memory traffic), not faster.
    const int tile_rows = std::min(tile, H);
    std::vector<float> level0[2];
    for (auto& b : level0) b.resize(static_cast<std::size_t>(W) * tile_rows * 2);
    std::vector<double> scratch(row_scratch * tile_rows);
    const int threads = resolve_thread_count(options.threads);
    std::vector<std::vector<double>> work(threads, std::vector<double>(4 * static_cast<std::size_t>(W) + 2));
    const float* f = driver->values.data();
    std::future<bool> pending;  // the tile row being written
    const auto wait_pending = [&]() {
        if (!pending.valid()) return true;
        auto t_write = Clock::now();
        const bool ok = pending.get();
        result.write_ms += ms_since(t_write);  // time the build waited for the writer
        return ok;
    };

    for (int y0 = 0, n = 0; y0 < H; y0 += tile, n ^= 1) {
        const int y1 = std::min(H, y0 + tile);
        float* out0 = level0[n].data();
        auto t_build = Clock::now();
        // Level 0 and the horizontal box integrals of every row (parallel over rows).
        const int rows = y1 - y0;
        parallel_for(std::min(threads, rows), threads, [&](int t) {
            for (int i = t; i < rows; i += threads) {
                std::vector<double>& buf = work[t];
                double* g1 = buf.data();
                double* g2 = g1 + W;
                double* p1 = g2 + W;
                double* p2 = p1 + W + 1;
                const float* src = f + static_cast<std::size_t>(y0 + i) * W;
                float* dst = out0 + static_cast<std::size_t>(i) * W * 2;
                p1[0] = p2[0] = 0;
                for (int x = 0; x < W; ++x) {
                    const double d = static_cast<double>(src[x]) - c;
                    g1[x] = d;
                    g2[x] = d * d;
                    dst[2 * x] = static_cast<float>(d);
                    dst[2 * x + 1] = static_cast<float>(d * d);
                    p1[x + 1] = p1[x] + d;
                    p2[x + 1] = p2[x] + d * d;
                }
                double* row = scratch.data() + static_cast<std::size_t>(i) * row_scratch;
                for (std::size_t k = 0; k < upper.size(); ++k) {
                    box_integrals(p1, g1, W, upper[k].w, row + offset[k]);
                    box_integrals(p2, g2, W, upper[k].w, row + offset[k] + upper[k].w);
                }
            }
        });
        // Vertical accumulation, rows in order within each level (parallel over levels).
        parallel_for(static_cast<int>(upper.size()), threads, [&](int k) {
            UpperLevel& L = upper[k];
            const double inv_area = static_cast<double>(L.w) * L.h / (static_cast<double>(W) * H);
            for (int r = y0; r < y1; ++r) {
                const double* row = scratch.data() + static_cast<std::size_t>(r - y0) * row_scratch + offset[k];
                L.add_row(r, H, inv_area, row, row + L.w);
            }
        });
        result.build_ms += ms_since(t_build);
        // The previous row must be out before this one is handed over (one
        // writer, rows in order); its buffer is the one the next row fills.
        if (!wait_pending()) return write_failed();
        pending = std::async(std::launch::async, [&writer, W, y0, y1, out0]() {
            return writer->write_tiles(0, W, y0, y1, 0, 1, OIIO::TypeDesc::FLOAT, out0);
        });
        progress(0.9 * y0 / H);
    }
    if (!wait_pending()) return write_failed();
    driver->values = {};  // the upper levels are complete; the driver is no longer needed
    for (auto& b : level0) b = {};
    scratch = {};

    auto t_write = Clock::now();
    for (std::size_t k = 0; k < upper.size(); ++k) {
        UpperLevel& L = upper[k];
        OIIO::ImageSpec level = spec;
        level.width = level.full_width = L.w;
        level.height = level.full_height = L.h;
        // The whole level in one call: fewer waits for a call's last tiles.
        if (!writer->open(out->temp_path(), level, OIIO::ImageOutput::AppendMIPLevel) ||
            !writer->write_tiles(0, L.w, 0, L.h, 0, 1, OIIO::TypeDesc::FLOAT, L.texels.data()))
            return write_failed();
        L.texels = {};
        progress(0.9 + 0.1 * (k + 1) / upper.size());
    }
    if (!writer->close()) return write_failed();
    result.write_ms += ms_since(t_write);
    if (auto st = out->commit(); !st) return st.error();
    progress(1.0);
    return result;
}

}  // namespace cmfilter
