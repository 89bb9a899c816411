// SPDX-License-Identifier: Apache-2.0
// The small-sigma shortcut of the gaussian method (docs/render.md, "Table
// sizes and the small-sigma shortcut"): where sigma is small enough, the
// filtered colour T(v, sigma) = (C0 * N(0, sigma^2))(v) (eq. 10) is C0(v)
// itself within a CIEDE2000 bound, so a renderer can evaluate the exact map
// C0(mean) instead of looking the table up. That is cheaper than a bilinear
// lookup and more accurate: at small sigma the table's value axis, not sigma,
// limits it (a hard edge is blurred over a value-node spacing).
//
// How small is small depends on the map and on v: T - C0 comes from C0's
// kinks (its texel centres; eq. 10 leaves a linear stretch unchanged) within a
// few sigma of v, so far from a hard edge a much larger sigma is harmless than
// next to one. The threshold is therefore measured per value, on the map
// itself, with T from the exact convolution that bakes tables
// (gaussian_convolution.h):
//   - points v_i, `points_per_texel` per texel starting at each texel centre,
//     from one texel before the domain to one after it;
//   - sigmas on a geometric grid, ratio 2^(1/8), from a thousandth of a texel
//     up to `sigma_cap`;
//   - at each point, the largest grid sigma s_i such that
//     CIEDE2000(T(v_i, s), C0(v_i)) <= bound at every grid sigma s <= s_i
//     (0 when the first one fails);
//   - between two neighbouring points, the smaller of their two s_i.
// T - C0 is, per channel, a sum over kinks of slope change x sigma x
// R((v - k) / sigma), R(d) = phi(d) - |d| Phi(-|d|): monotone in |v - k| and
// convex on each side of a kink, so between two points (no kink between them)
// it is largest at or near a point. Means outside the sampled range get no
// shortcut.
#pragma once

#include "cmfilter/colormap/color_map.h"
#include "cmfilter/util/error.h"

#include <cstddef>
#include <vector>

namespace cmfilter {

struct PlainLookupOptions {
    double bound = 0.1;        // CIEDE2000 between T(v, sigma) and C0(v); finite, > 0
    double sigma_cap = 0;      // search no further (a table's sigma_max); finite, > 0
    int points_per_texel = 8;  // >= 1
    int threads = 0;           // 0: all cores
};

// The per-value threshold: a mean v with sigma < below(v) may take C0(v).
class PlainLookupSigma {
public:
    PlainLookupSigma() = default;  // never: below() is 0 everywhere
    PlainLookupSigma(double v_first, double v_step, std::vector<float> cells);

    double below(double v) const
    {
        const double t = (v - v_first_) * inv_step_;
        if (!(t >= 0 && t < static_cast<double>(cells_.size()))) return 0;  // NaN too
        return cells_[static_cast<std::size_t>(t)];
    }

    bool empty() const { return cells_.empty(); }
    // Over the cells: the smallest, the median and the largest threshold.
    double smallest() const;
    double median() const;
    double largest() const;
    // The cells' value range and thresholds (cell c covers
    // [v_first + c v_step, v_first + (c + 1) v_step)).
    double v_first() const { return v_first_; }
    double v_step() const { return inv_step_ > 0 ? 1 / inv_step_ : 0; }
    const std::vector<float>& cells() const { return cells_; }

private:
    double v_first_ = 0, inv_step_ = 0;
    std::vector<float> cells_;
};

// BadInput for a bound, cap or point count out of range, or an invalid map.
// The result does not depend on the thread count.
Expected<PlainLookupSigma> plain_lookup_sigma(const ColorMap& map, const PlainLookupOptions& options);

}  // namespace cmfilter
