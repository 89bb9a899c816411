// SPDX-License-Identifier: Apache-2.0
// A summed-area table of one sample image (Crow 1984), in double, for the
// exact mean of the sample over any box of whole texels: the patch lookups
// of coordinate_lookup.h read each piece's footprint box from it. A periodic
// sample tiles the plane, so a box anywhere (and of any size) wraps; a box
// that runs off a non-periodic sample is moved back inside it (and cut to
// the sample where it is wider). Rectangular samples of any size; each
// channel is centred on its mean before summing, as periodic_summed_area.h
// does, so that long sums keep their precision.
#pragma once

#include "cmfilter/synthesis/sample_image.h"

#include <cstdint>
#include <vector>

namespace cmfilter {

class SampleBoxSums {
public:
    explicit SampleBoxSums(const SampleImage& image);

    int width() const { return width_; }
    int height() const { return height_; }
    int channels() const { return channels_; }
    // The mean of each channel over [x0, x0 + w) x [y0, y0 + h), w, h >= 1,
    // into out[0 .. channels).
    void box_mean(std::int64_t x0, std::int64_t y0, std::int64_t w, std::int64_t h, double* out) const;
    // What a renderer uploads to read the same box means in a shader
    // (shaders/cmfilter_coordinate_map.glsl): each channel's mean, and the
    // table, (width + 1) x (height + 1) x channels, element
    // (y (width + 1) + x) channels + k the sum of channel k minus its mean
    // over [0, x) x [0, y).
    const std::vector<double>& means() const { return means_; }
    const std::vector<double>& table() const { return table_; }

private:
    int width_ = 0, height_ = 0, channels_ = 0;
    bool periodic_ = false;
    std::vector<double> means_;
    std::vector<double> table_;  // (width + 1) x (height + 1) x channels: sums over [0, x) x [0, y)
    // Adds sign * the sum over [0, x) x [0, y) of the (periodic) sample.
    void add_corner(std::int64_t x, std::int64_t y, double sign, double* acc) const;
};

}  // namespace cmfilter
