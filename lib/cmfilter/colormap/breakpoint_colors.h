// SPDX-License-Identifier: Apache-2.0
// The colours a segment pyramid weighs its ramp means by: a colour per
// breakpoint t_0 < ... < t_K, joined linearly between them and flat outside
// (map_breakpoints.h). Through every breakpoint of a map they are the map's
// own colours C(t_k), exactly; through fewer, the colours that minimise the
// driver-weighted squared linear-RGB distance to the map,
//     c = argmin sum_i w_i || C(f_i) - sum_k c_k phi_k(f_i) ||^2,
// phi_k the hat functions of the breakpoints (phi_0 = 1 below t_0,
// phi_K = 1 above t_K), f_i the driver's values binned and w_i their shares:
// a linear projection of the map, so any map recoloured after the bake gets
// its own best colours, from the weights the pyramid records.
#pragma once

#include "cmfilter/color/color.h"
#include "cmfilter/colormap/color_map.h"

#include <vector>

namespace cmfilter {

// The driver's values in bins of [lo, hi]: each non-empty bin's mean value
// and share of the texels (shares sum to 1), ascending.
struct DriverWeights {
    std::vector<double> values;
    std::vector<double> shares;
    bool empty() const { return values.empty(); }
};

inline constexpr int kDriverWeightBins = 1024;

// The weights of `driver` in `bins` bins of [lo, hi] (empty for no texels).
DriverWeights driver_weights(const std::vector<float>& driver, double lo, double hi, int bins = kDriverWeightBins);

// The colours at `breakpoints` (at least one): C(t_k) without weights (or
// with empty ones); with them, the least-squares colours above, solved as
// the tridiagonal normal equations with a ridge of 1e-9 of the total weight
// towards C(t_k) (which keeps a breakpoint no driver value reaches at the
// map's colour).
std::vector<Rgb> breakpoint_colors(const ColorMap& map, const std::vector<double>& breakpoints,
                                   const DriverWeights* weights = nullptr);

// The curve through (t_k, colors[k]): linear between, flat outside.
Rgb breakpoint_curve(const std::vector<double>& breakpoints, const std::vector<Rgb>& colors, double f);

}  // namespace cmfilter
