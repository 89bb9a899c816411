// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/tables/gaussian_convolution.h"

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

// The step sum evaluates each non-zero step within 9 s (twice when steps are
// isolated); density = non-zero steps per node.
double step_sum_cost(double density, double s)
{
    return density * (2.0 * kTail * s + 1.0) * (density < 0.5 ? 2.0 : 1.0);
}

// A kink block in reach costs one erfc and one exp (about one step
// evaluation) plus kTaylorTerms Hermite terms (about 0.055 step evaluations each).
constexpr double kBlockCost = 1.0 + 0.055 * GaussianConvolution::kTaylorTerms;

}  // namespace

double GaussianConvolution::estimated_cost(const ColorMap& map, double sigma)
{
    const double s = std::max(0.0, sigma) / map.texel_width();
    if (s == 0.0) return 0.0;
    const long n = map.size();
    const double period = map.wrap == WrapMode::Clamp ? 0.0 : map.wrap == WrapMode::Repeat ? n : 2.0 * n;
    if (map.wrap != WrapMode::Clamp && 2.0 * kTail * s >= 4.0 * period) {
        // Fourier series: harmonics until exp(-2 pi^2 m^2 s^2 / p^2) < 1e-18.
        return 0.1 * period * std::sqrt(41.5 / (2.0 * kPi * kPi)) / s + 1.0;
    }
    const long last = map.wrap == WrapMode::Clamp ? n - 1 : static_cast<long>(period);
    long steps = 0;
    for (long k = 0; k < last; ++k) {
        const Rgb delta = map.node(k + 1) - map.node(k);
        if (delta.r != 0.0 || delta.g != 0.0 || delta.b != 0.0) ++steps;
    }
    const double density = static_cast<double>(steps) / std::max(1.0, static_cast<double>(last));
    double cost = step_sum_cost(density, s);
    if (s >= kBlockMinSigma) {
        const double blocks = std::min(static_cast<double>(steps) + 1.0, (2.0 * kTail + 1.0) / kBlockWidth + 1.0);
        cost = std::min(cost, kBlockCost * blocks);
    }
    return cost;
}

GaussianConvolution::GaussianConvolution(const ColorMap& map, double sigma)
    : map_(&map), s_(std::max(0.0, sigma) / map.texel_width())
{
    if (s_ == 0.0) return;
    // Non-zero steps C(k+1) - C(k): over nodes 0..n-1 (clamp) or one period.
    period_ = map.wrap == WrapMode::Clamp ? 0.0 : map.wrap == WrapMode::Repeat ? map.size() : 2.0 * map.size();
    const long last = map.wrap == WrapMode::Clamp ? map.size() - 1 : static_cast<long>(period_);
    for (long k = 0; k < last; ++k) {
        const Rgb delta = map.node(k + 1) - map.node(k);
        if (delta.r != 0.0 || delta.g != 0.0 || delta.b != 0.0) steps_.push_back({k, delta});
    }
    // Fourier pays off once the step sum would cover more than a few periods.
    if (map.wrap != WrapMode::Clamp && 2.0 * kTail * s_ >= 4.0 * period_) {
        build_fourier_series();
        return;
    }
    if (s_ >= kBlockMinSigma) build_kink_blocks();
}

