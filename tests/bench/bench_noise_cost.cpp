// SPDX-License-Identifier: Apache-2.0
// Cost of the filtered noise evaluation (sec. 4.2) against the unfiltered
// noise with every octave evaluated, on the same points, timed in the same
// process:
//   unfiltered  f(x, y): all octaves of the fractal sum
//   filtered    FilteredNoise::filter(x, y, w): the filtered mean (each
//               octave's prediction of its footprint mean, octaves past their
//               cutoff not evaluated) and sigma from a per-LOD table, then
//               T(mean, sigma) from a colour table (eq. 10)
// and, to compare like with like, the unfiltered noise mapped through C0.
// Footprint widths are drawn uniformly in LOD over the sigma table's range
// (1/16 of the finest octave's period to 4 base periods), and also reported
// per band of LOD. The sigma table's values do not change its cost: a table
// of the right length with placeholder values is used.
// A second table times mixture (noise_sub_footprints.h: up to 2 x 2, 4 x 4
// and 8 x 8 squares, each filtered and looked up as above) against the
// filtered noise, per LOD band of width 1, for gradient fBm and turbulence.
//   cmfilter-bench-noise-cost LUTS_DIR
#include "cmfilter/colormap/color_map_loading.h"
#include "cmfilter/noise/filtered_noise.h"
#include "cmfilter/tables/gaussian_color_table.h"
#include "cmfilter/noise/noise_spec.h"
#include "cmfilter/noise/noise_sub_footprints.h"

#include "bench_noise.h"

#include "bench_timing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <utility>
#include <vector>

using namespace cmfilter;
using namespace cmfilter_bench;

