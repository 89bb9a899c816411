// SPDX-License-Identifier: Apache-2.0
// Moment tables of a textured displacement's slopes weighted by Smith's
// masking from each point's height, for the `gaussian` methods' D_s there
// (Heitz et al. 2013, sec. 5.2, extended as displacement_masking.h says).
//
// Eq. 20 takes the slopes a viewer sees as the surface's slopes weighted by
// their projected area alone; that holds where heights and slopes are
// independent. On a relief they are not (scales: flat tops high, steep rims
// low), and Smith's height form (eq. 2) sees a point of height h with
// probability G1 = F(h)^Lambda_o. The Gaussian D_s is then fitted to the
// slopes weighted by G1: for each Lambda of a fixed set the table holds,
// over each cell of the repeat, the means of
//     w, w s_x, w s_y, w s_x^2, w s_y^2, w s_x s_y,   w = F(h)^Lambda,
// in a summed-area table (periodic_summed_area.h), so that any footprint's
// weighted slope mean and covariance, and its mean G1, are four lookups per
// Lambda: moment mipmaps of the masked slopes. Lambda = 0 gives the plain
// moments. The set: 0 and 2^k for k = -5 .. 9. Between two of them the
// weight's reciprocal is linear in Lambda (1 / E[F^Lambda] = 1 + Lambda for
// a uniform F); the weighted means are linear, the variances geometric and
// the correlation linear in log2 Lambda (linear in Lambda below 2^-5), so
// the covariance stays positive semi-definite. Against a dense grid on the
// bundled snake that is within 0.2% for G1 and 3.3% for the slope variances
// (unit tests). Beyond 512 (a view within a few hundredths of a degree of
// the horizon) the table holds 512's.
//
// Each cell's means come from a midpoint rule over the bilinear surface (G1
// is not polynomial): 2 points per texel and axis, at most 16 per cell and
// axis. The cells are min(N, 128) per side whatever N (a cell need not be a
// whole number of texels), so the table is at most 129^2 x 96 doubles
// (13 MB) and built from at most 2048^2 surface points.
#pragma once

#include "cmfilter/microsurface/displacement_masking.h"
#include "cmfilter/math/periodic_summed_area.h"

#include <array>
#include <functional>

namespace cmfilter {

// The channels of a weighted moment: w, w s_x, w s_y, w s_x^2, w s_y^2, w s_x s_y.
using MaskedMoments = std::array<double, 6>;

class MaskedSlopeTable {
public:
    static constexpr int kLambdas = 16;
    static constexpr int kMaxCells = 128;
    static constexpr int kMaxPoints = 16;

    MaskedSlopeTable() = default;
    // surface(u, v, h, sx, sy): the height and slopes at (u, v) in [0, 1)^2;
    // n texels per side; `masking` gives F.
    static MaskedSlopeTable build(const std::function<void(double, double, double&, double&, double&)>& surface, int n,
                                  const DisplacementMasking& masking);

    int cells() const { return table_.size(); }  // per side
    // The weighted means over the box [u0, u0 + wu] x [v0, v0 + wv] (texture
    // units, any reals, wu and wv > 0) for this Lambda (>= 0; NaN reads as 0).
    MaskedMoments box(double u0, double v0, double wu, double wv, double lambda) const;
    // The same over the whole repeat.
    MaskedMoments repeat(double lambda) const;

private:
    PeriodicSummedArea table_;  // kLambdas x 6 channels
    MaskedMoments blend(const double* channels, double lambda) const;
};

}  // namespace cmfilter
