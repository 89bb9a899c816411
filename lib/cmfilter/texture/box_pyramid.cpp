// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/texture/box_pyramid.h"

#include "cmfilter/util/parallel_for.h"

#include <algorithm>
#include <cstdint>

namespace cmfilter {

namespace {

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

}  // namespace

int box_level_extent(int extent, int level) { return level >= 31 ? 1 : std::max(1, extent >> level); }

int box_level_count(int width, int height)
{
    int levels = 1;
    for (int e = std::max(width, height); e > 1; e >>= 1) ++levels;
    return levels;
}

// Level-0 row r spans [r, r+1), output row y spans [y H / h, (y+1) H / h); in
// units of 1/h these are [r h, (r+1) h) and [y H, (y+1) H), so overlaps are
// exact integers. Since h <= H a level-0 row touches at most two output rows.
void BoxPyramidAccumulator::Upper::add_row(int r, int H, int channels, double inv_area, const double* integrals)
{
    const std::size_t n = static_cast<std::size_t>(w) * channels;
    std::int64_t lo = static_cast<std::int64_t>(r) * h;
    const std::int64_t hi = lo + h;
    while (lo < hi) {
        const std::int64_t end = static_cast<std::int64_t>(y + 1) * H;
        const std::int64_t seg = std::min(hi, end);
        const double weight = static_cast<double>(seg - lo) / h;  // in level-0 rows
        for (std::size_t i = 0; i < n; ++i) acc[i] += weight * integrals[i];
        lo = seg;
        if (seg == end) {  // output row y is complete: divide by its area
            float* out = texels.data() + static_cast<std::size_t>(y) * n;
            for (int x = 0; x < w; ++x)
                for (int c = 0; c < channels; ++c)
                    out[static_cast<std::size_t>(x) * channels + c] =
                        static_cast<float>(acc[static_cast<std::size_t>(c) * w + x] * inv_area);
            std::fill(acc.begin(), acc.end(), 0.0);
            ++y;
        }
    }
}

BoxPyramidAccumulator::BoxPyramidAccumulator(int width, int height, int channels, int threads)
    : width_(width), height_(height), channels_(channels), threads_(resolve_thread_count(threads))
{
    const int levels = box_level_count(width, height);
    upper_.resize(levels - 1);
    offset_.assign(upper_.size() + 1, 0);
    for (std::size_t k = 0; k < upper_.size(); ++k) {
        Upper& L = upper_[k];
        L.w = box_level_extent(width, static_cast<int>(k) + 1);
        L.h = box_level_extent(height, static_cast<int>(k) + 1);
        L.texels.assign(static_cast<std::size_t>(L.w) * L.h * channels, 0.0f);
        L.acc.assign(static_cast<std::size_t>(L.w) * channels, 0.0);
        offset_[k + 1] = offset_[k] + static_cast<std::size_t>(channels) * L.w;
    }
    // Per thread: the row's channel planes, then one prefix-sum array (W + 1).
    work_.assign(threads_, std::vector<double>(static_cast<std::size_t>(width) * channels + width + 1));
}

void BoxPyramidAccumulator::add_rows(int y0, int y1, const RowFill& fill)
{
    const int rows = y1 - y0;
    if (rows <= 0) return;
    const std::size_t row_size = offset_.back();
    integrals_.resize(row_size * rows);
    const int W = width_;
    // Each row's values and the horizontal box integrals for every level
    // (parallel over rows).
    parallel_for(std::min(threads_, rows), threads_, [&](int t) {
        for (int i = t; i < rows; i += threads_) {
            double* planes = work_[t].data();
            double* prefix = planes + static_cast<std::size_t>(W) * channels_;
            fill(y0 + i, t, planes);
            double* row = integrals_.data() + static_cast<std::size_t>(i) * row_size;
            for (int c = 0; c < channels_; ++c) {
                const double* g = planes + static_cast<std::size_t>(c) * W;
                prefix[0] = 0;
                for (int x = 0; x < W; ++x) prefix[x + 1] = prefix[x] + g[x];
                for (std::size_t k = 0; k < upper_.size(); ++k)
                    box_integrals(prefix, g, W, upper_[k].w,
                                  row + offset_[k] + static_cast<std::size_t>(c) * upper_[k].w);
            }
        }
    });
    // Vertical accumulation, rows in order within each level (parallel over levels).
    parallel_for(static_cast<int>(upper_.size()), threads_, [&](int k) {
        Upper& L = upper_[k];
        const double inv_area = static_cast<double>(L.w) * L.h / (static_cast<double>(W) * height_);
        for (int r = y0; r < y1; ++r)
            L.add_row(r, height_, channels_, inv_area,
                      integrals_.data() + static_cast<std::size_t>(r - y0) * row_size + offset_[k]);
    });
}

}  // namespace cmfilter