namespace {

constexpr int kPoints = 1 << 16;
constexpr int kRuns = 3;

}  // namespace

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::cerr << "usage: cmfilter-bench-noise-cost LUTS_DIR\n";
        return 1;
    }
    auto config = ColorConfig::load("");
    if (!config) return 1;
    ColorMapLoadOptions load;
    load.path = std::string(argv[1]) + "/terrain.png";
    auto map = load_color_map(load, *config);
    if (!map) return 1;
    auto table = GaussianColorTable::bake(map->map, {});
    if (!table) return 1;

    const char* specs[] = {"fbm:base=gradient,octaves=6", "fbm:base=value,octaves=6",
                           "turbulence:base=gradient,octaves=6", "fbm:base=gabor,octaves=4"};
    std::cout
        << "Machine: " << cpu_name() << ", one thread. " << kPoints
        << " points per run, footprint LOD uniform over the table's range; fastest of " << kRuns
        << " alternating runs each; terrain map, default table.\n\n"
        << "| noise | LOD band | unfiltered ns | filtered ns | filtered / unfiltered | unfiltered + C0 ns | filtered / (unfiltered + C0) |\n"
        << "|---|---|---:|---:|---:|---:|---:|\n";
    for (const char* text : specs) {
        const auto noise = noise_from_spec(text);
        if (!noise) return 1;
        const int octaves = noise->options().octaves;
        const double p0 = noise->base_period();
        const double lod_first = std::log2(noise->octave_period(octaves - 1) / 16.0 / p0), lod_last = 2.0;
        const int nodes = static_cast<int>(std::round((lod_last - lod_first) / 0.25)) + 1;
        auto sigmas = NoiseSigmaTable::create(lod_first, 0.25, std::vector<double>(nodes, 0.1));
        if (!sigmas) return 1;
        const FilteredNoise filtered(*noise, *sigmas);
        // The whole range, then its lower and upper halves.
        const std::pair<double, double> bands[] = {
            {lod_first, lod_last}, {lod_first, 0.5 * (lod_first + lod_last)}, {0.5 * (lod_first + lod_last), lod_last}};
        for (const auto& [lo, hi] : bands) {
            std::mt19937_64 rng(7);
            std::uniform_real_distribution<double> pos(0.0, 256.0 * p0), lod(lo, hi);
            std::vector<double> xs(kPoints), ys(kPoints), ws(kPoints);
            for (int i = 0; i < kPoints; ++i) {
                xs[i] = pos(rng);
                ys[i] = pos(rng);
                ws[i] = p0 * std::exp2(lod(rng));
            }
            double sink = 0;
            LookupCounters counters;
            const auto filtered_run = [&] {
                double acc = 0;
                for (int i = 0; i < kPoints; ++i) {
                    const FilteredNoise::Parameters p = filtered.filter(xs[i], ys[i], ws[i]);
                    acc += table->lookup(p.mean, p.sigma, &counters).g;
                }
                sink += acc;
            };
            const auto [unfiltered, filt] = fastest_pair_ms(
                kRuns,
                [&] {
                double acc = 0;
                for (int i = 0; i < kPoints; ++i) acc += (*noise)(xs[i], ys[i]);
                sink += acc;
                },
                filtered_run);
            const auto [mapped, filt2] = fastest_pair_ms(
                kRuns,
                [&] {
                double acc = 0;
                for (int i = 0; i < kPoints; ++i) acc += map->map.evaluate((*noise)(xs[i], ys[i])).g;
                sink += acc;
                },
                filtered_run);
            const double f = std::min(filt, filt2);
            char row[300];
            std::snprintf(row, sizeof row, "| %s | %.2f .. %.2f | %.1f | %.1f | %.2f | %.1f | %.2f |\n", text, lo, hi,
                          unfiltered * 1e6 / kPoints, f * 1e6 / kPoints, f / unfiltered, mapped * 1e6 / kPoints,
                          f / mapped);
            std::cout << row << std::flush;
            if (sink == 42.0) std::cout << "";
        }
    }
    std::cout << "\n| noise | LOD band | gaussian ns | mixture 2 x 2 ns (x gaussian) | mixture 4 x 4 ns (x gaussian) | "
                 "mixture 8 x 8 ns (x gaussian) |\n|---|---|---:|---:|---:|---:|\n";
    for (const char* text : {"fbm:base=gradient,octaves=6", "turbulence:base=gradient,octaves=6"}) {
        const auto noise = noise_from_spec(text);
        if (!noise) return 1;
        const double p0 = noise->base_period();
        auto sigmas = NoiseSigmaTable::create(-9.0, 0.25, std::vector<double>(45, 0.1));
        if (!sigmas) return 1;
        const FilteredNoise filtered(*noise, *sigmas);
        for (int band = -9; band < 2; ++band) {
            const int points = kPoints / 16;
            std::mt19937_64 rng(11);
            std::uniform_real_distribution<double> pos(0.0, 256.0 * p0), lod(band, band + 1);
            std::vector<double> xs(points), ys(points), ws(points);
            for (int i = 0; i < points; ++i) {
                xs[i] = pos(rng);
                ys[i] = pos(rng);
                ws[i] = p0 * std::exp2(lod(rng));
            }
            double sink = 0;
            const auto gaussian_run = [&] {
                double acc = 0;
                for (int i = 0; i < points; ++i) {
                    const FilteredNoise::Parameters p = filtered.filter(xs[i], ys[i], ws[i]);
                    acc += table->lookup(p.mean, p.sigma).g;
                }
                sink += acc;
            };
            double ns[3] = {0, 0, 0}, gaussian = 1e300;
            for (int k = 0; k < 3; ++k) {
                SubFootprintOptions options;
                options.max_cells = 2 << k;
                const auto mixture_run = [&] {
                    double acc = 0;
                    for (int i = 0; i < points; ++i) {
                        const FilteredNoise::Parameters whole = filtered.filter(xs[i], ys[i], ws[i]);
                        acc +=
                            sub_footprint_color<Rgb>(filtered, xs[i], ys[i], ws[i], whole, options,
                                                     [&](const FilteredNoise::Parameters& p) {
                            return table->lookup(p.mean, p.sigma);
                            }).g;
                    }
                    sink += acc;
                };
                const auto [g, m] = fastest_pair_ms(kRuns, gaussian_run, mixture_run);
                gaussian = std::min(gaussian, g);
                ns[k] = m * 1e6 / points;
            }
            const double g_ns = gaussian * 1e6 / points;
            char row[300];
            std::snprintf(row, sizeof row, "| %s | %d .. %d | %.1f | %.1f (%.1f) | %.1f (%.1f) | %.1f (%.1f) |\n", text,
                          band, band + 1, g_ns, ns[0], ns[0] / g_ns, ns[1], ns[1] / g_ns, ns[2], ns[2] / g_ns);
            std::cout << row << std::flush;
            if (sink == 42.0) std::cout << "";
        }
    }
    return 0;
}
