// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/noise/noise_sigma_bake.h"

#include "cmfilter/noise/noise_lattice.h"
#include "cmfilter/util/parallel_for.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace cmfilter {

namespace {

constexpr double kZ95 = 1.959963984540054;  // two-sided 95% normal quantile
constexpr double kDomainPeriods = 256.0;    // centres over [0, 256 p_0)^2
constexpr double kTwoPi = 6.283185307179586;

// A generator for one footprint: SplitMix64 from a hash of its keys.
std::uint64_t footprint_state(std::uint64_t seed, std::uint64_t stream, std::uint64_t index)
{
    std::uint64_t s = seed;
    std::uint64_t h = splitmix64(s) ^ stream;
    h = splitmix64(h) ^ index;
    return splitmix64(h);
}

// The box's strata per axis: even (strata are paired, below), at least 2.
int box_side(int samples)
{
    const int n = static_cast<int>(std::sqrt(static_cast<double>(samples)) + 1e-9);
    return std::max(2, n - n % 2);
}

}  // namespace

const char* to_string(FootprintShape shape) { return shape == FootprintShape::Box ? "box" : "gaussian"; }

std::vector<FootprintMoments> sample_footprints(const FractalNoise& noise, FootprintShape shape, double width,
                                                int samples_per_footprint, std::uint64_t seed, std::uint64_t stream,
                                                int first, int count, int threads)
{
    std::vector<FootprintMoments> out(static_cast<std::size_t>(std::max(count, 0)));
    const double domain = kDomainPeriods * noise.base_period();
    const int n = box_side(samples_per_footprint);
    const int s = shape == FootprintShape::Box ? n * n : std::max(2, samples_per_footprint);
    parallel_for(count, threads, [&](int k) {
        std::uint64_t state = footprint_state(seed, stream, static_cast<std::uint64_t>(first + k));
        const auto u = [&] { return unit_interval(splitmix64(state)); };
        const double cx = domain * u(), cy = domain * u();
        std::vector<double> f(static_cast<std::size_t>(s));
        if (shape == FootprintShape::Box) {
            const double cell = width / n;
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const double x = cx - 0.5 * width + cell * (i + u());
                    const double y = cy - 0.5 * width + cell * (j + u());
                    f[static_cast<std::size_t>(j * n + i)] = noise(x, y);
                }
        } else {
            // Box-Muller: two independent N(0, 1) per pair of uniforms; sd = w / 2.
            const double sd = 0.5 * width;
            for (int i = 0; i < s; ++i) {
                const double r = std::sqrt(-2.0 * std::log(1.0 - u())), a = kTwoPi * u();
                f[static_cast<std::size_t>(i)] = noise(cx + sd * r * std::cos(a), cy + sd * r * std::sin(a));
            }
        }
        double mean = 0;
        for (double v : f) mean += v;
        mean /= s;
        double ss = 0;
        for (double v : f) ss += (v - mean) * (v - mean);
        double variance = ss / (s - 1);  // independent samples: unbiased
        if (shape == FootprintShape::Box) {
            // Stratified samples are each uniform in their cell, so
            // E[(1/S) sum (f_i - mu)^2] = sigma^2 exactly and
            // (1/S) sum (f_i - m)^2 + Var(m) is unbiased; S/(S-1) would not be
            // (it assumes Var(m) = sigma^2 / S, and stratification makes Var(m)
            // smaller: up to +1/(S-1) in variance). Var(m) = (1/S^2) sum of
            // the cells' variances, estimated by collapsed strata (Cochran,
            // "Sampling Techniques", sec. 5A.12): horizontally adjacent cells
            // paired, (f_a - f_b)^2 / S^2 per pair; it errs high by the
            // squared difference of the paired cells' means, O(sigma^2 / S^2)
            // where the noise is smooth across a cell.
            double var_m = 0;
            for (int j = 0; j < n; ++j)
                for (int i = 0; i + 1 < n; i += 2) {
                    const double d = f[static_cast<std::size_t>(j * n + i)] -
                                     f[static_cast<std::size_t>(j * n + i + 1)];
                    var_m += d * d;
                }
            var_m /= static_cast<double>(s) * s;
            variance = ss / s + var_m;
        }
        out[static_cast<std::size_t>(k)] = {mean, variance};
    });
    return out;
}

SigmaEstimate estimate_sigma(const std::vector<FootprintMoments>& footprints, int samples_per_footprint)
{
    SigmaEstimate e;
    e.footprints = static_cast<int>(footprints.size());
    e.samples_per_footprint = samples_per_footprint;
    if (footprints.empty()) return e;
    double sum = 0;
    for (const auto& fp : footprints) sum += fp.variance;
    const double f = static_cast<double>(footprints.size());
    const double mean = sum / f;
    double ss = 0;
    for (const auto& fp : footprints) ss += (fp.variance - mean) * (fp.variance - mean);
    const double sd = footprints.size() > 1 ? std::sqrt(ss / (f - 1)) : 0.0;
    e.mean_variance = mean;
    e.variance_half_width = kZ95 * sd / std::sqrt(f);
    e.sigma = std::sqrt(mean);
    const double lo = std::sqrt(std::max(0.0, mean - e.variance_half_width));
    const double hi = std::sqrt(mean + e.variance_half_width);
    e.half_width = 0.5 * (hi - lo);
    return e;
}

