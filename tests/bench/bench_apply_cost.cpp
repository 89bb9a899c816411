// SPDX-License-Identifier: Apache-2.0
// Per-pixel cost of the paper's filtered lookup against naive filtering, on
// in-memory data, timed in the same process:
//   naive     bilinear fetch of the mean texture (one channel), then C0(mean)
//   gaussian  bilinear fetch of the moments (m1, m2), sigma = sqrt(max(0,
//             m2 - m1^2)), then T(mean, sigma) from the baked table (eq. 10)
// Each renderer stores what its method needs: naive a mean MIP level, the
// paper's method a moment level. Both fetch at the same points of a smooth
// 1024 x 1024 level, in scanline order with a random offset inside each texel
// (as a renderer or `apply` visits them), so the ratio measures what the
// method adds per pixel.
//
// A second table times the whole per-pixel path of `cmfilter apply`, where
// both methods read the same moment pyramid through MomentTexture
// (OpenImageIO's TextureSystem, file cached in memory after a warm-up run):
//   naive     MomentTexture::lookup, then C0(mean)
//   gaussian  MomentTexture::lookup, then T(mean, sigma)
// and a third the baked colour pyramid of the same driver through each map
// (bake-moments --method color-pyramid) against that gaussian path:
//   color-pyramid  ColorPyramidTexture::lookup: the colour itself
// and a fourth the segment pyramid of the same driver for each map's
// breakpoints (bake-moments --segments T.exr --tolerance 0.5, and exact)
// against the same gaussian path:
//   segments  SegmentPyramidTexture::lookup (K channels), then ramp_color,
//             with the file read through TextureSystem and read into memory
//
//   cmfilter-bench-apply-cost LUTS_DIR
#include "cmfilter/colormap/color_map_loading.h"
#include "cmfilter/tables/gaussian_color_table.h"
#include "cmfilter/texture/color_pyramid_file.h"
#include "cmfilter/texture/color_pyramid_texture.h"
#include "cmfilter/texture/segment_pyramid_file.h"
#include "cmfilter/texture/segment_pyramid_texture.h"
#include "cmfilter/texture/moment_pyramid.h"
#include "cmfilter/texture/moment_texture.h"

#include <OpenImageIO/imageio.h>

#include <filesystem>

#include "bench_timing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <vector>

using namespace cmfilter;
using namespace cmfilter_bench;

