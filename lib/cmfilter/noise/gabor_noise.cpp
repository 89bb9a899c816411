// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/noise/gabor_noise.h"

#include "cmfilter/noise/noise_lattice.h"

#include <cmath>
#include <string>

namespace cmfilter {

namespace {

constexpr double pi = 3.14159265358979323846;

// Poisson(mean) count by summing unit exponential gaps until they pass the mean
// (exact for any mean; O(mean) draws).
int poisson_count(double mean, std::uint64_t& state)
{
    int count = 0;
    double t = -std::log1p(-unit_interval(splitmix64(state)));
    while (t < mean) {
        ++count;
        t -= std::log1p(-unit_interval(splitmix64(state)));
    }
    return count;
}

// The generator state of cell (i, j): the seed and the cell hashed together.
std::uint64_t cell_state(std::uint64_t seed, long long i, long long j)
{
    std::uint64_t a = seed;
    std::uint64_t key = (static_cast<std::uint64_t>(i) << 32) ^ static_cast<std::uint64_t>(j & 0xFFFFFFFFll);
    const std::uint64_t seed_hash = splitmix64(a);
    std::uint64_t b = seed_hash ^ key;
    return splitmix64(b);
}

std::string number(double v) { return std::to_string(v); }

}  // namespace

Expected<GaborNoise> GaborNoise::create(const GaborNoiseOptions& o, std::uint64_t seed)
{
    if (!std::isfinite(o.amplitude)) return bad_input("gabor amplitude must be finite, got " + number(o.amplitude));
    if (!(o.bandwidth > 0) || !std::isfinite(o.bandwidth))
        return bad_input("gabor bandwidth must be positive and finite, got " + number(o.bandwidth));
    if (!(o.frequency >= 0) || !std::isfinite(o.frequency))
        return bad_input("gabor frequency must be >= 0 and finite, got " + number(o.frequency));
    if (o.orientation && !std::isfinite(*o.orientation))
        return bad_input("gabor orientation must be finite, got " + number(*o.orientation));
    if (!(o.impulse_density > 0) || !std::isfinite(o.impulse_density))
        return bad_input("gabor impulse density must be positive and finite, got " + number(o.impulse_density));
    const double r = 1.5 / o.bandwidth;
    const double per_cell = o.impulse_density * r * r;
    if (per_cell > 10000)
        return bad_input("gabor impulse density " + number(o.impulse_density) + " with bandwidth " +
                         number(o.bandwidth) + " gives " + number(per_cell) +
                         " impulses per cell on average; at most 10000");
    return GaborNoise(o, seed);
}

double GaborNoise::analytic_variance(const GaborNoiseOptions& o)
{
    // Campbell's theorem with E[w^2] = 1/3 (Lagae et al. 2009, sec. 3.3).
    const double a2 = o.bandwidth * o.bandwidth;
    return o.impulse_density * o.amplitude * o.amplitude / (12.0 * a2) *
           (1.0 + std::exp(-2.0 * pi * o.frequency * o.frequency / a2));
}

double GaborNoise::period() const
{
    return options_.frequency > 0 ? 1.0 / options_.frequency : 1.0 / options_.bandwidth;
}

double GaborNoise::operator()(double x, double y) const
{
    const double r = truncation_radius();
    const double r2 = r * r;
    const double per_cell = options_.impulse_density * r2;
    const double envelope = -pi * options_.bandwidth * options_.bandwidth;
    const double wave = 2.0 * pi * options_.frequency;
    const double cx = std::floor(x / r), cy = std::floor(y / r);
    double sum = 0;
    for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
            const long long i = static_cast<long long>(cx) + di, j = static_cast<long long>(cy) + dj;
            std::uint64_t state = cell_state(seed_, i, j);
            const int count = poisson_count(per_cell, state);
            for (int k = 0; k < count; ++k) {
                // Draw every impulse's values in a fixed order, used or not,
                // so the sequence never depends on the point evaluated.
                const double px = (static_cast<double>(i) + unit_interval(splitmix64(state))) * r;
                const double py = (static_cast<double>(j) + unit_interval(splitmix64(state))) * r;
                const double w = 2.0 * unit_interval(splitmix64(state)) - 1.0;
                const double angle_draw = unit_interval(splitmix64(state));
                const double dx = x - px, dy = y - py;
                const double d2 = dx * dx + dy * dy;
                if (d2 >= r2) continue;
                const double angle = options_.orientation ? *options_.orientation : 2.0 * pi * angle_draw;
                sum += w * std::exp(envelope * d2) * std::cos(wave * (dx * std::cos(angle) + dy * std::sin(angle)));
            }
        }
    return options_.amplitude * sum;
}

}  // namespace cmfilter
