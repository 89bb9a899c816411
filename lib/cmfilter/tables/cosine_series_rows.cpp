// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/tables/cosine_series_rows.h"

#include "cmfilter/util/parallel_for.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <complex>
#include <limits>

namespace cmfilter {

namespace {

constexpr double kPi = 3.14159265358979323846;
// Gaussian tail left out beyond 9 sigma: Phi(-9) = 1.13e-19 per side.
constexpr double kTail = 9.0;

}  // namespace

CosineSeriesRows::CosineSeriesRows(const ColorMap& map, double first, double step, int count, double sigma_max)
    : map_(&map), count_(count), sigma_max_(sigma_max)
{
    assert(map.wrap == WrapMode::Clamp && step > 0 && count >= 1);
    const long n = map.size();
    const double w = map.texel_width();
    const double x_first = map.vmin + 0.5 * w;       // first texel centre
    const double x_last = map.vmin + (n - 0.5) * w;  // last texel centre
    const double last = first + (count - 1) * step;  // last value node
    // f = C0 on [2a - x_first, 2b - x_last] must hold every node +- 9 sigma_max:
    //   a <= (first - 9 sigma_max + x_first) / 2,  b >= (last + 9 sigma_max + x_last) / 2.
    const double reach = kTail * sigma_max;
    const double a_max = 0.5 * (first - reach + x_first);
    const double b_min = 0.5 * (last + reach + x_last);
    J_ = std::max(0, static_cast<int>(std::ceil((first - a_max) / step)));
    const int right = std::max(0, static_cast<int>(std::ceil((b_min - last) / step)));
    const std::size_t k_min = static_cast<std::size_t>(J_) + (count - 1) + right;
    K_ = static_cast<int>(Fft::next_power_of_two(std::max<std::size_t>(k_min, 2)));
    window_ = K_ * step;
    start_ = first - J_ * step;

    // Slope changes kappa_k (per unit of v) at texel centre k.
    kappa_.resize(n);
    for (long k = 0; k < n; ++k) {
        const Rgb right_slope = k + 1 < n ? (1.0 / w) * (map.texels[k + 1] - map.texels[k]) : Rgb{};
        const Rgb left_slope = k > 0 ? (1.0 / w) * (map.texels[k] - map.texels[k - 1]) : Rgb{};
        kappa_[k] = right_slope - left_slope;
    }
    double sums[3] = {0, 0, 0};
    for (const Rgb& kp : kappa_)
        for (int c = 0; c < 3; ++c) sums[c] += std::abs(kp[c]);
    kappa_sum_ = std::max({sums[0], sums[1], sums[2]});
}

double CosineSeriesRows::row_cost() const
{
    // Measured: about 2.2 ns per K log2 K on the FFT and its O(K) set-up, a
    // ramp evaluation (erfc + exp) about 30 ns.
    const double K = static_cast<double>(K_);
    return 0.073 * K * std::log2(K);
}

void CosineSeriesRows::compute_coefficients(int threads)
{
    const ColorMap& map = *map_;
    const long n = map.size();
    const double w = map.texel_width();
    const double x_first = map.vmin + 0.5 * w;
    const double x_last = map.vmin + (n - 0.5) * w;
    const double a = start_, b = start_ + window_;

    // a_0: the mean of C0 over [a, b] (trapezoids between texel centres are exact).
    Rgb integral = (x_first - a) * map.texels.front() + (b - x_last) * map.texels.back();
    for (long k = 0; k + 1 < n; ++k) integral += (0.5 * w) * (map.texels[k] + map.texels[k + 1]);
    for (int c = 0; c < 3; ++c) {
        coefficients_[c].assign(K_ + 1, 0.0);
        coefficients_[c][0] = integral[c] / window_;
    }

    // sum_k kappa_k cos(w_m (x_k - a)) for m = 1..K: each kink advances its
    // phase by a rotation, renewed from the exact angle every 64 harmonics so
    // that rounding cannot accumulate.
    std::vector<double> sum(3 * (K_ + 1), 0.0);
    std::vector<long> kinks;
    for (long k = 0; k < n; ++k)
        if (kappa_[k].r != 0.0 || kappa_[k].g != 0.0 || kappa_[k].b != 0.0) kinks.push_back(k);
    constexpr int kChunk = 256;  // harmonics per parallel task
    parallel_for((K_ + kChunk - 1) / kChunk, threads, [&](int chunk) {
        const int m_first = 1 + chunk * kChunk;
        const int m_last = std::min(K_, m_first + kChunk - 1);
        for (long k : kinks) {
            const Rgb& kp = kappa_[k];
            const double phase = kPi * (x_first + k * w - a) / window_;
            const std::complex<double> rotation = std::polar(1.0, phase);
            std::complex<double> z;
            for (int m = m_first; m <= m_last; ++m) {
                if ((m - m_first) % 64 == 0) z = std::polar(1.0, phase * m);
                else z *= rotation;
                const double cosine = z.real();
                sum[3 * m + 0] += kp.r * cosine;
                sum[3 * m + 1] += kp.g * cosine;
                sum[3 * m + 2] += kp.b * cosine;
            }
        }
    });
    for (int m = 1; m <= K_; ++m) {
        const double wm = kPi * m / window_;
        const double scale = -2.0 / (window_ * wm * wm);
        for (int c = 0; c < 3; ++c) coefficients_[c][m] = scale * sum[3 * m + c];
    }

    fft_ = Fft(static_cast<std::size_t>(K_));
    cosines_.resize(K_ + 1);
    sines_.resize(K_ + 1);
    for (int m = 0; m <= K_; ++m) {
        cosines_[m] = std::cos(kPi * m / K_);
        sines_[m] = std::sin(kPi * m / K_);
    }
}

double CosineSeriesRows::error_bound(double sigma) const
{
    if (!(sigma > 0) || sigma > sigma_max_) return std::numeric_limits<double>::infinity();
    // |a_m| <= 2 W sum|kappa| / (pi^2 m^2); the dropped harmonics m > K have
    // damping exp(-beta m^2), beta = pi^2 sigma^2 / (2 W^2), and their ratio
    // to the previous one is below exp(-beta (2K + 3)):
    //   sum_{m>K} |a_m| exp(-beta m^2) <= 2 W sum|kappa| / pi^2
    //        * exp(-beta (K+1)^2) / (K+1)^2 / (1 - exp(-beta (2K + 3))).
    const double beta = kPi * kPi * sigma * sigma / (2.0 * window_ * window_);
    const double K = static_cast<double>(K_);
    const double k1 = K + 1.0;
    const double ratio = std::exp(-beta * (2.0 * K + 3.0));
    if (ratio >= 1.0) return std::numeric_limits<double>::infinity();
    return 2.0 * window_ * kappa_sum_ / (kPi * kPi) * std::exp(-beta * k1 * k1) / (k1 * k1) / (1.0 - ratio);
}

void CosineSeriesRows::evaluate(double sigma_a, float* out_a, double sigma_b, float* out_b) const
{
    assert(!coefficients_[0].empty());
    // For each channel the damped coefficients b_m = a_m exp(-w_m^2 sigma^2 / 2)
    // give y_j = sum_{m=0}^{K} b_m cos(pi m j / K), j = 0..K (a DCT-I), from
    // the real sequence of length K
    //   v_m = (b_m + b_{K-m}) / 2 - sin(pi m / K) (b_m - b_{K-m})
    // and its DFT V_j = sum_m v_m exp(-2 pi i m j / K):
    //   y_{2j} = Re V_j + (b_0 + b_K) / 2,   y_{2j+1} = y_{2j-1} - Im V_j,
    //   y_1 = sum_m b_m cos(pi m / K).
    // Six real sequences (two rows, three channels) go through three complex
    // FFTs, two per transform: z = v + i v', V_j = (Z_j + conj Z_{K-j}) / 2,
    // V'_j = (Z_j - conj Z_{K-j}) / 2i.
    const std::size_t K = static_cast<std::size_t>(K_);
    const int rows = out_b ? 2 : 1;
    const double sigmas[2] = {sigma_a, sigma_b};
    float* outs[2] = {out_a, out_b};
    std::vector<double> b(K + 1), damping(K + 1);
    std::vector<double> v(6 * K, 0.0);  // sequence 3 row + channel
    double y0_shift[6] = {}, y1[6] = {};
    for (int r = 0; r < rows; ++r) {
        // exp(-w_m^2 sigma^2 / 2) = exp(-beta m^2) by the recurrence
        // d_{m+1} = d_m q_m, q_{m+1} = q_m exp(-2 beta), restarted from exp()
        // every 64 harmonics (relative error < 1e-14); past its underflow the
        // harmonics stay zero.
        const double beta = kPi * kPi * sigmas[r] * sigmas[r] / (2.0 * window_ * window_);
        std::size_t m_end = K + 1;
        const double q_step = std::exp(-2.0 * beta);
        double d = 1.0, q = 1.0;
        for (std::size_t m = 0; m <= K; ++m) {
            if (m % 64 == 0) {
                const double md = static_cast<double>(m);
                d = std::exp(-beta * md * md);
                q = std::exp(-beta * (2.0 * md + 1.0));
            }
            if (d == 0.0) {
                m_end = m;
                break;
            }
            damping[m] = d;
            d *= q;
            q *= q_step;
        }
        for (int c = 0; c < 3; ++c) {
            const std::vector<double>& a = coefficients_[c];
            for (std::size_t m = 0; m < m_end; ++m) b[m] = a[m] * damping[m];
            std::fill(b.begin() + m_end, b.end(), 0.0);
            const int seq = 3 * r + c;
            double* vs = v.data() + seq * K;
            double first = 0;
            for (std::size_t m = 0; m < m_end; ++m) first += b[m] * cosines_[m];
            y1[seq] = first;
            y0_shift[seq] = 0.5 * (b[0] + b[K]);
            for (std::size_t m = 0; m < K; ++m) vs[m] = 0.5 * (b[m] + b[K - m]) - sines_[m] * (b[m] - b[K - m]);
        }
    }
    std::vector<std::complex<double>> z(K);
    std::vector<double> y(K + 1);
    for (int pair = 0; pair < 3 * rows; pair += 2) {
        const int s0 = pair, s1 = pair + 1 < 3 * rows ? pair + 1 : -1;
        for (std::size_t m = 0; m < K; ++m) z[m] = {v[s0 * K + m], s1 >= 0 ? v[s1 * K + m] : 0.0};
        fft_.forward(z.data());
        for (int which = 0; which < 2; ++which) {
            const int seq = which == 0 ? s0 : s1;
            if (seq < 0) break;
            double odd = y1[seq];
            y[1] = odd;
            for (std::size_t j = 0; j <= K / 2; ++j) {
                const std::complex<double> zj = z[j], zk = std::conj(z[(K - j) % K]);
                const std::complex<double> V = which == 0 ? 0.5 * (zj + zk)
                                                          : std::complex<double>(0.0, -0.5) * (zj - zk);
                y[2 * j] = V.real() + y0_shift[seq];
                if (j > 0 && 2 * j + 1 <= K) {
                    odd -= V.imag();
                    y[2 * j + 1] = odd;
                }
            }
            float* out = outs[seq / 3];
            const int c = seq % 3;
            for (int i = 0; i < count_; ++i) out[3 * i + c] = static_cast<float>(y[J_ + i]);
        }
    }
}

}  // namespace cmfilter
