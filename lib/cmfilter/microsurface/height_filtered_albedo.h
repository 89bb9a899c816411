// SPDX-License-Identifier: Apache-2.0
// The albedo of a height-coloured microsurface over one footprint (Heitz et
// al. 2013, sec. 5.1), for each representation of the height filtering
// distribution D_h (eqs. 15-16) `render` offers:
//   naive           C_h(mean height): the footprint's resolved mean, with no
//                   masking or shadowing;
//   paper-fit       V T(mean + mu_d, sigma_d), the Gaussian table (eq. 10) at
//                   the paper's fit of D_h's moments (eqs. 17-18);
//   exact-moments   the same with D_h's exact mean and central sigma
//                   (height_moment_table.h);
//   exact           V <C_h, D_h> without a Gaussian (height_color.h);
// with V the mean visibility of eq. 13 (eq. 14 multiplies it in). D_h is
// taken over the heights the footprint does not resolve (sigma_h and the
// slopes' sigma_s along the view's and the light's azimuths, from
// microsurface_footprint.h), about the resolved mean height; Lambda_o and
// Lambda_i are Smith's (eq. 3) for those slopes.
//
// The heights the footprint resolves are geometry: the light can be hidden
// from the pixel's point by the resolved bumps around it. Where a renderer
// does not displace them (render's one-ray methods colour a flat plane),
// every representation but naive multiplies in their expected shadowing,
// Smith's visibility (eq. 2) of a point at the resolved height h_r on the
// resolved surface (sigma_r, and its slopes along the light's azimuth):
//     V_r = Phi(h_r / sigma_r)^Lambda_r(theta_i).
// It is 1 far away (nothing resolved: Lambda_r -> 0) and the expected
// shadowing of the point itself close up (everything resolved), so the
// albedo is continuous from one to the other; in between it takes the
// resolved and the unresolved shadowing as independent.
#pragma once

#include "cmfilter/color/color.h"
#include "cmfilter/tables/color_layer.h"
#include "cmfilter/tables/gaussian_albedo.h"
#include "cmfilter/microsurface/height_moment_table.h"
#include "cmfilter/microsurface/microsurface_footprint.h"
#include "cmfilter/microsurface/smith_lambda.h"

namespace cmfilter {

enum class HeightRepresentation { Naive, PaperFit, ExactMoments, Exact };

// The view (towards the viewer) and the light (towards it) in the
// microsurface's frame: angles from its mean normal, in [0, pi/2] (beyond:
// below the surface, read as pi/2), and azimuths from its x axis.
struct HeightDirections {
    double theta_o = 0, phi_o = 0, theta_i = 0, phi_i = 0;
};

// Eq. 13's mean visibility for the unresolved slopes and V_r for the
// resolved heights; their product shadows every microsurface colour layer
// (eqs. 14 and 19).
struct MicrosurfaceVisibility {
    double lambda_o = 0, lambda_i = 0;
    double lambda_sum = 0;           // Lambda_o + Lambda_i (or their correlated form) (eq. 3)
    double visibility = 1;           // eq. 13
    double resolved_visibility = 1;  // V_r
    double total() const { return visibility * resolved_visibility; }
};

MicrosurfaceVisibility microsurface_visibility(const MicrosurfaceFootprint& footprint,
                                               const HeightDirections& directions,
                                               MaskingShadowing masking = MaskingShadowing::Uncorrelated);

struct HeightAlbedo {
    Rgb albedo;                      // visibility * resolved_visibility * colour (naive: colour)
    Rgb colour;                      // <C_h, D_h> in the representation asked for, unshadowed
    double mean = 0, sigma = 0;      // of the heights seen lit (the naive method: the resolved mean, sigma 0)
    double lambda_sum = 0;           // Lambda_o + Lambda_i (or their correlated form) (eq. 3)
    double visibility = 1;           // eq. 13
    double resolved_visibility = 1;  // V_r
};

// V_r: Phi(height / sigma_r)^lambda, 1 where sigma_r or lambda is 0, and
// for an infinite lambda 0 below the highest point.
double resolved_visibility(double height, double sigma_r, double lambda);

// `heights` is C_h and its table; `table` serves ExactMoments; `counts`
// counts the table lookups as
// gaussian_albedo does. `masking` chooses how the Lambdas combine
// (smith_lambda.h): the paper's sum (eq. 13), or correlated by the
// directions' azimuths.
HeightAlbedo height_filtered_albedo(const ColorLayer& heights, const MicrosurfaceFootprint& footprint,
                                    const HeightDirections& directions, HeightRepresentation representation,
                                    const HeightMomentTable& table, AlbedoCounts& counts,
                                    MaskingShadowing masking = MaskingShadowing::Uncorrelated);

}  // namespace cmfilter
