// SPDX-License-Identifier: Apache-2.0
// Accuracy of the filtered noise colour (sec. 4.2) against a supersampled
// reference, per bundled map and LOD:
//   gaussian       T(mean_over_footprint, sigma): the table T of the map
//                  (default GaussianColorTable::bake, 256 value nodes) looked
//                  up at the filtered mean and the box column of the noise's
//                  sigma table, baked in process (bake_noise_sigma);
//   gaussian-2048  the same with a 2048-value table (isolates the value
//                  axis' bilinear error at small sigma);
//   naive          C0(mean_over_footprint);
//   oracle-2048    T(m, s) with the 2048-value table at the footprint's own
//                  sample mean m and standard deviation s of the reference
//                  samples: what is left is the Gaussian assumption alone,
//                  without the errors of the filtered mean and of the sigma table;
//   mean-oracle-2048  T(m, sigma): the footprint's own mean with the table's
//                  sigma: what exact footprint means would leave;
//   shape-table    C averaged over the noise's own residual distribution at
//                  the LOD: mean + r, r = f(p) - mean_over_footprint for
//                  points p of 8192 other footprints of the same width
//                  (16 jittered points each, a 128-bin histogram): what a
//                  table T_L(mean) would give whose kernel is the noise's
//                  measured one instead of a Gaussian, one lookup per
//                  footprint;
//   conditional-table  the same with r's distribution among the footprints
//                  whose filtered mean falls in the same one of 32 bins
//                  (bins with under 256 samples take the whole): a table of
//                  E[C | filtered mean] per LOD, the best any one lookup
//                  from the filtered mean can do up to its sampling;
//   mixture        the mixture of Gaussians over sub-footprints
//                  (noise_sub_footprints.h, default options: up to 8 x 8)
//                  with the 256-value table; mixture-2048 the same with the
//                  2048-value table; mixture-4 up to 4 x 4;
//   reference      the average of C0(f(x)) over 32 x 32 jittered-stratified
//                  samples inside the square footprint of width w.
// Footprints: squares of width w = p_0 2^L, L from log2(p_{N-1} / 16 / p_0)
// (1/16 of the finest octave's period) to LAST_LOD (2 by default: 4 base
// periods; the sigma table is baked to it) in steps of 0.5,
// P centres uniform over [0, 256 p_0)^2. Each map is laid over
// [mean - 2.78 sigma, mean + 2.78 sigma] of the noise's global statistics
// (clamp), so the noise's standard deviation is 0.18 of the map's domain, as
// for the Gaussian-like driver of docs/apply.md.
// Errors are CIEDE2000 (scene-linear Rec.709), summarised over the P
// footprints. CSV on stdout:
//   noise,map,lod,width,method,mean,p95,max
//
// (LABEL names the noise in the CSV, whose specs contain commas.)
//   cmfilter-noise-accuracy LUTS_DIR LABEL NOISE_SPEC [P] [THREADS] [LAST_LOD]
#include "cmfilter/color/ciede2000.h"
#include "cmfilter/colormap/color_map_loading.h"
#include "cmfilter/color/error_summary.h"
#include "cmfilter/noise/filtered_noise.h"
#include "cmfilter/tables/gaussian_color_table.h"
#include "cmfilter/noise/noise_lattice.h"
#include "cmfilter/noise/noise_sigma_bake.h"
#include "cmfilter/noise/noise_spec.h"
#include "cmfilter/noise/noise_sub_footprints.h"

#include "bench_noise.h"
#include "cmfilter/util/parallel_for.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

using namespace cmfilter;

namespace {

constexpr int kStrata = 32;  // reference: 32 x 32 jittered samples
constexpr double kLodStep = 0.5;
constexpr double kDomainSigmas = 2.78;  // map domain: mean +- 2.78 sigma (sd = 0.18 of it)

struct Map {
    std::string name;
    ColorMap map;
    GaussianColorTable table, table2048;
};

const char* const kMethods[] = {"gaussian",    "gaussian-2048",     "naive",   "oracle-2048",  "mean-oracle-2048",
                                "shape-table", "conditional-table", "mixture", "mixture-2048", "mixture-4"};
constexpr int kMethodCount = 10;

// The residual r = f(p) - mean_over_footprint of a noise over footprints of
// one width (see shape-table and conditional-table above).
constexpr int kResidualFootprints = 8192, kResidualStrata = 4, kResidualBins = 128;
constexpr int kMeanBins = 32, kMinBinSamples = 256;

struct ResidualHistogram {
    std::vector<double> value, weight;
};

struct ResidualDistribution {
    ResidualHistogram all;
    std::vector<ResidualHistogram> by_mean;  // empty where too few samples
    double mean_first = 0, mean_step = 1;

