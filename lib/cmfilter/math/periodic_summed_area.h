// SPDX-License-Identifier: Apache-2.0
// A summed-area table over one repeat of a periodic N x N grid of cells, each
// holding the same number of channels: the exact mean of the
// piecewise-constant cells over any axis-aligned box, of any size and
// anywhere on the plane. Each channel is centred on its mean over the repeat
// before summing, so whole repeats add nothing and a box far from the origin
// or many repeats wide keeps its precision (Crow 1984; the periodic split as
// in displacement_texture.h's footprints).
#pragma once

#include <vector>

namespace cmfilter {

class PeriodicSummedArea {
public:
    static constexpr int kMaxChannels = 96;
    PeriodicSummedArea() = default;
    // cells: N x N x channels, row-major, channels interleaved; N >= 1,
    // 1 <= channels <= kMaxChannels.
    PeriodicSummedArea(const std::vector<double>& cells, int n, int channels);

    int size() const { return n_; }
    int channels() const { return channels_; }
    // Each channel's mean over the repeat.
    const std::vector<double>& means() const { return means_; }
    // The mean of each channel over [x0, x0 + wx] x [y0, y0 + wy] (cells;
    // any reals, wx and wy > 0) into out[0 .. channels).
    void box_mean(double x0, double y0, double wx, double wy, double* out) const;

private:
    int n_ = 0, channels_ = 0;
    std::vector<double> means_;
    std::vector<double> table_;  // (N + 1)^2 x channels, of the centred cells
    void at(double x, double y, double* out) const;
    void integral(double x, double y, double* out) const;
};

}  // namespace cmfilter
