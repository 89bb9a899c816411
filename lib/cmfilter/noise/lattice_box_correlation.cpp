// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/noise/lattice_box_correlation.h"

#include "cmfilter/math/gauss_legendre.h"
#include "cmfilter/noise/noise_lattice.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace cmfilter {

namespace {

// s(t) = fade(1 - |t|) on [-1, 1]: the weight a lattice point gives a point t
// away along one axis (quintic_fade(1 - t) = 1 - quintic_fade(t)).
double kernel(double t)
{
    const double a = std::fabs(t);
    return a >= 1.0 ? 0.0 : quintic_fade(1.0 - a);
}

// integral over t of g(t) s(t) s(t + d), d in [0, 2]: the support is
// [-1, 1 - d], with kinks at -d and 0.
template <typename G>
double lag_integral(double d, G&& g)
{
    double cuts[4] = {-1.0, -d, 0.0, 1.0 - d};
    std::sort(cuts, cuts + 4);
    auto f = [&](double t) { return g(t) * kernel(t) * kernel(t + d); };
    double sum = 0;
    for (int i = 0; i < 3; ++i)
        if (cuts[i + 1] > cuts[i]) sum += gauss_legendre_8(f, cuts[i], cuts[i + 1]);
    return sum;
}

double lag_a(double d)
{
    return lag_integral(d, [d](double t) { return t * (t + d); });
}
double lag_b(double d)
{
    return lag_integral(d, [](double) { return 1.0; });
}

// (1/k) integral over [-k/2, k/2] of an even lag function supported on
// [-2, 2], piecewise polynomial with a kink at 1.
template <typename L>
double box_mean(double k, L&& lag)
{
    const double h = std::min(0.5 * k, 2.0);
    double sum = gauss_legendre_8(lag, 0.0, std::min(h, 1.0));
    if (h > 1.0) sum += gauss_legendre_8(lag, 1.0, h);
    return 2.0 * sum / k;
}

template <typename Beta>
BoxCorrelation tabulate(Beta&& beta)
{
    std::vector<double> samples(BoxCorrelation::grid_count);
    for (int j = 0; j < BoxCorrelation::grid_count; ++j)
        samples[static_cast<std::size_t>(j)] = beta(std::exp2(BoxCorrelation::grid_log2(j)));
    return *BoxCorrelation::from_grid(std::move(samples));
}

}  // namespace

BoxCorrelation gradient_noise_box_correlation()
{
    const double a0 = lag_a(0.0), b0 = lag_b(0.0);
    return tabulate([&](double k) {
        if (k >= 4.0) return 0.0;
        return box_mean(k, lag_a) * box_mean(k, lag_b) / (a0 * b0);
    });
}

BoxCorrelation value_noise_box_correlation()
{
    const double b0 = lag_b(0.0);
    return tabulate([&](double k) {
        const double r = box_mean(k, lag_b) / b0;
        return r * r;
    });
}

}  // namespace cmfilter
