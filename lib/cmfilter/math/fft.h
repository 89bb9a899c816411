// SPDX-License-Identifier: Apache-2.0
// A radix-2 complex fast Fourier transform in double precision, planned once
// per size and reused: the twiddle factors and the bit-reversal permutation
// are computed when the plan is made. It serves the cosine-series bake of
// Gaussian table rows (cosine_series_rows.h); nothing else needs an FFT yet.
//
//   forward:  X_j = sum_m x_m exp(-2 pi i m j / n)
//   inverse:  x_m = sum_j X_j exp(+2 pi i m j / n)   (unnormalised)
#pragma once

#include <complex>
#include <cstddef>
#include <vector>

namespace cmfilter {

class Fft {
public:
    // n must be a power of two, >= 1.
    explicit Fft(std::size_t n);

    std::size_t size() const { return n_; }
    void forward(std::complex<double>* data) const { transform(data, false); }
    void inverse(std::complex<double>* data) const { transform(data, true); }

    static bool is_power_of_two(std::size_t n) { return n != 0 && (n & (n - 1)) == 0; }
    static std::size_t next_power_of_two(std::size_t n);

private:
    void transform(std::complex<double>* data, bool inverse) const;

    std::size_t n_;
    std::vector<std::complex<double>> twiddles_;  // exp(-2 pi i k / n), k < n/2
    std::vector<std::size_t> swaps_;              // bit-reversal pairs (i, j), i < j, flattened
};

}  // namespace cmfilter