namespace {

const char* kMaps[] = {"terrain", "stripes", "step", "narrow-band", "hue-ramp"};
constexpr int kSize = 1024;       // level width and height
constexpr int kPixels = 1 << 22;  // lookups per run
constexpr int kRuns = 7;

// Bilinear fetch of C interleaved float channels at (s, t) in texel units, clamped.
template <int C>
void fetch(const std::vector<float>& level, float s, float t, float* out)
{
    const float x = std::clamp(s - 0.5f, 0.0f, kSize - 1.0f), y = std::clamp(t - 0.5f, 0.0f, kSize - 1.0f);
    const int x0 = std::min(static_cast<int>(x), kSize - 2), y0 = std::min(static_cast<int>(y), kSize - 2);
    const float fx = x - x0, fy = y - y0;
    const float* p = level.data() + (static_cast<std::size_t>(y0) * kSize + x0) * C;
    const float* q = p + static_cast<std::size_t>(kSize) * C;
    for (int c = 0; c < C; ++c) {
        const float a = p[c] + fx * (p[C + c] - p[c]);
        const float b = q[c] + fx * (q[C + c] - q[c]);
        out[c] = a + fy * (b - a);
    }
}

// The baked colour pyramid of the driver at driver_path through each map,
// against gaussian through the moments, both through TextureSystem.
int through_color_pyramid(const std::string& luts, const ColorConfig& config, const MomentTexture& moments,
                          const std::string& driver_path, const std::string& dir)
{
    constexpr int kLookups = 1 << 20;
    std::cout << "\nColour pyramid against gaussian, both through TextureSystem (bilinear, LOD 0), " << kLookups
              << " lookups per run in scanline order; fastest of " << kRuns << " alternating runs each.\n\n"
              << "| map | gaussian ns/pixel | color-pyramid ns/pixel | color-pyramid / gaussian |\n"
                 "|---|---:|---:|---:|\n";
    for (const char* name : kMaps) {
        ColorMapLoadOptions opt;
        opt.path = luts + "/" + name + ".png";
        auto map = load_color_map(opt, config);
        if (!map) return 1;
        auto table = GaussianColorTable::bake(map->map, {});
        if (!table) return 1;
        ColorPyramidBakeOptions bake;
        bake.driver_path = driver_path;
        bake.output_path = dir + "/" + name + "-colors.exr";
        bake.map = &map->map;
        if (auto baked = bake_color_pyramid(bake); !baked) {
            std::cerr << baked.error().message << "\n";
            return 1;
        }
        auto colors = ColorPyramidTexture::open(bake.output_path);
        if (!colors) return 1;
        const auto coordinate = [](int i, int axis) {
            const int texel = i % (kSize * kSize);
            return (static_cast<float>(axis == 0 ? texel % kSize : texel / kSize) + 0.5f) / kSize;
        };
        double sink = 0;
        LookupCounters counters;
        const auto [gaussian, pyramid] = fastest_pair_ms(
            kRuns,
            [&] {
            double acc = 0;
            for (int i = 0; i < kLookups; ++i) {
                const MomentSample m = moments.lookup(coordinate(i, 0), coordinate(i, 1), 0.0f);
                acc += table->lookup(m.mean, m.sigma, &counters).g;
            }
            sink += acc;
            },
            [&] {
            double acc = 0;
            for (int i = 0; i < kLookups; ++i) acc += colors->lookup(coordinate(i, 0), coordinate(i, 1), 0.0f).color.g;
            sink += acc;
        });
        char row[200];
        std::snprintf(row, sizeof row, "| %s | %.1f | %.1f | %.2f |\n", name, gaussian * 1e6 / kLookups,
                      pyramid * 1e6 / kLookups, pyramid / gaussian);
        std::cout << row;
        if (sink == 42.0) std::cout << "";
    }
    return 0;
}

// The segment pyramid of the driver at driver_path for each map's
// breakpoints (tolerance 0.5, then every exact breakpoint), against gaussian
// through the moments, both through TextureSystem.
int through_segments(const std::string& luts, const ColorConfig& config, const MomentTexture& moments,
                     const std::string& driver_path, const std::string& dir)
{
    constexpr int kLookups = 1 << 18;
    std::cout << "\nSegment pyramid against gaussian through TextureSystem (bilinear, LOD 0), the pyramid read "
                 "through TextureSystem and read into memory, "
              << kLookups << " lookups per run in scanline order; fastest of " << kRuns << " alternating runs each.\n\n"
              << "| map | breakpoints | channels | gaussian ns/pixel | segments ns/pixel (TextureSystem, memory) | "
                 "segments / gaussian (TextureSystem, memory) |\n"
                 "|---|---|---:|---:|---:|---:|\n";
    for (const char* name : kMaps) {
        ColorMapLoadOptions opt;
        opt.path = luts + "/" + name + ".png";
        auto map = load_color_map(opt, config);
        if (!map) return 1;
        auto table = GaussianColorTable::bake(map->map, {});
        if (!table) return 1;
        for (double tolerance : {0.5, 0.0}) {
            SegmentPyramidBakeOptions bake;
            bake.driver_path = driver_path;
            bake.output_path = dir + "/" + name + "-segments.exr";
            bake.maps = {&map->map};
            bake.tolerance_de = tolerance;
            auto baked = bake_segment_pyramid(bake);
            if (!baked) {
                std::cerr << baked.error().message << "\n";
                return 1;
            }
            auto tiles = SegmentPyramidTexture::open(bake.output_path, PyramidReads::TextureSystem);
            auto memory = SegmentPyramidTexture::open(bake.output_path, PyramidReads::Memory);
            if (!tiles || !memory) return 1;
            const std::vector<Rgb> colors = ramp_colors(map->map, tiles->info().breakpoints, tiles->info().weights());
            std::vector<float> ramps(tiles->channels());
            const auto coordinate = [](int i, int axis) {
                const int texel = i % (kSize * kSize);
                return (static_cast<float>(axis == 0 ? texel % kSize : texel / kSize) + 0.5f) / kSize;
            };
            double sink = 0;
            LookupCounters counters;
            const auto gaussian_run = [&] {
                double acc = 0;
                for (int i = 0; i < kLookups; ++i) {
                    const MomentSample m = moments.lookup(coordinate(i, 0), coordinate(i, 1), 0.0f);
                    acc += table->lookup(m.mean, m.sigma, &counters).g;
                }
                sink += acc;
            };
            const auto segments_run = [&](const SegmentPyramidTexture& segments) {
                return [&] {
                    double acc = 0;
                    for (int i = 0; i < kLookups; ++i) {
                        segments.lookup(coordinate(i, 0), coordinate(i, 1), 0.0f, ramps.data());
                        acc += ramp_color(colors, ramps.data()).g;
                    }
                    sink += acc;
                };
            };
            const auto [gaussian, segment] = fastest_pair_ms(kRuns, gaussian_run, segments_run(*tiles));
            const auto [gaussian_again, in_memory] = fastest_pair_ms(kRuns, gaussian_run, segments_run(*memory));
            char row[240];
            std::snprintf(row, sizeof row, "| %s | %s | %d | %.1f | %.1f, %.1f | %.2f, %.2f |\n", name,
                          tolerance > 0 ? "tolerance 0.5" : "exact", tiles->channels(), gaussian * 1e6 / kLookups,
                          segment * 1e6 / kLookups, in_memory * 1e6 / kLookups, segment / gaussian,
                          in_memory / gaussian_again);
            std::cout << row;
            if (sink == 42.0) std::cout << "";
        }
    }
    return 0;
}

// The same level as a 1024 x 1024 float driver, baked to a moment pyramid in
// a temporary directory, looked up at LOD 0 in scanline order.
int through_moment_texture(const std::string& luts, const ColorConfig& config, const std::vector<float>& driver)
{
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "cmfilter-bench-apply-cost";
    fs::create_directories(dir);
    const std::string driver_path = (dir / "driver.exr").string(), moments_path = (dir / "moments.exr").string();
    {
        auto out = OIIO::ImageOutput::create(driver_path);
        OIIO::ImageSpec spec(kSize, kSize, 1, OIIO::TypeDesc::FLOAT);
        if (!out || !out->open(driver_path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, driver.data()) ||
            !out->close())
            return 1;
    }
    MomentBakeOptions bake;
    bake.driver_path = driver_path;
    bake.output_path = moments_path;
    if (auto baked = bake_moment_pyramid(bake); !baked) {
        std::cerr << baked.error().message << "\n";
        return 1;
    }
    auto texture = MomentTexture::open(moments_path);
    if (!texture) return 1;
    constexpr int kLookups = 1 << 20;
    std::cout << "\nThrough MomentTexture (TextureSystem, bilinear, LOD 0), " << kLookups
              << " lookups per run in scanline order; fastest of " << kRuns << " alternating runs each.\n\n"
              << "| map | naive ns/pixel | gaussian ns/pixel | gaussian / naive |\n|---|---:|---:|---:|\n";
    for (const char* name : kMaps) {
        ColorMapLoadOptions opt;
        opt.path = luts + "/" + name + ".png";
        auto map = load_color_map(opt, config);
        if (!map) return 1;
        auto table = GaussianColorTable::bake(map->map, {});
        if (!table) return 1;
        const auto coordinate = [](int i, int axis) {
            const int texel = i % (kSize * kSize);
            return (static_cast<float>(axis == 0 ? texel % kSize : texel / kSize) + 0.5f) / kSize;
        };
        double sink = 0;
        LookupCounters counters;
        const auto [naive, gaussian] = fastest_pair_ms(
            kRuns,
            [&] {
            double acc = 0;
            for (int i = 0; i < kLookups; ++i) {
                const MomentSample m = texture->lookup(coordinate(i, 0), coordinate(i, 1), 0.0f);
                acc += map->map.evaluate(m.mean).g;
            }
            sink += acc;
            },
            [&] {
            double acc = 0;
            for (int i = 0; i < kLookups; ++i) {
                const MomentSample m = texture->lookup(coordinate(i, 0), coordinate(i, 1), 0.0f);
                acc += table->lookup(m.mean, m.sigma, &counters).g;
            }
            sink += acc;
        });
        char row[200];
        std::snprintf(row, sizeof row, "| %s | %.1f | %.1f | %.2f |\n", name, naive * 1e6 / kLookups,
                      gaussian * 1e6 / kLookups, gaussian / naive);
        std::cout << row;
        if (sink == 42.0) std::cout << "";
    }
    if (int st = through_color_pyramid(luts, config, *texture, driver_path, dir.string()); st != 0) return st;
    if (int st = through_segments(luts, config, *texture, driver_path, dir.string()); st != 0) return st;
    fs::remove_all(dir);
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::cerr << "usage: cmfilter-bench-apply-cost LUTS_DIR\n";
        return 1;
    }
    auto config = ColorConfig::load("");
    if (!config) return 1;

