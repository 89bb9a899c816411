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
    if (s_ == 0.0) return;
    // Non-zero steps C(k+1) - C(k): over nodes 0..n-1 (clamp) or one period.
    period_ = map.wrap == WrapMode::Clamp ? 0.0
              : map.wrap == WrapMode::Repeat ? map.size() : 2.0 * map.size();
    const long last = map.wrap == WrapMode::Clamp ? map.size() - 1 : static_cast<long>(period_);
    for (long k = 0; k < last; ++k) {
        const Rgb delta = map.node(k + 1) - map.node(k);
        if (delta.r != 0.0 || delta.g != 0.0 || delta.b != 0.0) steps_.push_back({k, delta});
    }
    if (map.wrap == WrapMode::Clamp) return;
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
    const ColorMap& map = *map_;
    const long n = map.size();
    // For clamp, fold x far outside the nodes back to where the map is constant.
    double xc = x;
    if (map.wrap == WrapMode::Clamp) xc = std::clamp(x, -kTail * s_ - 2.0, n + 1.0 + kTail * s_);
    const long k_lo = static_cast<long>(std::floor(xc - kTail * s_));
    const long k_hi = static_cast<long>(std::ceil(xc + kTail * s_));
    Rgb result = map.node(k_lo);

    // Steps k in [k_lo, k_hi): the non-zero ones only, repeated every period
    // for periodic maps. Adjacent steps share one ramp evaluation.
    const long period = map.wrap == WrapMode::Clamp ? 0 : static_cast<long>(period_);
    long base = 0;
    if (period > 0) base = (k_lo >= 0 ? k_lo / period : -((-k_lo + period - 1) / period)) * period;
    long last_k = k_lo - 2;
    double r_last = 0;
    for (; base < k_hi; base += period) {
        auto it = steps_.begin();
        if (period == 0 || base < k_lo)
            it = std::lower_bound(steps_.begin(), steps_.end(), k_lo - base,
                                  [](const Step& st, long k) { return st.k < k; });
        for (; it != steps_.end(); ++it) {
            const long k = base + it->k;
            if (k >= k_hi) break;
            const double r_here = k == last_k + 1 ? r_last : ramp_convolution(xc - k, s_);
            const double r_next = ramp_convolution(xc - k - 1, s_);
            result += (r_here - r_next) * it->delta;  // (S * N)(x - k) [C(k+1) - C(k)]
            last_k = k;
            r_last = r_next;
        }
        if (period == 0) break;
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
