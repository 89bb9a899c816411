// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/synthesis/synthesis_quality.h"

#include "cmfilter/synthesis/synthesis_random.h"

#include "cmfilter/util/parallel_for.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace cmfilter {

namespace {

// Random sample texel pairs for the coherence's normaliser: a fixed,
// deterministic set.
constexpr int kRandomPairs = 4096;
constexpr std::uint64_t kPairSeed = 0x636d66696c746572ull;
constexpr std::uint64_t kGridSeed = 0x677269642d736565ull;

int wrap(int i, int n) { return ((i % n) + n) % n; }
int clamp_index(int i, int n) { return std::min(std::max(i, 0), n - 1); }

// A texton distance, never below 0 (M's rounding can make it slightly negative).
double texton_distance(const LevelAnalysis& level, std::int32_t a, std::int32_t b)
{
    return std::max(0.0, static_cast<double>(level.distance(a, b)));
}

// The output texels the coherence measures: an even grid of about `wanted`
// cells, one texel at a fixed pseudo-random place in each (a grid of cell
// centres would alias with a tiling whose period divides the cell size and
// miss every tile border), every texel when `wanted` is 0 or at least the
// output.
std::vector<std::size_t> coherence_grid(int width, int height, int wanted)
{
    const std::size_t texels = static_cast<std::size_t>(width) * height;
    std::vector<std::size_t> grid;
    if (wanted <= 0 || static_cast<std::size_t>(wanted) >= texels) {
        grid.resize(texels);
        for (std::size_t t = 0; t < texels; ++t) grid[t] = t;
        return grid;
    }
    const int gx = std::clamp(static_cast<int>(std::lround(std::sqrt(double(wanted) * width / height))), 1, width);
    const int gy = std::clamp(static_cast<int>(std::lround(double(wanted) / gx)), 1, height);
    SplitMix64 state(kGridSeed);
    for (int j = 0; j < gy; ++j)
        for (int i = 0; i < gx; ++i) {
            // Cell [x0, x1) x [y0, y1); 53 random bits place the texel in it.
            const int x0 = static_cast<int>(static_cast<long long>(i) * width / gx);
            const int x1 = static_cast<int>(static_cast<long long>(i + 1) * width / gx);
            const int y0 = static_cast<int>(static_cast<long long>(j) * height / gy);
            const int y1 = static_cast<int>(static_cast<long long>(j + 1) * height / gy);
            const double rx = state.uniform();
            const double ry = state.uniform();
            const int x = std::min(x1 - 1, x0 + static_cast<int>(rx * (x1 - x0)));
            const int y = std::min(y1 - 1, y0 + static_cast<int>(ry * (y1 - y0)));
            grid.push_back(static_cast<std::size_t>(y) * width + x);
        }
    return grid;
}

}  // namespace