NoiseGlobalStats measure_global_stats(const FractalNoise& noise, int samples, std::uint64_t seed, int threads)
{
    NoiseGlobalStats g;
    g.samples = std::max(samples, 2);
    std::vector<double> f(static_cast<std::size_t>(g.samples));
    const double domain = kDomainPeriods * noise.base_period();
    constexpr int kChunk = 4096;
    const int chunks = (g.samples + kChunk - 1) / kChunk;
    parallel_for(chunks, threads, [&](int c) {
        std::uint64_t state = footprint_state(seed, 0xC0FFEEull, static_cast<std::uint64_t>(c));
        const int end = std::min(g.samples, (c + 1) * kChunk);
        for (int i = c * kChunk; i < end; ++i) {
            const double x = domain * unit_interval(splitmix64(state));
            const double y = domain * unit_interval(splitmix64(state));
            f[static_cast<std::size_t>(i)] = noise(x, y);
        }
    });
    double sum = 0;
    for (double v : f) sum += v;
    const double n = static_cast<double>(g.samples);
    g.mean = sum / n;
    double m2 = 0, m3 = 0, m4 = 0;  // central moments (population)
    for (double v : f) {
        const double d = v - g.mean, d2 = d * d;
        m2 += d2;
        m3 += d2 * d;
        m4 += d2 * d2;
    }
    m2 /= n;
    m3 /= n;
    m4 /= n;
    g.variance = m2 * n / (n - 1);
    g.sigma = std::sqrt(g.variance);
    g.skewness = m2 > 0 ? m3 / std::pow(m2, 1.5) : 0.0;
    g.excess_kurtosis = m2 > 0 ? m4 / (m2 * m2) - 3.0 : 0.0;
    g.variance_half_width = kZ95 * std::sqrt(std::max(0.0, m4 - m2 * m2) / n);
    return g;
}

Expected<std::vector<double>> noise_sigma_lods(const FractalNoise& noise, const NoiseSigmaBakeOptions& options)
{
    if (!(options.lod_step > 0) || !std::isfinite(options.lod_step) || options.lod_step > 4)
        return bad_input("LOD step " + std::to_string(options.lod_step) + " is invalid (expected 0 < step <= 4)");
    if (!(options.finest_fraction > 0) || !std::isfinite(options.finest_fraction) || !std::isfinite(options.lod_last))
        return bad_input("noise sigma bake: finest fraction and last LOD must be finite (fraction > 0)");
    const double finest = noise.octave_period(noise.options().octaves - 1);
    const double first = std::log2(options.finest_fraction * finest / noise.base_period());
    const double span = options.lod_last - first;
    const int count = span <= 0 ? 1 : static_cast<int>(std::ceil(span / options.lod_step - 1e-9)) + 1;
    if (count > 4096)
        return bad_input("LOD step " + std::to_string(options.lod_step) + " gives " + std::to_string(count) +
                         " LODs (at most 4096)");
    std::vector<double> lods(static_cast<std::size_t>(count));
    for (int k = 0; k < count; ++k) lods[static_cast<std::size_t>(k)] = first + options.lod_step * k;
    return lods;
}

Expected<NoiseSigmaBake> bake_noise_sigma(const FractalNoise& noise, const NoiseSigmaBakeOptions& options)
{
    auto lods = noise_sigma_lods(noise, options);
    if (!lods) return lods.error();
    if (options.samples_per_footprint < 4 || options.initial_footprints < 2 ||
        options.max_footprints < options.initial_footprints || !(options.relative_half_width > 0) ||
        options.global_samples < 2)
        return bad_input("noise sigma bake: need S >= 4, 2 <= initial F <= max F, a target half-width > 0 "
                         "and at least 2 global samples");
    NoiseSigmaBake bake;
    bake.lod_first = lods->front();
    bake.lod_step = options.lod_step;
    const int box_s = box_side(options.samples_per_footprint) * box_side(options.samples_per_footprint);
    const std::size_t total = lods->size() * 2;
    std::size_t done = 0;
    for (std::size_t k = 0; k < lods->size(); ++k) {
        NoiseSigmaBakeRow row;
        row.lod = (*lods)[k];
        const double width = noise.base_period() * std::exp2(row.lod);
        for (FootprintShape shape : {FootprintShape::Box, FootprintShape::Gaussian}) {
            const int s = shape == FootprintShape::Box ? box_s : options.samples_per_footprint;
            const std::uint64_t stream = 2 * k + (shape == FootprintShape::Box ? 0 : 1);
            std::vector<FootprintMoments> fps;
            SigmaEstimate e;
            int want = options.initial_footprints;
            for (;;) {
                const int have = static_cast<int>(fps.size());
                auto more =
                    sample_footprints(noise, shape, width, s, options.seed, stream, have, want - have, options.threads);
                fps.insert(fps.end(), more.begin(), more.end());
                e = estimate_sigma(fps, s);
                const double target = options.relative_half_width * e.sigma;
                if (e.half_width <= target || want >= options.max_footprints) break;
                // The half-width shrinks as 1 / sqrt(F): aim 10% past the estimate.
                const double ratio = e.half_width / target;
                const double next = std::ceil(1.1 * want * ratio * ratio / 256.0) * 256.0;
                want = static_cast<int>(std::min<double>(options.max_footprints, std::max<double>(next, want + 256)));
            }
            (shape == FootprintShape::Box ? row.box : row.gaussian) = e;
            if (options.progress) options.progress(static_cast<double>(++done) / static_cast<double>(total + 1));
        }
        bake.rows.push_back(row);
    }
    bake.global = measure_global_stats(noise, options.global_samples, options.seed, options.threads);
    if (options.progress) options.progress(1.0);
    return bake;
}

Expected<NoiseSigmaTable> NoiseSigmaBake::table(FootprintShape shape) const
{
    std::vector<double> sigmas;
    sigmas.reserve(rows.size());
    for (const auto& r : rows) sigmas.push_back(shape == FootprintShape::Box ? r.box.sigma : r.gaussian.sigma);
    return NoiseSigmaTable::create(lod_first, lod_step, std::move(sigmas));
}

}  // namespace cmfilter
