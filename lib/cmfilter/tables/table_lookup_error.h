// SPDX-License-Identifier: Apache-2.0
// Measured (not assumed) accuracy of bilinear table lookups: CIEDE2000 between
// GaussianColorTable::lookup(v, sigma) and the exact convolution T(v, sigma)
// at random (v, sigma), v uniform over the domain [vmin, vmax] and
// sigma = sigma_max u^2 with u uniform (density proportional to 1/sqrt(sigma):
// densest near 0, where filtering is used most and the table bends most).
//
// The points and their exact colours depend only on the map, sigma_max, the
// seed and the count, not on the table's node counts: a caller comparing many
// tables of one sigma_max (table_size_search.h) draws them once.
#pragma once

#include "cmfilter/color/ciede2000.h"
#include "cmfilter/colormap/color_map.h"
#include "cmfilter/color/error_summary.h"
#include "cmfilter/tables/gaussian_color_table.h"

#include <cstdint>
#include <vector>

namespace cmfilter {

struct LookupErrorOptions {
    int samples = 20000;
    std::uint64_t seed = 1;
    int threads = 0;
};

// The random points of a measurement and L*a*b* of the exact T there.
struct LookupErrorPoints {
    std::vector<double> v, sigma;
    std::vector<Lab> exact;
};

// options.samples points over the map's domain and [0, sigma_max], drawn in
// one sequence from options.seed (the result does not depend on the thread
// count), each with its exact colour (gaussian_convolution.h).
LookupErrorPoints draw_lookup_error_points(const ColorMap& map, double sigma_max, const LookupErrorOptions& options);

// CIEDE2000 between the table's lookup and the exact colour at each point, in
// the points' order.
std::vector<double> lookup_errors(const GaussianColorTable& table, const LookupErrorPoints& points, int threads);

// summarize_errors(lookup_errors(table, draw_lookup_error_points(map,
// table sigma_max, options))).
ErrorSummary measure_lookup_error(const GaussianColorTable& table, const ColorMap& map,
                                  const LookupErrorOptions& options);

}  // namespace cmfilter
