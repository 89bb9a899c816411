// SPDX-License-Identifier: Apache-2.0
// The radix-2 FFT against the DFT summed term by term in long double.
#include "cmfilter/math/fft.h"

#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <random>
#include <vector>

using cmfilter::Fft;

namespace {

std::vector<std::complex<long double>> naive_dft(const std::vector<std::complex<double>>& x, int sign)
{
    const std::size_t n = x.size();
    const long double pi = 3.141592653589793238462643383279502884L;
    std::vector<std::complex<long double>> y(n);
    for (std::size_t j = 0; j < n; ++j)
        for (std::size_t m = 0; m < n; ++m) {
            const long double angle = sign * 2.0L * pi * static_cast<long double>((m * j) % n) / n;
            y[j] += std::complex<long double>(x[m]) * std::complex<long double>(std::cos(angle), std::sin(angle));
        }
    return y;
}

}  // namespace

TEST_CASE("forward and inverse FFT equal the DFT for every power-of-two size up to 1024")
{
    std::mt19937_64 rng(7);
    std::normal_distribution<double> normal;
    for (std::size_t n = 1; n <= 1024; n *= 2) {
        std::vector<std::complex<double>> x(n);
        for (auto& v : x) v = {normal(rng), normal(rng)};
        const Fft fft(n);
        for (int sign : {-1, +1}) {
            std::vector<std::complex<double>> y = x;
            if (sign < 0) fft.forward(y.data());
            else fft.inverse(y.data());
            const auto ref = naive_dft(x, sign);
            double worst = 0;
            for (std::size_t j = 0; j < n; ++j)
                worst = std::max(worst, static_cast<double>(std::abs(std::complex<long double>(y[j]) - ref[j])));
            CAPTURE(n);
            CAPTURE(sign);
            // Rounding of a radix-2 FFT grows like eps sqrt(n) log2(n) |x|; |x| ~ sqrt(n) here.
            CHECK(worst < 1e-12);
        }
    }
}

TEST_CASE("next_power_of_two and is_power_of_two")
{
    CHECK(Fft::next_power_of_two(1) == 1);
    CHECK(Fft::next_power_of_two(3) == 4);
    CHECK(Fft::next_power_of_two(408) == 512);
    CHECK(Fft::next_power_of_two(512) == 512);
    CHECK(Fft::is_power_of_two(1024));
    CHECK_FALSE(Fft::is_power_of_two(0));
    CHECK_FALSE(Fft::is_power_of_two(768));
}
