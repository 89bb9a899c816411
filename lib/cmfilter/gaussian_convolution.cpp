#include "cmfilter/gaussian_convolution.h"

#include <algorithm>
#include <cmath>

namespace cmfilter {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInvSqrt2 = 0.70710678118654752440;
constexpr double kInvSqrt2Pi = 0.39894228040143267794;
// Steps beyond kTail standard deviations are folded into a constant: the
// neglected Gaussian mass is Phi(-9) = 1.13e-19 per side.
constexpr double kTail = 9.0;

// R(d) = E[max(0, d + s Z)] = d Phi(d/s) + s phi(d/s), Z ~ N(0, 1).
inline double ramp_convolution(double d, double s)
{
    const double t = d / s;
    const double cdf = 0.5 * std::erfc(-t * kInvSqrt2);
    const double pdf = kInvSqrt2Pi * std::exp(-0.5 * t * t);
    return d * cdf + s * pdf;
}

}  // namespace

GaussianConvolution::GaussianConvolution(const ColorMap& map, double sigma)
    : map_(&map), s_(std::max(0.0, sigma) / map.texel_width())
{
    if (map.wrap == WrapMode::Clamp || s_ == 0.0) return;
    period_ = map.wrap == WrapMode::Repeat ? map.size() : 2.0 * map.size();
    // Fourier pays off once the step sum would cover more than a few periods.
    if (2.0 * kTail * s_ < 4.0 * period_) return;
    use_fourier_ = true;

    // Periodic node values c_k, k = 0..p-1, and their mean (harmonic 0:
    // sinc^2(0) = 1, so the mean of the piecewise-linear map is the node mean).
    const long p = static_cast<long>(period_);
    for (long k = 0; k < p; ++k) mean_ += map.node(k);
    mean_ = (1.0 / p) * mean_;
    // Harmonic m survives the Gaussian with weight exp(-2 pi^2 m^2 s^2 / p^2);
    // stop once that is below 1e-18 (exp(-41.4)).
    const double decay = 2.0 * kPi * kPi * s_ * s_ / (period_ * period_);
    for (long m = 1; decay * m * m < 41.5; ++m) {
        const double damping = std::exp(-decay * m * m);
        const double xi = static_cast<double>(m) / period_;
        const double sinc = std::sin(kPi * xi) / (kPi * xi);
        std::complex<double> acc[3];
        for (long k = 0; k < p; ++k) {
            const std::complex<double> e = std::polar(1.0, -2.0 * kPi * xi * k);
            const Rgb& c = map.node(k);
            for (int ch = 0; ch < 3; ++ch) acc[ch] += c[ch] * e;
        }
        for (int ch = 0; ch < 3; ++ch)
            harmonics_[ch].push_back(acc[ch] * (sinc * sinc * damping / period_));
    }
}

Rgb GaussianConvolution::operator()(double v) const
{
    const double x = map_->node_coordinate(v);
    if (s_ == 0.0 || !std::isfinite(x)) return map_->evaluate(v);
    return use_fourier_ ? fourier_series(x) : sum_of_steps(x);
}

Rgb GaussianConvolution::sum_of_steps(double x) const
{
    const long n = map_->size();
    const ColorMap& map = *map_;
    // For clamp, fold x far outside the nodes back to where the map is constant.
    double xc = x;
    if (map.wrap == WrapMode::Clamp) xc = std::clamp(x, -kTail * s_ - 2.0, n + 1.0 + kTail * s_);
    long k_lo = static_cast<long>(std::floor(xc - kTail * s_));
    long k_hi = static_cast<long>(std::ceil(xc + kTail * s_));
    Rgb result = map.node(k_lo);
    if (map.wrap == WrapMode::Clamp) {
        // Steps are zero outside nodes 0..n-1.
        k_lo = std::max(k_lo, 0L);
        k_hi = std::min(k_hi, n - 1);
    }
    if (k_lo >= k_hi) return result;
    double r_prev = ramp_convolution(xc - k_lo, s_);
    for (long k = k_lo; k < k_hi; ++k) {
        const double r_next = ramp_convolution(xc - k - 1, s_);
        const double step = r_prev - r_next;  // (S * N)(x - k)
        r_prev = r_next;
        result += step * (map.node(k + 1) - map.node(k));
    }
    return result;
}

Rgb GaussianConvolution::fourier_series(double x) const
{
    double out[3] = {mean_.r, mean_.g, mean_.b};
    const double xi0 = 2.0 * kPi * x / period_;
    for (std::size_t i = 0; i < harmonics_[0].size(); ++i) {
        const std::complex<double> e = std::polar(1.0, xi0 * static_cast<double>(i + 1));
        for (int ch = 0; ch < 3; ++ch) out[ch] += 2.0 * (harmonics_[ch][i] * e).real();
    }
    return {out[0], out[1], out[2]};
}

}  // namespace cmfilter
