// SPDX-License-Identifier: Apache-2.0
// How a surface's Gaussian table is chosen for rendering (tolerance_tables.h):
// the options, and the record kept beside the material. The table is the fixed
// default, or the smallest that meets a CIEDE2000 tolerance over the surface's
// own sigma range; the small-sigma shortcut (plain_lookup.h) has a bound.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace cmfilter {

struct TableFit {
    double tolerance = 0;       // CIEDE2000 the table meets; 0: the table was not fitted
    std::string statistic;      // what the tolerance bounds, e.g. "p99.9"
    double error = 0;           // that statistic at the search's verification points
    double sigma_max = 0;       // the surface's largest sigma: the fitted table's sigma axis
    std::string sigma_max_how;  // where it came from (driver_sigma_range.h)
    int candidates = 0;         // tables measured by the search
    double plain_bound = 0;     // CIEDE2000 bound of the small-sigma shortcut; 0: off
};

// The shortcut's default bound, as a fraction of the tolerance: where it is
// taken, C0(mean) differs from the exact T(mean, sigma) by at most a tenth of
// what the table itself may differ by.
inline constexpr double kPlainLookupFraction = 0.1;

struct TableChoiceOptions {
    // > 0: fit to this CIEDE2000; 0: keep the table the material holds; absent:
    // the scene's colormap/tolerance, if the surface has one.
    std::optional<double> tolerance;
    // The shortcut's CIEDE2000 bound; 0: off; absent: kPlainLookupFraction x the
    // tolerance when the table is fitted, else off.
    std::optional<double> plain_bound;
    double quantile = 0.999;  // the lookup-error statistic the tolerance bounds
    std::uint64_t seed = 1;   // the search's points (table_size_search.h)
    int threads = 0;          // 0: all cores
};

}  // namespace cmfilter