Expected<SynthesisQuality> measure_synthesis(const CoordinateMap& map, const SampleAnalysis& analysis,
                                             const QualityOptions& options)
{
    if (analysis.levels.empty()) return bad_input("the sample analysis has no levels");
    if (map.levels.empty()) return bad_input("the coordinate map has no levels");
    const LevelAnalysis& sample = analysis.levels[0];
    const CoordinateLevel& out = map.full();
    const int sw = sample.width, sh = sample.height;
    if (out.sample_width != sw || out.sample_height != sh)
        return bad_input("the coordinate map points into a " + std::to_string(out.sample_width) + " x " +
                         std::to_string(out.sample_height) + " sample, but the analysis's sample is " +
                         std::to_string(sw) + " x " + std::to_string(sh));
    if (out.width < 1 || out.height < 1 || out.coords.size() != 2 * out.texels())
        return bad_input("the coordinate map's level 0 is inconsistent: " + std::to_string(out.width) + " x " +
                         std::to_string(out.height) + " texels, " + std::to_string(out.coords.size()) + " coordinates");
    for (std::size_t t = 0; t < out.texels(); ++t)
        if (out.x(t) < 0 || out.x(t) >= sw || out.y(t) < 0 || out.y(t) >= sh)
            return bad_input("the coordinate map copies sample texel (" + std::to_string(out.x(t)) + ", " +
                             std::to_string(out.y(t)) + ") at texel (" + std::to_string(t % out.width) + ", " +
                             std::to_string(t / out.width) + "), outside the " + std::to_string(sw) + " x " +
                             std::to_string(sh) + " sample");
    const int n = options.neighbourhood;
    if (n < 1 || 2 * n + 1 > std::min(sw, sh))
        return bad_input("QualityOptions::neighbourhood " + std::to_string(n) +
                             " is invalid: expected >= 1 with a (2n + 1)^2 window within the " + std::to_string(sw) +
                             " x " + std::to_string(sh) + " sample",
                         "QualityOptions::neighbourhood");
    if (options.coherence_texels < 0)
        return bad_input("QualityOptions::coherence_texels " + std::to_string(options.coherence_texels) +
                             " is invalid: expected >= 0 (0: every output texel)",
                         "QualityOptions::coherence_texels");

    const int ow = out.width, oh = out.height;
    const bool toroidal = map.info.toroidal, periodic = analysis.periodic;
    auto sample_texel = [&](int x, int y) -> std::size_t {
        x = periodic ? wrap(x, sw) : clamp_index(x, sw);
        y = periodic ? wrap(y, sh) : clamp_index(y, sh);
        return static_cast<std::size_t>(y) * sw + x;
    };
    auto output_texton = [&](std::size_t t) {
        return sample.texton[static_cast<std::size_t>(out.y(t)) * sw + out.x(t)];
    };

    SynthesisQuality quality;

    // Coherence: per measured output texel p, D(p) = min over sample texels q
    // of the mean over window offsets o of dist(texton(c(p + o)), texton(q + o)).
    const std::vector<std::size_t> grid = coherence_grid(ow, oh, options.coherence_texels);
    std::vector<double> root_distance(grid.size());
    parallel_for(static_cast<int>(grid.size()), options.threads, [&](int i) {
        const std::size_t p = grid[static_cast<std::size_t>(i)];
        const int px = static_cast<int>(p % ow), py = static_cast<int>(p / ow);
        // The window's offsets and output textons (offsets outside a
        // non-toroidal output skipped).
        std::vector<int> dx, dy;
        std::vector<std::int32_t> texton;
        for (int oy = -n; oy <= n; ++oy)
            for (int ox = -n; ox <= n; ++ox) {
                int x = px + ox, y = py + oy;
                if (toroidal) {
                    x = wrap(x, ow);
                    y = wrap(y, oh);
                } else if (x < 0 || x >= ow || y < 0 || y >= oh) {
                    continue;
                }
                dx.push_back(ox);
                dy.push_back(oy);
                texton.push_back(output_texton(static_cast<std::size_t>(y) * ow + x));
            }
        double best = std::numeric_limits<double>::infinity();
        for (int qy = 0; qy < sh; ++qy)
            for (int qx = 0; qx < sw; ++qx) {
                double sum = 0;
                for (std::size_t o = 0; o < texton.size() && sum < best * texton.size(); ++o)
                    sum += texton_distance(sample, texton[o], sample.texton[sample_texel(qx + dx[o], qy + dy[o])]);
                best = std::min(best, sum / texton.size());
            }
        root_distance[static_cast<std::size_t>(i)] = std::sqrt(best);
    });
    double mean_root = 0;
    for (double d : root_distance) mean_root += d;
    mean_root /= static_cast<double>(root_distance.size());
    SplitMix64 state(kPairSeed);
    double pair_distance = 0;
    const std::size_t sample_texels = sample.texels();
    for (int r = 0; r < kRandomPairs; ++r) {
        const std::size_t a = state.next() % sample_texels;
        const std::size_t b = state.next() % sample_texels;
        pair_distance += texton_distance(sample, sample.texton[a], sample.texton[b]);
    }
    pair_distance /= kRandomPairs;
    quality.coherence = pair_distance > 0 ? mean_root / std::sqrt(pair_distance) : 0.0;

    // Coverage: the share of sample texels copied at least once, beside what
    // M texels copied uniformly at random would reach, 1 - (1 - 1/N)^M.
    std::vector<char> used(sample_texels, 0);
    for (std::size_t t = 0; t < out.texels(); ++t) used[static_cast<std::size_t>(out.y(t)) * sw + out.x(t)] = 1;
    std::size_t distinct = 0;
    for (char u : used) distinct += static_cast<std::size_t>(u);
    const double texels_n = static_cast<double>(sample_texels);
    quality.coverage = distinct / texels_n;
    quality.uniform_coverage = 1.0 - std::pow(1.0 - 1.0 / texels_n, static_cast<double>(out.texels()));

    // Seams: adjacent output pairs that are not adjacent in the sample,
    // c(p + e) != c(p) + e, and their contrast against the sample's own edges.
    std::size_t pairs = 0, seams = 0;
    double seam_distance = 0;
    for (int axis = 0; axis < 2; ++axis) {
        const int ex = axis == 0 ? 1 : 0, ey = 1 - ex;
        for (int y = 0; y < oh; ++y)
            for (int x = 0; x < ow; ++x) {
                int nx = x + ex, ny = y + ey;
                if (nx >= ow || ny >= oh) {
                    if (!toroidal) continue;
                    nx = wrap(nx, ow);
                    ny = wrap(ny, oh);
                }
                const std::size_t p = static_cast<std::size_t>(y) * ow + x;
                const std::size_t q = static_cast<std::size_t>(ny) * ow + nx;
                int cx = out.x(p) + ex, cy = out.y(p) + ey;
                if (periodic) {
                    cx = wrap(cx, sw);
                    cy = wrap(cy, sh);
                }
                ++pairs;
                if (out.x(q) == cx && out.y(q) == cy) continue;
                ++seams;
                seam_distance += texton_distance(sample, output_texton(p), output_texton(q));
            }
    }
    quality.seam_share = pairs > 0 ? static_cast<double>(seams) / pairs : 0.0;
    if (seams > 0) {
        double edge_distance = 0;
        std::size_t edges = 0;
        for (int axis = 0; axis < 2; ++axis) {
            const int ex = axis == 0 ? 1 : 0, ey = 1 - ex;
            for (int y = 0; y < sh; ++y)
                for (int x = 0; x < sw; ++x) {
                    int nx = x + ex, ny = y + ey;
                    if (nx >= sw || ny >= sh) {
                        if (!periodic) continue;
                        nx = wrap(nx, sw);
                        ny = wrap(ny, sh);
                    }
                    edge_distance += texton_distance(sample, sample.texton[static_cast<std::size_t>(y) * sw + x],
                                                     sample.texton[static_cast<std::size_t>(ny) * sw + nx]);
                    ++edges;
                }
        }
        const double mean_edge = edges > 0 ? edge_distance / edges : 0.0;
        quality.seam_contrast = mean_edge > 0 ? (seam_distance / seams) / mean_edge : 0.0;
    }
    return quality;
}

CoordinateMap tiled_coordinate_map(int width, int height, int sample_width, int sample_height)
{
    CoordinateMap map;
    map.info.levels = 1;
    CoordinateLevel level;
    level.width = std::max(width, 0);
    level.height = std::max(height, 0);
    level.sample_width = sample_width;
    level.sample_height = sample_height;
    level.coords.resize(2 * level.texels());
    if (sample_width > 0 && sample_height > 0)
        for (int y = 0; y < level.height; ++y)
            for (int x = 0; x < level.width; ++x) {
                const std::size_t t = static_cast<std::size_t>(y) * level.width + x;
                level.coords[2 * t] = x % sample_width;
                level.coords[2 * t + 1] = y % sample_height;
            }
    map.levels.push_back(std::move(level));
    return map;
}

}  // namespace cmfilter
