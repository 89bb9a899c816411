// SPDX-License-Identifier: Apache-2.0
// The breakpoints of a colour map over a driver range, and the ramp basis that
// makes the filtered colour of any map with those breakpoints a weighted sum
// of its colours there (the segment pyramid, texture/segment_pyramid_file.h).
//
// C0 (color_map.h) is piecewise linear between its texel centres. Over the
// range [lo, hi] that a driver takes, only the knots where its slope changes
// matter (a breakpoint), and lo or hi where C0 is not flat next to them. For
// breakpoints t_0 < ... < t_K, every map that is linear between consecutive
// t_k and flat outside [t_0, t_K] (within [lo, hi]) is
//     C(f) = C(t_0) + sum_{k=1..K} (C(t_k) - C(t_{k-1})) r_k(f),
//     r_k(f) = clamp((f - t_{k-1}) / (t_k - t_{k-1}), 0, 1),
// so that over any footprint mean C(f) = C(t_0) + sum_k (C(t_k) - C(t_{k-1}))
// mean r_k(f) (issue 42's segment identity, sum_k a_k P_k + b_k M_k, written
// in the ramp basis: K channels for K + 1 breakpoints instead of 2K + 1).
// The means of r_k are box means of a function of f, so a pyramid of them is
// exact at every level for any colours on those breakpoints.
#pragma once

#include "cmfilter/color/color.h"
#include "cmfilter/colormap/breakpoint_colors.h"
#include "cmfilter/colormap/color_map.h"
#include "cmfilter/util/error.h"

#include <cstddef>
#include <vector>

namespace cmfilter {

// The breakpoints of `map` over [lo, hi] (lo <= hi), ascending: its knots in
// (lo, hi) where the slope changes (relative change above 1e-7 of its largest
// colour), and lo and hi where C0 is not flat beside them. Empty for a map
// flat over [lo, hi]. BadInput when a periodic map puts more than
// `max_knots` knots in the range.
Expected<std::vector<double>> map_breakpoints(const ColorMap& map, double lo, double hi,
                                              std::size_t max_knots = 1u << 20);

// The interpolant through `breakpoints` (at least one): C at each, linear
// between, flat outside.
Rgb breakpoint_interpolant(const ColorMap& map, const std::vector<double>& breakpoints, double f);

struct BreakpointFit {
    double max_de = 0;   // largest CIEDE2000 between C0 and the interpolant on [lo, hi]
    double worst_f = 0;  // where
    // With weights: the mean CIEDE2000 over the driver's binned values, each
    // weighed by its share (what a tolerance bake keeps within its
    // tolerance); else 0.
    double mean_de = 0;
};

// C0 against its curve through `breakpoints` (breakpoint_colors.h: the
// interpolant, or with `weights` the least-squares colours), at every knot
// of C0 and every breakpoint in [lo, hi], lo, hi and the midpoints between
// them (both are piecewise linear: their RGB difference peaks at those knots).
BreakpointFit breakpoint_fit(const ColorMap& map, const std::vector<double>& breakpoints, double lo, double hi,
                             const DriverWeights* weights = nullptr);

struct BreakpointSelection {
    std::vector<double> breakpoints;  // at least two, ascending
    std::vector<BreakpointFit> fits;  // one per map: the largest error anywhere on [lo, hi]
    std::vector<double> mean_de;      // one per map: the mean error over the driver's texels
    double max_de = 0;                // the largest of fits
    double max_mean_de = 0;           // the largest of mean_de
    std::size_t candidates = 0;       // the maps' exact breakpoints together
    // Non-empty when the colours are least-squares fitted
    // (BreakpointSelectionOptions::fit_colors): the driver's weights they are
    // fitted with, which fits and mean_de use.
    DriverWeights color_weights;
    const DriverWeights* weights() const { return color_weights.empty() ? nullptr : &color_weights; }
};

struct BreakpointSelectionOptions {
    std::vector<const ColorMap*> maps;  // at least one
    double lo = 0, hi = 1;              // the driver's range
    // The driver's texels (optional): the mean errors weigh each value by
    // how often the driver takes it; without, uniformly over [lo, hi].
    const std::vector<float>* driver = nullptr;
    // <= 0: every exact breakpoint of every map (errors 0 up to rounding).
    // > 0: the fewest of them with every map's mean CIEDE2000 (C0 against its
    // interpolant, over the driver's texels) at most this, found by removing
    // one breakpoint at a time, the one whose removal raises the largest mean
    // least. The mean over level 0's texels bounds the filtered error at
    // every level up to the non-linearity of CIEDE2000 (docs/apply.md).
    double tolerance_de = 0;
    // > 0: go on removing past the tolerance down to this many breakpoints
    // (at least 2); the result says the mean errors it then reaches.
    std::size_t max_breakpoints = 0;
    // With a tolerance and a driver: the colours through the breakpoints
    // least-squares fitted to each map over the driver's values
    // (breakpoint_colors.h) instead of the map's own, and the breakpoints then
    // moved off the maps' knots (each, in turn, to the best of 12 places
    // between its neighbours) and removed further while every map stays
    // within the tolerance: fewer channels for smooth maps, whose
    // interpolant errs to one side of the curve between breakpoints.
    bool fit_colors = false;
};
// BadInput when no map is given or a map is invalid (naming the field).
Expected<BreakpointSelection> select_breakpoints(const BreakpointSelectionOptions& options);

// r_1(f) .. r_K(f) for breakpoints t_0 .. t_K (K = breakpoints.size() - 1).
void ramp_weights(const std::vector<double>& breakpoints, double f, double* ramps);

// c_0 and the steps c_k - c_{k-1}, k = 1..K, of the colours c_k through the
// breakpoints (breakpoint_colors.h: C(t_k), or with `weights` the
// least-squares colours): what the ramp means are weighted by (the colours a
// shader recolours with).
std::vector<Rgb> ramp_colors(const ColorMap& map, const std::vector<double>& breakpoints,
                             const DriverWeights* weights = nullptr);

// mean C = colors[0] + sum_k colors[k] ramps[k - 1].
Rgb ramp_color(const std::vector<Rgb>& colors, const float* ramps);

}  // namespace cmfilter
