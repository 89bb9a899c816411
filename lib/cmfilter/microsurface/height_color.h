// SPDX-License-Identifier: Apache-2.0
// The exact height-filtered colour <C_h, D_h> of eq. 14 (Heitz et al. 2013,
// sec. 5.1), without the Gaussian approximation of eqs. 17-18: the mean of a
// colour map C_h over the heights the viewer sees lit, distributed as D_h
// (eq. 16) for heights N(0, sigma_h^2) and the Lambda sum L.
//
// D_h's CDF is Phi(h / sigma_h)^(L + 1) (with u = P_h(h), D_h is
// (L + 1) u^L du = d(u^(L+1))), so the heights that carry weight lie where
// it is within [1e-15, 1 - 1e-15]; there the map is piecewise linear between
// its nodes (color_map.h), and <C_h, D_h> = int C_h(h) D_h(h) dh is
// integrated by Gauss-Legendre between the nodes, on panels no wider than
// sigma_h / 4 nor than 1/32 of that range (D_h narrows as L grows), where
// D_h's density is smooth.
// The mean visibility of eq. 13 (smith_lambda.h) multiplies it in eq. 14.
#pragma once

#include "cmfilter/colormap/color_map.h"

namespace cmfilter {

// sigma_h >= 0 (0: C_h(offset)); L >= 0 (NaN reads as 0, beyond 1e100 as
// 1e100). The heights are offset by `offset` (a resolved mean height,
// microsurface_footprint.h): C_h is read at offset + h for h ~ D_h.
Rgb exact_height_color(const ColorMap& map, double sigma_h, double lambda_sum, double offset = 0);

}  // namespace cmfilter
