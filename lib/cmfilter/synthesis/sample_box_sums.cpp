// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/synthesis/sample_box_sums.h"

#include <algorithm>
#include <cstddef>

namespace cmfilter {

namespace {

// floor(a / b) and the remainder in [0, b), for b > 0.
void floor_divide(std::int64_t a, std::int64_t b, std::int64_t& q, std::int64_t& r)
{
    q = a / b;
    r = a % b;
    if (r < 0) {
        r += b;
        --q;
    }
}

// [x0, x0 + w) moved inside [0, n), cut to it when wider.
void keep_inside(std::int64_t& x0, std::int64_t& w, std::int64_t n)
{
    if (w >= n) {
        x0 = 0;
        w = n;
        return;
    }
    x0 = std::clamp<std::int64_t>(x0, 0, n - w);
}

}  // namespace

SampleBoxSums::SampleBoxSums(const SampleImage& image)
    : width_(image.width), height_(image.height), channels_(image.channels), periodic_(image.periodic)
{
    const std::size_t c = static_cast<std::size_t>(channels_);
    const std::size_t texels = static_cast<std::size_t>(width_) * height_;
    means_.assign(c, 0.0);
    for (std::size_t t = 0; t < texels; ++t)
        for (std::size_t k = 0; k < c; ++k) means_[k] += image.pixels[t * c + k];
    for (double& m : means_) m /= static_cast<double>(std::max<std::size_t>(texels, 1));

    const std::size_t row = static_cast<std::size_t>(width_ + 1) * c;
    table_.assign(row * (height_ + 1), 0.0);
    for (int y = 0; y < height_; ++y) {
        std::vector<double> running(c, 0.0);
        for (int x = 0; x < width_; ++x) {
            for (std::size_t k = 0; k < c; ++k) {
                running[k] += image.pixels[(static_cast<std::size_t>(y) * width_ + x) * c + k] - means_[k];
                table_[(y + 1) * row + (x + 1) * c + k] = table_[y * row + (x + 1) * c + k] + running[k];
            }
        }
    }
}

void SampleBoxSums::add_corner(std::int64_t x, std::int64_t y, double sign, double* acc) const
{
    // Over the periodic extension: x = qx W + rx, y = qy H + ry, the sum is
    // qx qy S(W, H) + qx S(W, ry) + qy S(rx, H) + S(rx, ry).
    std::int64_t qx = 0, rx = x, qy = 0, ry = y;
    if (periodic_) {
        floor_divide(x, width_, qx, rx);
        floor_divide(y, height_, qy, ry);
    }
    const std::size_t c = static_cast<std::size_t>(channels_);
    const std::size_t row = static_cast<std::size_t>(width_ + 1) * c;
    const auto s = [&](std::int64_t a, std::int64_t b, std::size_t k) {
        return table_[static_cast<std::size_t>(b) * row + static_cast<std::size_t>(a) * c + k];
    };
    for (std::size_t k = 0; k < c; ++k) {
        double v = s(rx, ry, k);
        if (qx != 0) v += static_cast<double>(qx) * s(width_, ry, k);
        if (qy != 0) v += static_cast<double>(qy) * s(rx, height_, k);
        if (qx != 0 && qy != 0) v += static_cast<double>(qx) * static_cast<double>(qy) * s(width_, height_, k);
        acc[k] += sign * v;
    }
}

void SampleBoxSums::box_mean(std::int64_t x0, std::int64_t y0, std::int64_t w, std::int64_t h, double* out) const
{
    if (!periodic_) {
        keep_inside(x0, w, width_);
        keep_inside(y0, h, height_);
    }
    for (int k = 0; k < channels_; ++k) out[k] = 0;
    add_corner(x0 + w, y0 + h, 1, out);
    add_corner(x0, y0 + h, -1, out);
    add_corner(x0 + w, y0, -1, out);
    add_corner(x0, y0, 1, out);
    const double area = static_cast<double>(w) * static_cast<double>(h);
    for (int k = 0; k < channels_; ++k) out[k] = means_[k] + out[k] / area;
}

}  // namespace cmfilter