void GaussianConvolution::build_kink_blocks()
{
    // C0(y) = C(lo) + sum_k kappa_k max(0, y - k) on [lo, hi], constant beyond;
    // kappa_k = [C(k+1) - C(k)] - [C(k) - C(k-1)] are the slope changes. For
    // clamp [lo, hi] = [0, n-1] is exact; a periodic map is unrolled far
    // enough (9 s beyond one period each side) for any x wrapped into one period.
    const ColorMap& map = *map_;
    const long n = map.size();
    long lo = 0, hi = n - 1;
    if (map.wrap != WrapMode::Clamp) {
        const long reach = static_cast<long>(std::ceil(kTail * s_)) + 2;
        lo = -reach;
        hi = static_cast<long>(period_) + reach;
    }
    // B <= 3 s: every kink within h = 1.5 s of its block centre.
    const long width = std::max(1L, static_cast<long>(std::floor(kBlockWidth * s_)));

    // The non-zero slope changes, and how many blocks they fall in.
    struct Kink {
        long k;
        Rgb kappa;
    };
    std::vector<Kink> kinks;
    std::size_t occupied_blocks = 0;
    Rgb previous;  // C(k) - C(k-1), zero left of lo
    for (long k = lo; k <= hi; ++k) {
        const Rgb next = k < hi ? map.node(k + 1) - map.node(k) : Rgb{};
        const Rgb kappa = next - previous;
        previous = next;
        if (kappa.r == 0.0 && kappa.g == 0.0 && kappa.b == 0.0) continue;
        if (kinks.empty() || (kinks.back().k - lo) / width != (k - lo) / width) ++occupied_blocks;
        kinks.push_back({k, kappa});
    }

    // Use the expansion only where it is cheaper than the step sum.
    const double steps_span = map.wrap == WrapMode::Clamp ? static_cast<double>(n - 1) : period_;
    const double density = static_cast<double>(steps_.size()) / std::max(1.0, steps_span);
    const double blocks_in_reach =
        std::min(static_cast<double>(occupied_blocks), (2.0 * kTail + 1.0) * s_ / width + 1.0);
    if (kBlockCost * blocks_in_reach >= step_sum_cost(density, s_)) return;

    use_blocks_ = true;
    blocks_base_ = map.node(lo);
    // M_p = sum_k kappa_k u^p / p!,  u = (centre - k) / s, block by block.
    // Kinks go two at a time so that their power chains overlap.
    auto accumulate = [&](KinkBlock& block, const Kink* a, const Kink* b) {
        const double ua = (block.centre - static_cast<double>(a->k)) / s_;
        const double ub = b ? (block.centre - static_cast<double>(b->k)) / s_ : 0.0;
        const Rgb kb = b ? b->kappa : Rgb{};
        double ta = 1.0, tb = 1.0;
        for (int p = 0; p < kTaylorTerms; ++p) {
            block.moments[p] += ta * a->kappa + tb * kb;
            const double inv = 1.0 / (p + 1);
            ta *= ua * inv;
            tb *= ub * inv;
        }
    };
    for (std::size_t i = 0; i < kinks.size();) {
        const long index = (kinks[i].k - lo) / width;
        const long first = lo + index * width;
        const long last = std::min(hi, first + width - 1);
        KinkBlock block;
        block.centre = 0.5 * static_cast<double>(first + last);
        std::size_t end = i;
        while (end < kinks.size() && kinks[end].k <= last) ++end;
        for (; i + 1 < end; i += 2) accumulate(block, &kinks[i], &kinks[i + 1]);
        if (i < end) accumulate(block, &kinks[i], nullptr), ++i;
        blocks_.push_back(block);
    }
    prefix_.resize(blocks_.size() + 1);
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        prefix_[b + 1].m0 = prefix_[b].m0 + blocks_[b].moments[0];
        prefix_[b + 1].m1 = prefix_[b].m1 + blocks_[b].moments[1];
        prefix_[b + 1].centre_m0 = prefix_[b].centre_m0 + blocks_[b].centre * blocks_[b].moments[0];
    }
}

void GaussianConvolution::build_fourier_series()
{
    const ColorMap& map = *map_;
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
        for (int ch = 0; ch < 3; ++ch) harmonics_[ch].push_back(acc[ch] * (sinc * sinc * damping / period_));
    }
}

Rgb GaussianConvolution::operator()(double v) const
{
    const double x = map_->node_coordinate(v);
    if (s_ == 0.0 || !std::isfinite(x)) return map_->evaluate(v);
    if (use_fourier_) return fourier_series(x);
    if (use_blocks_) return sum_of_kink_blocks(x);
    return sum_of_steps(x);
}

