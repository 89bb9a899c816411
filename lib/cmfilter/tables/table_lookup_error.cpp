// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/tables/table_lookup_error.h"

#include "cmfilter/tables/gaussian_convolution.h"
#include "cmfilter/util/parallel_for.h"

#include <algorithm>
#include <random>

namespace cmfilter {

LookupErrorPoints draw_lookup_error_points(const ColorMap& map, double sigma_max, const LookupErrorOptions& options)
{
    const int n = std::max(0, options.samples);
    LookupErrorPoints points;
    points.v.resize(n);
    points.sigma.resize(n);
    points.exact.resize(n);
    // Draw all samples first so the result does not depend on the thread count.
    std::mt19937_64 rng(options.seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < n; ++i) {
        points.v[i] = map.vmin + (map.vmax - map.vmin) * unit(rng);
        const double u = unit(rng);
        points.sigma[i] = sigma_max * u * u;
    }
    parallel_for(n, options.threads, [&](int i) {
        points.exact[i] = linear_rec709_to_lab(gaussian_convolution(map, points.v[i], points.sigma[i]));
    });
    return points;
}

std::vector<double> lookup_errors(const GaussianColorTable& table, const LookupErrorPoints& points, int threads)
{
    const int n = static_cast<int>(points.v.size());
    std::vector<double> error(n);
    parallel_for(n, threads, [&](int i) {
        const Rgb looked_up = table.lookup(points.v[i], points.sigma[i]);
        error[i] = ciede2000(points.exact[i], linear_rec709_to_lab(looked_up));
    });
    return error;
}

ErrorSummary measure_lookup_error(const GaussianColorTable& table, const ColorMap& map,
                                  const LookupErrorOptions& options)
{
    const LookupErrorPoints points = draw_lookup_error_points(map, table.axes().sigma_max, options);
    return summarize_errors(lookup_errors(table, points, options.threads));
}

}  // namespace cmfilter
