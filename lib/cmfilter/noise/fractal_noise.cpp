// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/noise/fractal_noise.h"

#include "cmfilter/noise/noise_lattice.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cmfilter {

const char* to_string(FractalSum sum) { return sum == FractalSum::Fbm ? "fbm" : "turbulence"; }

double measure_mean_abs(const std::function<double(double, double)>& evaluate, double period, int samples_per_axis)
{
    const double side = 256.0 * period;
    const double cell = side / samples_per_axis;
    std::uint64_t state = 0x5EED5EED5EEDull;
    double sum = 0;
    for (int j = 0; j < samples_per_axis; ++j)
        for (int i = 0; i < samples_per_axis; ++i) {
            const double x = (i + unit_interval(splitmix64(state))) * cell;
            const double y = (j + unit_interval(splitmix64(state))) * cell;
            sum += std::fabs(evaluate(x, y));
        }
    return sum / (static_cast<double>(samples_per_axis) * samples_per_axis);
}

Expected<FractalNoise> FractalNoise::create(BaseNoise base, const FractalOptions& o, std::uint64_t seed)
{
    if (!base.evaluate) return bad_input("fractal noise needs a base noise");
    if (!(base.period > 0) || !std::isfinite(base.period))
        return bad_input("base noise period must be positive and finite, got " + std::to_string(base.period));
    if (o.octaves < 1 || o.octaves > 64)
        return bad_input("octaves must be in [1, 64], got " + std::to_string(o.octaves));
    if (!(o.lacunarity > 1) || !std::isfinite(o.lacunarity))
        return bad_input("lacunarity must be > 1 and finite, got " + std::to_string(o.lacunarity));
    if (!(o.gain > 0) || !std::isfinite(o.gain))
        return bad_input("gain must be positive and finite, got " + std::to_string(o.gain));

    FractalNoise f;
    f.base_ = std::move(base);
    auto& known = o.sum == FractalSum::Fbm ? f.base_.correlation : f.base_.correlation_abs;
    if (!known) {
        auto evaluate = f.base_.evaluate;
        auto term = o.sum == FractalSum::Fbm ? std::function<double(double, double)>(evaluate)
                                             : std::function<double(double, double)>([evaluate](double x, double y) {
                                                   return std::fabs(evaluate(x, y));
                                               });
        auto measured = measure_box_correlation(term, f.base_.period);
        if (!measured) return measured.error();
        known = std::move(*measured);
    }
    f.correlation_ = known;
    f.log2_cutoff_ = std::log2(known->cutoff());
    f.options_ = o;
    std::uint64_t state = seed;
    double scale = 1, amplitude = 1;
    for (int i = 0; i < o.octaves; ++i) {
        f.scales_.push_back(scale);
        f.amplitudes_.push_back(amplitude);
        f.periods_.push_back(f.base_.period / scale);
        f.log2_periods_.push_back(std::log2(f.periods_.back()));
        f.shift_x_.push_back(256.0 * f.base_.period * unit_interval(splitmix64(state)));
        f.shift_y_.push_back(256.0 * f.base_.period * unit_interval(splitmix64(state)));
        scale *= o.lacunarity;
        amplitude *= o.gain;
    }
    return f;
}

double FractalNoise::octave(int i, double x, double y) const
{
    const auto k = static_cast<std::size_t>(i);
    const double n = base_.evaluate(scales_[k] * x + shift_x_[k], scales_[k] * y + shift_y_[k]);
    return options_.sum == FractalSum::Fbm ? n : std::fabs(n);
}

double FractalNoise::operator()(double x, double y) const
{
    double sum = 0;
    for (int i = 0; i < options_.octaves; ++i) sum += octave_amplitude(i) * octave(i, x, y);
    return sum;
}

double FractalNoise::octave_mean() const { return options_.sum == FractalSum::Fbm ? base_.mean : base_.mean_abs; }

double FractalNoise::resolved_fraction(int i, double w) const { return (*correlation_)(w / octave_period(i)); }

double FractalNoise::mean_over_footprint(double x, double y, double w) const
{
    if (!(w > 0)) return (*this)(x, y);  // a point keeps every octave whole
    return mean_over_footprint_log2(x, y, std::log2(w));
}

double FractalNoise::mean_over_footprint_log2(double x, double y, double log2_w) const
{
    if (!(log2_w > -std::numeric_limits<double>::infinity())) return (*this)(x, y);  // a point (or NaN)
    const double mu = octave_mean();
    // beta(w / p_i) from one log2 per call: log2(w / p_i) = log2 w - log2 p_i.
    double sum = 0;
    for (int i = 0; i < options_.octaves; ++i) {
        const double log2_k = log2_w - log2_periods_[static_cast<std::size_t>(i)];
        double term = mu;  // past the cutoff: averaged away, and not evaluated
        if (log2_k < log2_cutoff_) term = mu + correlation_->at_log2(log2_k) * (octave(i, x, y) - mu);
        sum += octave_amplitude(i) * term;
    }
    return sum;
}

}  // namespace cmfilter