    const ResidualHistogram& given(double mean) const
    {
        const int i = std::clamp(static_cast<int>(std::floor((mean - mean_first) / mean_step)), 0, kMeanBins - 1);
        const ResidualHistogram& h = by_mean[static_cast<std::size_t>(i)];
        return h.value.empty() ? all : h;
    }
};

ResidualHistogram histogram(const std::vector<double>& r, double first, double last)
{
    const double step = (last - first) / kResidualBins;
    std::vector<double> count(kResidualBins);
    for (double v : r)
        count[static_cast<std::size_t>(
            std::clamp(static_cast<int>(step > 0 ? (v - first) / step : 0), 0, kResidualBins - 1))] += 1;
    ResidualHistogram h;
    for (int i = 0; i < kResidualBins; ++i)
        if (count[static_cast<std::size_t>(i)] > 0) {
            h.value.push_back(first + (i + 0.5) * step);
            h.weight.push_back(count[static_cast<std::size_t>(i)] / static_cast<double>(r.size()));
        }
    return h;
}

// Footprints centred in [3000 p_0, 3256 p_0)^2, away from the measured ones.
ResidualDistribution measure_residuals(const FractalNoise& noise, double w, std::uint64_t seed)
{
    const double p0 = noise.base_period();
    std::uint64_t state = seed ^ 0x5eedull;
    std::vector<double> means, residuals;
    for (int q = 0; q < kResidualFootprints; ++q) {
        const double cx = p0 * (3000 + 256 * unit_interval(splitmix64(state)));
        const double cy = p0 * (3000 + 256 * unit_interval(splitmix64(state)));
        const double m = noise.mean_over_footprint(cx, cy, w);
        for (int a = 0; a < kResidualStrata; ++a)
            for (int b = 0; b < kResidualStrata; ++b) {
                const double x = cx + w * ((a + unit_interval(splitmix64(state))) / kResidualStrata - 0.5);
                const double y = cy + w * ((b + unit_interval(splitmix64(state))) / kResidualStrata - 0.5);
                means.push_back(m);
                residuals.push_back(noise(x, y) - m);
            }
    }
    const auto [rmin, rmax] = std::minmax_element(residuals.begin(), residuals.end());
    const auto [mmin, mmax] = std::minmax_element(means.begin(), means.end());
    ResidualDistribution d;
    d.all = histogram(residuals, *rmin, *rmax);
    d.mean_first = *mmin;
    d.mean_step = *mmax > *mmin ? (*mmax - *mmin) / kMeanBins : 1.0;
    std::vector<std::vector<double>> per_bin(kMeanBins);
    for (std::size_t i = 0; i < means.size(); ++i)
        per_bin[static_cast<std::size_t>(
                    std::clamp(static_cast<int>((means[i] - d.mean_first) / d.mean_step), 0, kMeanBins - 1))]
            .push_back(residuals[i]);
    for (const auto& r : per_bin)
        d.by_mean.push_back(static_cast<int>(r.size()) >= kMinBinSamples ? histogram(r, *rmin, *rmax)
                                                                         : ResidualHistogram{});
    return d;
}

Rgb colour_through(const ColorMap& map, double mean, const ResidualHistogram& h)
{
    Rgb c;
    for (std::size_t i = 0; i < h.value.size(); ++i) c += h.weight[i] * map.evaluate(mean + h.value[i]);
    return c;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 4 || argc > 7) {
        std::cerr << "usage: cmfilter-noise-accuracy LUTS_DIR LABEL NOISE_SPEC [P] [THREADS] [LAST_LOD]\n";
        return 1;
    }
    const std::string luts = argv[1], label = argv[2], spec_text = argv[3];
    const int points = argc > 4 ? std::atoi(argv[4]) : 2048;
    const int threads = argc > 5 ? std::atoi(argv[5]) : 0;
    const double last_lod = argc > 6 ? std::atof(argv[6]) : 2.0;
    const auto t0 = std::chrono::steady_clock::now();
    const auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };

    const auto noise = noise_from_spec(spec_text);
    if (!noise) return 1;
    NoiseSigmaBakeOptions bake_options;
    bake_options.threads = threads;
    bake_options.lod_last = std::max(bake_options.lod_last, last_lod);
    auto bake = bake_noise_sigma(*noise, bake_options);
    if (!bake) {
        std::cerr << bake.error().message << "\n";
        return 1;
    }
    auto sigma_table = bake->table(FootprintShape::Box);
    if (!sigma_table) {
        std::cerr << sigma_table.error().message << "\n";
        return 1;
    }
    const FilteredNoise filtered(*noise, *sigma_table);
    const double global_mean = bake->global.mean, global_sigma = bake->global.sigma;
    std::fprintf(stderr, "noise_accuracy: %s: sigma table baked in %.1f s (global mean %.4f, sigma %.4f)\n",
                 spec_text.c_str(), seconds(), global_mean, global_sigma);

    auto config = ColorConfig::load("");
    if (!config) {
        std::cerr << config.error().message << "\n";
        return 1;
    }
    std::vector<Map> maps;
    for (const char* name : {"terrain", "stripes", "step", "narrow-band", "hue-ramp"}) {
        ColorMapLoadOptions load;
        load.path = luts + "/" + name + ".png";
        load.vmin = global_mean - kDomainSigmas * global_sigma;
        load.vmax = global_mean + kDomainSigmas * global_sigma;
        auto loaded = load_color_map(load, *config);
        if (!loaded) {
            std::cerr << loaded.error().message << "\n";
            return 1;
        }
        GaussianColorTableOptions options;
        options.threads = threads;
        auto table = GaussianColorTable::bake(loaded->map, options);
        options.values = 2048;
        auto table2048 = GaussianColorTable::bake(loaded->map, options);
        if (!table || !table2048) {
            std::cerr << "noise_accuracy: table bake failed for " << name << "\n";
            return 1;
        }
        maps.push_back({name, loaded->map, std::move(*table), std::move(*table2048)});
    }

    const int octaves = noise->options().octaves;
    const double p0 = noise->base_period();
    const double lod_first = std::log2(noise->octave_period(octaves - 1) / 16.0 / p0);
    const int lods = static_cast<int>(std::floor((last_lod - lod_first) / kLodStep + 1e-9)) + 1;
    const std::size_t map_count = maps.size();

    SubFootprintOptions four;
    four.max_cells = 4;
    std::cout << "noise,map,lod,width,method,mean,p95,max\n";
    for (int k = 0; k < lods; ++k) {
        const double lod = lod_first + k * kLodStep, w = p0 * std::exp2(lod);
        const double sigma = filtered.unresolved_sigma(w);
        const ResidualDistribution residuals = measure_residuals(*noise, w, static_cast<std::uint64_t>(k));
        // errors[(map * kMethodCount + method) * points + footprint]
        std::vector<double> errors(map_count * kMethodCount * static_cast<std::size_t>(points));
        parallel_for(points, threads, [&](int j) {
            std::uint64_t state = (static_cast<std::uint64_t>(k) << 32) ^ static_cast<std::uint64_t>(j);
            splitmix64(state);
            const double cx = 256.0 * p0 * unit_interval(splitmix64(state));
            const double cy = 256.0 * p0 * unit_interval(splitmix64(state));
            std::vector<double> f(kStrata * kStrata);
            for (int a = 0; a < kStrata; ++a)
                for (int b = 0; b < kStrata; ++b) {
                    const double x = cx + w * ((a + unit_interval(splitmix64(state))) / kStrata - 0.5);
                    const double y = cy + w * ((b + unit_interval(splitmix64(state))) / kStrata - 0.5);
                    f[static_cast<std::size_t>(a * kStrata + b)] = (*noise)(x, y);
                }
            const double mean = filtered.mean_over_footprint(cx, cy, w);
            double sum = 0, sum2 = 0;
            for (double v : f) sum += v;
            const double sample_mean = sum / static_cast<double>(f.size());
            for (double v : f) sum2 += (v - sample_mean) * (v - sample_mean);
            const double sample_sigma = std::sqrt(sum2 / static_cast<double>(f.size()));
            const FilteredNoise::Parameters whole = filtered.filter(cx, cy, w);
            for (std::size_t m = 0; m < map_count; ++m) {
                const auto mixture = [&](const GaussianColorTable& table, const SubFootprintOptions& options) {
                    return sub_footprint_color<Rgb>(filtered, cx, cy, w, whole, options,
                                                    [&](const FilteredNoise::Parameters& p) {
                        return table.lookup(p.mean, p.sigma);
                    });
                };
                Rgb reference;
                for (double v : f) reference += maps[m].map.evaluate(v);
                reference = (1.0 / static_cast<double>(f.size())) * reference;
                const Rgb estimates[kMethodCount] = {maps[m].table.lookup(mean, sigma),
                                                     maps[m].table2048.lookup(mean, sigma),
                                                     maps[m].map.evaluate(mean),
                                                     maps[m].table2048.lookup(sample_mean, sample_sigma),
                                                     maps[m].table2048.lookup(sample_mean, sigma),
                                                     colour_through(maps[m].map, mean, residuals.all),
                                                     colour_through(maps[m].map, mean, residuals.given(mean)),
                                                     mixture(maps[m].table, {}),
                                                     mixture(maps[m].table2048, {}),
                                                     mixture(maps[m].table, four)};
                for (int e = 0; e < kMethodCount; ++e)
                    errors[(m * kMethodCount + e) * points + j] = ciede2000_linear_rgb(reference, estimates[e]);
            }
        });
        for (std::size_t m = 0; m < map_count; ++m)
            for (int e = 0; e < kMethodCount; ++e) {
                const auto first = errors.begin() + static_cast<std::ptrdiff_t>((m * kMethodCount + e) * points);
                const ErrorSummary s = summarize_errors(std::vector<double>(first, first + points));
                std::printf("%s,%s,%.2f,%.9g,%s,%.4f,%.4f,%.4f\n", label.c_str(), maps[m].name.c_str(), lod, w,
                            kMethods[e], s.mean, s.p95, s.max);
            }
        std::fflush(stdout);
        std::fprintf(stderr, "noise_accuracy: LOD %.2f (sigma %.4f) done at %.1f s\n", lod, sigma, seconds());
    }
    return 0;
}
