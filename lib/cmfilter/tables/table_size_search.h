// SPDX-License-Identifier: Apache-2.0
// The smallest Gaussian colour table that meets a colour-difference tolerance
// (bake-colormap --tolerance; docs/bake-colormap.md, "Smallest table for a
// tolerance"): over a grid of value counts, sigma counts and both sigma
// spacings, the table of fewest bytes (values x sigmas x 3 x 4) whose
// lookup error, a nearest-rank quantile of CIEDE2000 at random (v, sigma)
// (table_lookup_error.h), is at most the tolerance.
//
// The search assumes that, for a fixed sigma count and spacing, the error
// does not grow with more value nodes. Per spacing it walks the staircase of
// the smallest passing value count per sigma count: sigma counts ascending,
// each starting from the previous one's value count (anything larger has
// more bytes than that winner) and stepping down while the next smaller value
// count passes, skipping sizes of more bytes than the best so far (equal
// sizes are measured and decided by the lower error). So a walk's winner's
// next smaller value count at its sigma count and spacing has been measured
// and failed. Every candidate is measured at the same search points, drawn once
// from `seed` (table_lookup_error.h: their exact colours are computed once).
// The winner, the smallest of every candidate measured so far that passed,
// is then checked at an independent, larger set of points (seed + 1); if it
// fails there it is excluded and the search resumes (measured candidates are
// not measured again).
#pragma once

#include "cmfilter/colormap/color_map.h"
#include "cmfilter/util/error.h"
#include "cmfilter/color/error_summary.h"
#include "cmfilter/tables/gaussian_color_table.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace cmfilter {

struct TableSize {
    int values = 0;
    int sigmas = 0;
    SigmaSpacing spacing = SigmaSpacing::Sqrt;

    // Bytes of the float32 RGB nodes: values x sigmas x 3 x 4.
    std::size_t bytes() const { return static_cast<std::size_t>(values) * sigmas * 3 * sizeof(float); }
};

// lo, 1.5 lo, 2 lo, 3 lo, 4 lo, ... up to hi (for a power-of-two lo: the
// powers of two and the 1.5x between them): 4, 6, 8, 12, ..., 3072, 4096 for
// (4, 4096).
std::vector<int> power_of_two_counts(int lo, int hi);

struct TableSizeSearchOptions {
    double tolerance = 1.0;           // CIEDE2000, finite and > 0
    double quantile = 0.999;          // the error statistic: nearest-rank quantile in (0, 1]; 1 is the maximum
    std::optional<double> sigma_max;  // as GaussianColorTableOptions (default (vmax - vmin) / 4)
    std::optional<double> margin;     // as GaussianColorTableOptions
    std::vector<int> value_counts = power_of_two_counts(4, 4096);  // ascending, each >= 2
    std::vector<int> sigma_counts = power_of_two_counts(2, 1024);  // ascending, each >= 2
    std::vector<SigmaSpacing> spacings = {SigmaSpacing::Sqrt, SigmaSpacing::Linear};
    int search_samples = 20000;   // points every candidate is measured at
    int verify_samples = 100000;  // independent points the winner is checked at
    std::uint64_t seed = 1;       // search points; the verification points use seed + 1
    int threads = 0;              // 0: all cores
};

// One candidate measured during the search, in the order measured.
struct TableSizeTrial {
    TableSize size;
    double error = 0;         // the statistic at the search points
    bool verified = false;    // checked at the verification points too
    double verify_error = 0;  // the statistic there (when verified)
};

struct TableSizeSearchResult {
    GaussianColorTable table;  // the chosen table, baked
    TableSize size;
    double sigma_max = 0;         // the sigma axis the search used
    double search_error = 0;      // the statistic at the search points
    double error = 0;             // the statistic at the verification points (<= tolerance)
    ErrorSummary verify_summary;  // mean, p95, max at the verification points
    std::vector<TableSizeTrial> trials;
    int rejected = 0;  // winners of the search that failed verification
};

// "max" for q = 1, else "p" and the percentile ("p99.9", "p95").
std::string quantile_name(double q);

// BadInput (naming the value) for a tolerance, quantile, count list or sample
// count out of range, a bad map, sigma_max or margin; BadInput too when no
// table in the grid meets the tolerance, naming it, the largest size and the
// lowest error reached.
Expected<TableSizeSearchResult> find_smallest_table(const ColorMap& map, const TableSizeSearchOptions& options);

}  // namespace cmfilter
