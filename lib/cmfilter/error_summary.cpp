// Summary statistics of an error sample; p95 is the nearest-rank percentile
// (Hyndman & Fan 1996, "Sample quantiles in statistical packages", definition 1:
// the value at rank ceil(p n) of the sorted sample).
#include "cmfilter/error_summary.h"

#include <algorithm>

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

}  // namespace cmfilter
