// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/math/fft.h"

#include <cassert>
#include <cmath>

namespace cmfilter {

std::size_t Fft::next_power_of_two(std::size_t n)
{
    std::size_t p = 1;
    while (p < n) p <<= 1;
    return p;
}

Fft::Fft(std::size_t n) : n_(n)
{
    assert(is_power_of_two(n));
    constexpr double kPi = 3.14159265358979323846;
    twiddles_.resize(n / 2);
    // Each twiddle from its own angle (no recurrence), so errors do not grow with n.
    for (std::size_t k = 0; k < n / 2; ++k)
        twiddles_[k] = std::polar(1.0, -2.0 * kPi * static_cast<double>(k) / static_cast<double>(n));
    for (std::size_t i = 1, j = 0; i < n; ++i) {
        std::size_t bit = n >> 1;
        for (; j & bit; bit >>= 1) j ^= bit;
        j ^= bit;
        if (i < j) {
            swaps_.push_back(i);
            swaps_.push_back(j);
        }
    }
}

void Fft::transform(std::complex<double>* data, bool inverse) const
{
    for (std::size_t s = 0; s < swaps_.size(); s += 2) std::swap(data[swaps_[s]], data[swaps_[s + 1]]);
    // Iterative Cooley-Tukey, decimation in time. The inverse uses conjugate
    // twiddles. Complex products are written out so that no NaN/Inf checks of
    // std::complex's operator* (C99 Annex G) sit in the inner loop.
    double* d = reinterpret_cast<double*>(data);
    const double sign = inverse ? -1.0 : 1.0;
    for (std::size_t half = 1; half < n_; half <<= 1) {
        const std::size_t stride = n_ / (2 * half);
        for (std::size_t start = 0; start < n_; start += 2 * half) {
            for (std::size_t k = 0; k < half; ++k) {
                const double wr = twiddles_[k * stride].real();
                const double wi = sign * twiddles_[k * stride].imag();
                double* a = d + 2 * (start + k);
                double* b = d + 2 * (start + k + half);
                const double br = b[0] * wr - b[1] * wi;
                const double bi = b[0] * wi + b[1] * wr;
                b[0] = a[0] - br;
                b[1] = a[1] - bi;
                a[0] += br;
                a[1] += bi;
            }
        }
    }
}

}  // namespace cmfilter
