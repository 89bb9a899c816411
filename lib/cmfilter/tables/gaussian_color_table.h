// SPDX-License-Identifier: Apache-2.0
// The prefiltered colour-map table of section 4.2 (eq. 10):
//     T(v, sigma) = (C0 * N(0, sigma^2))(v),  sigma in [0, sigma_max],
// sampled on a grid of value nodes (columns) and sigma nodes (rows), looked up
// bilinearly in both axes. Row 0 is sigma = 0, the map itself.
//
// Value axis (docs/table-format.md):
//   clamp   N nodes end-inclusive over [vmin - margin, vmax + margin];
//           lookups beyond clamp to the end columns.
//   mirror  N nodes end-inclusive over [vmin, vmax]; T is symmetric about vmin
//           and vmax, so lookups reflect into the domain.
//   repeat  N nodes v_i = vmin + i (vmax - vmin) / N, periodic.
// Sigma axis: sigma_j = sigma_max g(j / (M - 1)), g(t) = t (linear) or t^2
// (sqrt spacing: uniform in sqrt(sigma), denser near 0 where T changes fastest).
#pragma once

#include "cmfilter/colormap/color_map.h"
#include "cmfilter/util/error.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace cmfilter {

enum class SigmaSpacing { Linear, Sqrt };
const char* to_string(SigmaSpacing spacing);
Expected<SigmaSpacing> parse_sigma_spacing(const std::string& name);

struct GaussianColorTableOptions {
    int values = 256;                 // value-axis nodes (>= 2)
    int sigmas = 256;                 // sigma-axis nodes (>= 2)
    std::optional<double> sigma_max;  // default: (vmax - vmin) / 4
    SigmaSpacing spacing = SigmaSpacing::Sqrt;
    std::optional<double> margin;  // clamp only; default 3 sigma_max
    int threads = 0;               // 0: all hardware threads
};

// Geometry of a table: everything needed to map (v, sigma) to a texel.
struct TableAxes {
    int values = 0;
    int sigmas = 0;
    double vmin = 0, vmax = 1;  // the colour map's domain
    WrapMode wrap = WrapMode::Clamp;
    double margin = 0;  // clamp only
    double sigma_max = 0;
    SigmaSpacing spacing = SigmaSpacing::Linear;

    double value_first() const;  // value of column 0
    double value_last() const;   // value of column values-1
    double value_at(int i) const;
    double sigma_at(int j) const;
};

// Caller-owned tallies of lookups that left the table's range.
struct LookupCounters {
    std::size_t lookups = 0;
    std::size_t sigma_clamped = 0;  // sigma > sigma_max, looked up at sigma_max
    std::size_t value_clamped = 0;  // clamp wrap: mean beyond the value axis
    std::size_t invalid = 0;        // NaN mean or sigma (or infinite mean when periodic): black
};

class GaussianColorTable {
public:
    GaussianColorTable() = default;
    GaussianColorTable(TableAxes axes, std::vector<float> rgb);  // rgb: sigmas x values x 3

    // Bakes every node with the exact convolution: per node by the step and
    // kink-block sums (gaussian_convolution.h), or whole rows of clamp maps by
    // the bounded cosine series (cosine_series_rows.h).
    static Expected<GaussianColorTable> bake(const ColorMap& map, const GaussianColorTableOptions& options);

    // Bilinear lookup; never returns NaN. counters may be null.
    Rgb lookup(double mean, double sigma, LookupCounters* counters = nullptr) const;

    const TableAxes& axes() const { return axes_; }
    const std::vector<float>& data() const { return rgb_; }
    Rgb node(int i, int j) const;  // column i (value), row j (sigma)

private:
    TableAxes axes_;
    std::vector<float> rgb_;
    // Lookup constants, from the axes: column = (v - value_first) value_scale
    // (clamp, mirror) or (v - vmin) value_scale (repeat); row = t (M - 1).
    double value_scale_ = 0, inv_sigma_max_ = 0;
};

// Resolves defaults and checks ranges, naming the offending value.
Expected<TableAxes> make_table_axes(const ColorMap& map, const GaussianColorTableOptions& options);

}  // namespace cmfilter
