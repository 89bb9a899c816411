// SPDX-License-Identifier: Apache-2.0
// A scene-linear RGB triple, the colour type shared by maps, tables and metrics.
#pragma once

namespace cmfilter {

struct Rgb {
    double r = 0, g = 0, b = 0;

    Rgb& operator+=(const Rgb& o)
    {
        r += o.r;
        g += o.g;
        b += o.b;
        return *this;
    }
    Rgb& operator-=(const Rgb& o)
    {
        r -= o.r;
        g -= o.g;
        b -= o.b;
        return *this;
    }
    friend Rgb operator+(Rgb a, const Rgb& b) { return a += b; }
    friend Rgb operator-(Rgb a, const Rgb& b) { return a -= b; }
    friend Rgb operator*(double s, const Rgb& c) { return {s * c.r, s * c.g, s * c.b}; }
    double operator[](int i) const { return i == 0 ? r : (i == 1 ? g : b); }
};

}  // namespace cmfilter
