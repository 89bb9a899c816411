// SPDX-License-Identifier: Apache-2.0
// Summary statistics of an error sample; p95 is the nearest-rank percentile
// (Hyndman & Fan 1996, "Sample quantiles in statistical packages", definition 1:
// the value at rank ceil(p n) of the sorted sample).
#include "cmfilter/color/error_summary.h"

#include <algorithm>
#include <cmath>

namespace cmfilter {

ErrorSummary summarize_errors(std::vector<double> values)
{
    ErrorSummary s;
    s.count = values.size();
    if (values.empty()) return s;
    std::sort(values.begin(), values.end());

    double sum = 0.0;
    for (double v : values) sum += v;
    s.mean = sum / static_cast<double>(values.size());

    // Nearest rank ceil(0.95 n), computed in integers (19 n / 20 rounded up) so
    // that n = 100 gives exactly rank 95 without floating-point doubt.
    const std::size_t n = values.size();
    const std::size_t rank = std::max<std::size_t>(1, (19 * n + 19) / 20);
    s.p95 = values[rank - 1];
    s.max = values.back();
    return s;
}

double nearest_rank_quantile(std::vector<double> values, double q)
{
    if (values.empty()) return 0.0;
    const std::size_t n = values.size();
    const double exact_rank = q * static_cast<double>(n) * (1.0 - 1e-12);
    const std::size_t rank = std::clamp<std::size_t>(static_cast<std::size_t>(std::ceil(exact_rank)), 1, n);
    auto kth = values.begin() + static_cast<std::ptrdiff_t>(rank - 1);
    std::nth_element(values.begin(), kth, values.end());
    return *kth;
}

}  // namespace cmfilter
