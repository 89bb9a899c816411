#include "cmfilter/table_lookup_error.h"

#include "cmfilter/ciede2000.h"
#include "cmfilter/gaussian_convolution.h"
#include "cmfilter/parallel_for.h"

#include <random>
#include <vector>

namespace cmfilter {

ErrorSummary measure_lookup_error(const GaussianColorTable& table, const ColorMap& map,
                                  const LookupErrorOptions& options)
{
    const int n = std::max(0, options.samples);
    const TableAxes& ax = table.axes();
    // Draw all samples first so the result does not depend on the thread count.
    std::vector<double> v(n), sigma(n);
    std::mt19937_64 rng(options.seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < n; ++i) {
        v[i] = ax.vmin + (ax.vmax - ax.vmin) * unit(rng);
        const double u = unit(rng);
        sigma[i] = ax.sigma_max * u * u;
    }
    std::vector<double> error(n);
    parallel_for(n, options.threads, [&](int i) {
        const Rgb exact = gaussian_convolution(map, v[i], sigma[i]);
        const Rgb looked_up = table.lookup(v[i], sigma[i]);
        error[i] = ciede2000_linear_rgb(exact, looked_up);
    });
    return summarize_errors(std::move(error));
}

}  // namespace cmfilter
