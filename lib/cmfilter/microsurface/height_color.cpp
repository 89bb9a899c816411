// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/microsurface/height_color.h"

#include "cmfilter/math/gauss_legendre.h"
#include "cmfilter/math/normal_distribution.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace cmfilter {

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

Rgb exact_height_color(const ColorMap& map, double sigma_h, double lambda_sum, double offset)
{
    if (map.texels.empty()) return {};
    if (!(sigma_h > 0)) return map.evaluate(offset);
    const double L = std::isnan(lambda_sum) ? 0.0 : std::min(std::max(0.0, lambda_sum), 1e100);
    const double k1 = L + 1;
    // The heights that carry weight: v = Phi(h / sigma_h)^(L+1) in
    // [1e-15, 1 - 1e-15], at u = v^(1/(L+1)). Where u is close to 1 (the
    // upper end always, the lower one for large L: beyond L ~ 3e17 its u
    // rounds to 1, whose quantile is +infinity) the quantile is taken of
    // 1 - u, through complements.
    const auto quantile_of_root = [&](double log_v) {
        const double log_u = log_v / k1;
        return log_u < -0.5 ? normal_quantile(std::exp(log_u)) : -normal_quantile(-std::expm1(log_u));
    };
    const double x_lo = quantile_of_root(std::log(1e-15));
    const double x_hi = quantile_of_root(std::log1p(-1e-15));
    // Breakpoints: the map's nodes between them (at most 100000), then
    // panels no wider than sigma_h / 4, nor than 1/32 of the span (D_h
    // narrows as L grows: about sigma_h / sqrt(2 ln L)), where D_h's density
    // is smooth and C_h linear.
    std::vector<double> breaks{sigma_h * x_lo};
    const double first = std::ceil(map.node_coordinate(offset + sigma_h * x_lo));
    const double last = std::floor(map.node_coordinate(offset + sigma_h * x_hi));
    const double stride = std::max(1.0, std::ceil((last - first + 1) / 100000));
    for (double k = first; k <= last; k += stride) breaks.push_back(map.vmin + (k + 0.5) * map.texel_width() - offset);
    breaks.push_back(sigma_h * x_hi);
    // D_h in h (eq. 16): (L + 1) Phi(h / sigma_h)^L phi(h / sigma_h) / sigma_h.
    const auto weighted = [&](double h) {
        const double x = h / sigma_h;
        const double density = std::exp(std::log(k1) + L * log_normal_cdf(x) - 0.5 * x * x) /
                               (sigma_h * std::sqrt(2 * kPi));
        return density * map.evaluate(h + offset);
    };
    const double panel = std::min(0.25, (x_hi - x_lo) / 32) * sigma_h;
    // Segments under this share of a panel take the 2-point rule: relative
    // error about (share / 4)^4 / 4320 per segment, below 1e-9 here.
    constexpr double kNarrow = 0.125;
    Rgb sum;
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
        const double a = breaks[i], b = breaks[i + 1];
        if (!(b > a)) continue;
        if (b - a < kNarrow * panel) {
            // Between two of the map's nodes far closer than D_h bends: the
            // integrand is a line times a nearly cubic density there.
            sum += gauss_legendre_2(weighted, a, b);
            continue;
        }
        const int panels = static_cast<int>(std::min(64.0, std::ceil((b - a) / panel)));
        sum += gauss_legendre_8(weighted, a, b, std::max(1, panels));
    }
    return sum;
}

}  // namespace cmfilter
