// SPDX-License-Identifier: Apache-2.0
// Exact box-mean MIP levels of an N-channel image, with the level geometry of
// a moment pyramid (docs/moments-format.md): level k is w_k x h_k =
// max(1, W >> k) x max(1, H >> k), and its texel (x, y) is the mean over the
// level-0 rectangle [x W / w_k, (x+1) W / w_k) x [y H / h_k, (y+1) H / h_k),
// each level-0 texel weighted by the area of it inside (fractional texels for
// sizes that are not powers of two), so every level holds means of level 0
// itself, never means of means.
//
// Level 0 is streamed past in row order: the caller fills each row's values
// (in double) and the accumulator builds every upper level from the same rows,
// horizontally from double-precision prefix sums with boundaries as exact
// rationals, vertically by exact integer overlaps. Only the upper levels (1/3
// of the texels) are kept, as float32.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

namespace cmfilter {

// Extent of level k along an axis of `extent` level-0 texels: max(1, extent >> k).
int box_level_extent(int extent, int level);
// Levels down to 1 x 1: floor(log2(max(width, height))) + 1.
int box_level_count(int width, int height);

class BoxPyramidAccumulator {
public:
    // channels >= 1; threads as parallel_for (0: all cores).
    BoxPyramidAccumulator(int width, int height, int channels, int threads);

    // Fills level-0 row y: planes[c * width + x] = channel c of texel x.
    // Called concurrently for different rows (thread is 0 .. threads-1).
    using RowFill = std::function<void(int y, int thread, double* planes)>;

    // Adds level-0 rows [y0, y1); successive calls must continue where the
    // previous one ended (row 0 first).
    void add_rows(int y0, int y1, const RowFill& fill);

    int levels() const { return static_cast<int>(upper_.size()) + 1; }
    int channels() const { return channels_; }
    int level_width(int k) const { return box_level_extent(width_, k); }
    int level_height(int k) const { return box_level_extent(height_, k); }
    // Level k >= 1, complete once every row was added: w_k * h_k * channels
    // floats, channels interleaved, top row first. take_level moves it out.
    const std::vector<float>& level(int k) const { return upper_[k - 1].texels; }
    std::vector<float> take_level(int k) { return std::move(upper_[k - 1].texels); }

private:
    struct Upper {
        int w = 0, h = 0;
        std::vector<float> texels;
        std::vector<double> acc;  // one output row being accumulated, channel planes
        int y = 0;                // output row being accumulated
        void add_row(int r, int H, int channels, double inv_area, const double* integrals);
    };
    int width_, height_, channels_, threads_;
    std::vector<Upper> upper_;
    std::vector<std::size_t> offset_;        // of each level in a row's integrals
    std::vector<std::vector<double>> work_;  // per thread: planes and prefix sums
    std::vector<double> integrals_;          // per batch row, per level: channel planes
};

}  // namespace cmfilter