    // A smooth level: mean sweeping [0.02, 0.98] over a few periods, sigma in
    // [0, 0.2], so that the lookups cover the whole table.
    std::vector<float> means(static_cast<std::size_t>(kSize) * kSize), moments(2 * means.size());
    const double k = 2.0 * 3.14159265358979 / kSize;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * kSize + x;
            const double m = 0.5 + 0.48 * std::sin(3 * k * x + 2 * std::sin(2 * k * y));
            const double s = 0.1 + 0.1 * std::cos(5 * k * y + k * x);
            means[i] = static_cast<float>(m);
            moments[2 * i] = static_cast<float>(m);
            moments[2 * i + 1] = static_cast<float>(m * m + s * s);
        }
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<float> ss(kPixels), ts(kPixels);
    for (int i = 0; i < kPixels; ++i) {
        const int texel = i % (kSize * kSize);
        ss[i] = static_cast<float>(texel % kSize) + unit(rng);
        ts[i] = static_cast<float>(texel / kSize) + unit(rng);
    }

    std::cout << "Machine: " << cpu_name() << ", one thread. " << kPixels << "  lookups per run in scanline order"
              << " over a smooth " << kSize << " x " << kSize << " level; fastest of " << kRuns
              << " alternating runs each.\n\n"
              << "| map | naive ns/pixel | gaussian ns/pixel | gaussian / naive |\n|---|---:|---:|---:|\n";
    for (const char* name : kMaps) {
        ColorMapLoadOptions opt;
        opt.path = std::string(argv[1]) + "/" + name + ".png";
        auto map = load_color_map(opt, *config);
        if (!map) {
            std::cerr << map.error().message << "\n";
            return 1;
        }
        auto table = GaussianColorTable::bake(map->map, {});
        if (!table) return 1;
        double sink = 0;
        LookupCounters counters;
        const auto [naive, gaussian] = fastest_pair_ms(
            kRuns,
            [&] {
            double acc = 0;
            for (int i = 0; i < kPixels; ++i) {
                float m;
                fetch<1>(means, ss[i], ts[i], &m);
                acc += map->map.evaluate(m).g;
            }
            sink += acc;
            },
            [&] {
            double acc = 0;
            for (int i = 0; i < kPixels; ++i) {
                float m[2];
                fetch<2>(moments, ss[i], ts[i], m);
                const double sigma =
                    std::sqrt(std::max(0.0, static_cast<double>(m[1]) - static_cast<double>(m[0]) * m[0]));
                acc += table->lookup(m[0], sigma, &counters).g;
            }
            sink += acc;
        });
        char row[200];
        std::snprintf(row, sizeof row, "| %s | %.2f | %.2f | %.2f |\n", name, naive * 1e6 / kPixels,
                      gaussian * 1e6 / kPixels, gaussian / naive);
        std::cout << row;
        if (sink == 42.0) std::cout << "";  // keep the work observable
    }
    return through_moment_texture(argv[1], *config, means);
}
