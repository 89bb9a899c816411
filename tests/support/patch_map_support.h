// SPDX-License-Identifier: Apache-2.0
// Coordinate maps made by hand for the lookup tests and the LOD accuracy
// measurement, with no synthesis: a procedural sample image, one shifted
// copy of it, and maps of random rectangular patches (each patch one
// constant offset into the sample, as k-coherence synthesis copies pieces,
// Bosserhoff & Nicoll sec. 4.2).
#pragma once

#include "cmfilter/synthesis/coordinate_lookup.h"
#include "cmfilter/synthesis/coordinate_map.h"

#include <cmath>
#include <cstdint>
#include <random>

namespace cmfilter_test {

// Smooth periodic waves (whole periods over the sample) plus texel noise,
// so that a box mean, a bilinear read and a neighbouring piece all differ.
inline cmfilter::SampleImage procedural_sample(int width, int height, int channels, bool periodic,
                                               std::uint64_t seed = 7)
{
    cmfilter::SampleImage image;
    image.width = width;
    image.height = height;
    image.channels = channels;
    image.periodic = periodic;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double tau = 6.283185307179586;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < channels; ++c) {
                const double u = static_cast<double>(x) / width, v = static_cast<double>(y) / height;
                const double waves = 0.5 + 0.2 * std::sin(tau * ((1 + c) * u + 2 * v)) +
                                     0.15 * std::cos(tau * (3 * u - (c + 1) * v));
                image.pixels.push_back(static_cast<float>(waves + 0.3 * (unit(rng) - 0.5)));
            }
    return image;
}

inline cmfilter::CoordinateMap empty_map(int width, int height, int sample_width, int sample_height, bool periodic)
{
    cmfilter::CoordinateMap map;
    map.info.sample_periodic = periodic;
    cmfilter::CoordinateLevel level;
    level.width = width;
    level.height = height;
    level.sample_width = sample_width;
    level.sample_height = sample_height;
    level.coords.assign(level.texels() * 2, 0);
    map.levels.push_back(level);
    return map;
}

inline int wrap_index(long long v, int n)
{
    const long long r = v % n;
    return static_cast<int>(r < 0 ? r + n : r);
}

// Texels [x0, x1) x [y0, y1) of level 0 copy the sample from (sx, sy) on:
// c(p) = (sx + x - x0, sy + y - y0), wrapped into the sample.
inline void paste_patch(cmfilter::CoordinateMap& map, int x0, int y0, int x1, int y1, long long sx, long long sy)
{
    cmfilter::CoordinateLevel& level = map.levels[0];
    for (int y = std::max(0, y0); y < std::min(level.height, y1); ++y)
        for (int x = std::max(0, x0); x < std::min(level.width, x1); ++x) {
            const std::size_t t = static_cast<std::size_t>(y) * level.width + x;
            level.coords[2 * t] = wrap_index(sx + (x - x0), level.sample_width);
            level.coords[2 * t + 1] = wrap_index(sy + (y - y0), level.sample_height);
        }
}

// The whole output one copy of the sample shifted by (dx, dy): c(p) = p + d
// (wrapped into the sample).
inline cmfilter::CoordinateMap shifted_map(int width, int height, int sample_width, int sample_height, int dx, int dy,
                                           bool periodic)
{
    cmfilter::CoordinateMap map = empty_map(width, height, sample_width, sample_height, periodic);
    paste_patch(map, 0, 0, width, height, dx, dy);
    return map;
}

// Random rectangles of sides [min_side, max_side] laid over the output
// until covered and then as many again, each a piece of the sample at a
// random place (inside it, unless periodic: then anywhere, wrapping).
inline cmfilter::CoordinateMap random_patch_map(int width, int height, int sample_width, int sample_height,
                                                int min_side, int max_side, bool periodic, std::uint64_t seed)
{
    cmfilter::CoordinateMap map = empty_map(width, height, sample_width, sample_height, periodic);
    std::mt19937_64 rng(seed);
    const auto uniform = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    const auto piece = [&](int x0, int y0, int w, int h) {
        const int sx = periodic ? uniform(0, sample_width - 1) : uniform(0, std::max(0, sample_width - w));
        const int sy = periodic ? uniform(0, sample_height - 1) : uniform(0, std::max(0, sample_height - h));
        paste_patch(map, x0, y0, x0 + w, y0 + h, sx, sy);
    };
    for (int y = 0; y < height; y += max_side)
        for (int x = 0; x < width; x += max_side) piece(x, y, max_side, max_side);
    const double mean_side = 0.5 * (min_side + max_side);
    const int count = static_cast<int>(static_cast<double>(width) * height / (mean_side * mean_side));
    for (int n = 0; n < count; ++n) {
        const int w = uniform(min_side, max_side), h = uniform(min_side, max_side);
        piece(uniform(-w + 1, width - 1), uniform(-h + 1, height - 1), w, h);
    }
    return map;
}

// Root-mean-square and mean absolute difference of two images of one size.
struct ImageDifference {
    double rmse = 0, mean_abs = 0;
};
inline ImageDifference image_difference(const cmfilter::OutputImage& a, const cmfilter::OutputImage& b)
{
    ImageDifference d;
    const std::size_t n = a.pixels.size();
    for (std::size_t i = 0; i < n; ++i) {
        const double e = static_cast<double>(a.pixels[i]) - b.pixels[i];
        d.rmse += e * e;
        d.mean_abs += std::abs(e);
    }
    if (n > 0) {
        d.rmse = std::sqrt(d.rmse / n);
        d.mean_abs /= n;
    }
    return d;
}

}  // namespace cmfilter_test
