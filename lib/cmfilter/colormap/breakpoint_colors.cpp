// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/colormap/breakpoint_colors.h"

#include <algorithm>
#include <cstddef>

namespace cmfilter {

DriverWeights driver_weights(const std::vector<float>& driver, double lo, double hi, int bins)
{
    DriverWeights out;
    if (driver.empty() || bins < 1) return out;
    std::vector<double> sum(static_cast<std::size_t>(bins), 0.0), count(static_cast<std::size_t>(bins), 0.0);
    const double scale = hi > lo ? bins / (hi - lo) : 0.0;
    for (float v : driver) {
        const std::size_t b = static_cast<std::size_t>(std::clamp(static_cast<int>((v - lo) * scale), 0, bins - 1));
        sum[b] += v;
        count[b] += 1;
    }
    const double n = static_cast<double>(driver.size());
    for (std::size_t b = 0; b < sum.size(); ++b) {
        if (count[b] == 0) continue;
        out.values.push_back(sum[b] / count[b]);
        out.shares.push_back(count[b] / n);
    }
    return out;
}

Rgb breakpoint_curve(const std::vector<double>& t, const std::vector<Rgb>& c, double f)
{
    if (!(f > t.front())) return c.front();
    if (f >= t.back()) return c.back();
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), f) - t.begin());
    const double w = (f - t[k - 1]) / (t[k] - t[k - 1]);
    return (1 - w) * c[k - 1] + w * c[k];
}

std::vector<Rgb> breakpoint_colors(const ColorMap& map, const std::vector<double>& t, const DriverWeights* weights)
{
    const std::size_t n = t.size();
    std::vector<Rgb> at(n);
    for (std::size_t k = 0; k < n; ++k) at[k] = map.evaluate(t[k]);
    if (!weights || weights->empty() || n < 2) return at;
    // Normal equations A c = b, A tridiagonal (diag d, off-diagonal e between k and k + 1).
    std::vector<double> d(n, 0.0), e(n, 0.0);
    std::vector<Rgb> b(n);
    double total = 0;
    for (std::size_t i = 0; i < weights->values.size(); ++i) {
        const double f = weights->values[i], w = weights->shares[i];
        total += w;
        const Rgb y = map.evaluate(f);
        if (!(f > t.front()) || f >= t.back()) {
            const std::size_t k = f >= t.back() ? n - 1 : 0;
            d[k] += w;
            b[k] += w * y;
            continue;
        }
        const std::size_t k = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), f) - t.begin());
        const double u = (f - t[k - 1]) / (t[k] - t[k - 1]);  // phi_k = u, phi_{k-1} = 1 - u
        d[k - 1] += w * (1 - u) * (1 - u);
        d[k] += w * u * u;
        e[k - 1] += w * u * (1 - u);
        b[k - 1] += (w * (1 - u)) * y;
        b[k] += (w * u) * y;
    }
    const double ridge = 1e-9 * std::max(total, 1e-300);
    for (std::size_t k = 0; k < n; ++k) {
        d[k] += ridge;
        b[k] += ridge * at[k];
    }
    // Thomas algorithm (A is symmetric positive definite: no pivoting).
    std::vector<double> cp(n, 0.0);
    std::vector<Rgb> x(n);
    double denom = d[0];
    cp[0] = e[0] / denom;
    x[0] = (1.0 / denom) * b[0];
    for (std::size_t k = 1; k < n; ++k) {
        denom = d[k] - e[k - 1] * cp[k - 1];
        cp[k] = k + 1 < n ? e[k] / denom : 0.0;
        x[k] = (1.0 / denom) * (b[k] - e[k - 1] * x[k - 1]);
    }
    for (std::size_t k = n - 1; k-- > 0;) x[k] = x[k] - cp[k] * x[k + 1];
    return x;
}

}  // namespace cmfilter
