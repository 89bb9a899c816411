// Measured (not assumed) accuracy of bilinear table lookups: CIEDE2000 between
// GaussianColorTable::lookup(v, sigma) and the exact convolution T(v, sigma)
// at random (v, sigma), v uniform over the domain [vmin, vmax] and
// sigma = sigma_max u^2 with u uniform (density proportional to 1/sqrt(sigma):
// densest near 0, where filtering is used most and the table bends most).
#pragma once

#include "cmfilter/color_map.h"
#include "cmfilter/error_summary.h"
#include "cmfilter/gaussian_color_table.h"

#include <cstdint>

namespace cmfilter {

struct LookupErrorOptions {
    int samples = 20000;
    std::uint64_t seed = 1;
    int threads = 0;
};

ErrorSummary measure_lookup_error(const GaussianColorTable& table, const ColorMap& map,
                                  const LookupErrorOptions& options);

}  // namespace cmfilter