Rgb GaussianConvolution::sum_of_kink_blocks(double x) const
{
    if (map_->wrap != WrapMode::Clamp) x = wrap_coordinate(x, period_, WrapMode::Repeat);
    // Block b contributes sum_k kappa_k R(x - k). Taylor-expanding R about the
    // block centre c, R(x - k) = sum_p R^(p)(x - c) (c - k)^p / p!, with
    //   s^0 R     = s (t Phi(t) + phi(t)),   s R' = s Phi(t),
    //   s^p R^(p) = s (-1)^p He_{p-2}(t) phi(t)  (p >= 2),   t = (x - c) / s,
    // gives sum_p [s^p R^(p)(x - c)] M_p with the block moments M_p.
    // Lagrange remainder (Cramer's bound |He_m phi| <= 0.433 sqrt(m!)), with
    // |c - k| <= h s, h = 1.5, and 33 terms (p = 0..32):
    //   <= 0.433 s h^33 sqrt(31!) / 33! |kappa| = 2.9e-15 s |kappa| per kink.
    const double s = s_;
    const double reach = (kTail + 0.5) * s;
    // Blocks whose every kink lies more than 9 s to the left of x have
    // R(x - k) = x - k: their sum is x sum M_0 - sum c M_0 + s sum M_1, read
    // from prefix sums. Blocks more than 9 s to the right contribute nothing.
    const auto by_centre = [](const KinkBlock& b, double c) { return b.centre < c; };
    const std::size_t first = static_cast<std::size_t>(
        std::lower_bound(blocks_.begin(), blocks_.end(), x - reach, by_centre) - blocks_.begin());
    const std::size_t end = static_cast<std::size_t>(
        std::lower_bound(blocks_.begin(), blocks_.end(), x + reach, by_centre) - blocks_.begin());
    const LinearPrefix& left = prefix_[first];
    Rgb result = blocks_base_ + x * left.m0 - left.centre_m0 + s * left.m1;
    // Blocks in reach, a chunk at a time: erfc and exp per block, then the
    // Hermite recurrence and the moment sums with the term index outermost, so
    // that the blocks of a chunk advance side by side instead of each waiting
    // on its own recurrence.
    constexpr std::size_t kChunk = 32;
    for (std::size_t chunk = first; chunk < end; chunk += kChunk) {
        const std::size_t count = std::min(kChunk, end - chunk);
        const KinkBlock* block = blocks_.data() + chunk;
        double t[kChunk], weight[kChunk], he[kChunk], he_prev[kChunk];
        double r[kChunk], g[kChunk], bl[kChunk];
        for (std::size_t j = 0; j < count; ++j) {
            const double d = x - block[j].centre;
            t[j] = d / s;
            const double cdf = 0.5 * std::erfc(-t[j] * kInvSqrt2);
            const double sp = s * kInvSqrt2Pi * std::exp(-0.5 * t[j] * t[j]);
            const double w0 = d * cdf + sp, w1 = s * cdf;
            const Rgb& m0 = block[j].moments[0];
            const Rgb& m1 = block[j].moments[1];
            r[j] = w0 * m0.r + w1 * m1.r;
            g[j] = w0 * m0.g + w1 * m1.g;
            bl[j] = w0 * m0.b + w1 * m1.b;
            weight[j] = sp;  // s phi(t) (-1)^p, sign folded in as p advances
            he[j] = 1.0;     // He_0
            he_prev[j] = 0.0;
        }
        // He_0 = 1, He_1 = t, He_{m+1} = t He_m - m He_{m-1}.
        for (int p = 2; p < kTaylorTerms; ++p) {
            const double m = p - 2;
            for (std::size_t j = 0; j < count; ++j) {
                const double w = weight[j] * he[j];
                const Rgb& mp = block[j].moments[p];
                r[j] += w * mp.r;
                g[j] += w * mp.g;
                bl[j] += w * mp.b;
                const double next = t[j] * he[j] - m * he_prev[j];
                he_prev[j] = he[j];
                he[j] = next;
                weight[j] = -weight[j];
            }
        }
        for (std::size_t j = 0; j < count; ++j) result += Rgb{r[j], g[j], bl[j]};
    }
    return result;
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
