// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/microsurface/height_moment_table.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace cmfilter {

Expected<HeightMomentTable> HeightMomentTable::create(const HeightMomentTableOptions& o)
{
    if (o.nodes < 2)
        return bad_input("height moment table nodes " + std::to_string(o.nodes) + " is out of range (expected >= 2)");
    if (!(o.max_lambda_sum > 0) || !std::isfinite(o.max_lambda_sum))
        return bad_input("height moment table max Lambda sum " + std::to_string(o.max_lambda_sum) +
                         " is out of range (expected finite, > 0)");
    HeightMomentTable t;
    t.s_max_ = std::log1p(o.max_lambda_sum);
    t.mean_.resize(static_cast<std::size_t>(o.nodes));
    t.sigma_.resize(static_cast<std::size_t>(o.nodes));
    for (int i = 0; i < o.nodes; ++i) {
        const double s = t.s_max_ * i / (o.nodes - 1);
        const HeightMoments m = exact_height_moments(std::expm1(s), 1.0);
        t.mean_[static_cast<std::size_t>(i)] = m.mean;
        t.sigma_[static_cast<std::size_t>(i)] = m.sigma;
    }
    return t;
}

HeightMoments HeightMomentTable::lookup(double lambda_sum, double sigma_h) const
{
    const double L = std::isnan(lambda_sum) ? 0.0 : std::max(0.0, lambda_sum);
    const double s = std::isinf(L) ? s_max_ : std::min(std::log1p(L), s_max_);
    const double x = s / s_max_ * static_cast<double>(mean_.size() - 1);
    const std::size_t i = std::min(static_cast<std::size_t>(x), mean_.size() - 2);
    const double f = x - static_cast<double>(i);
    const double scale = std::max(0.0, sigma_h);
    return {scale * ((1 - f) * mean_[i] + f * mean_[i + 1]), scale * ((1 - f) * sigma_[i] + f * sigma_[i + 1])};
}

}  // namespace cmfilter
