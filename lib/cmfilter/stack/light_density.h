// SPDX-License-Identifier: Apache-2.0
// How evenly a stack's lights cover the hemisphere, for fits that would
// otherwise follow the dense parts of an uneven dome (the second paper,
// sec. 5: "the sampling over the hemisphere is often not evenly spread and
// the Levenberg-Marquardt-method produce visual artifacts").
//
// Density weights: light k's neighbourhood count n_k is the number of
// lights (itself included) at most `radius` radians from it; its weight is
// proportional to 1 / n_k, scaled so that the weights average 1. In a
// weighted least-squares fit a cluster of lights then counts about as much
// as one light of an even dome covering the same solid angle: the light
// set resampled to an even density, without interpolating images.
//
// Spacing: the mean over the lights of the angle to the nearest other light.
// A lobe max(0, a . u)^n falls to half its peak at the angle
// theta_h = acos(2^(-1/n)); a lobe whose full width at half maximum 2
// theta_h is below the spacing can sit between lights, unseen by them, so
// its exponent is not determined by the images. The widest such exponent:
//   n(s) = ln 2 / -ln cos(s / 2)   (2 theta_h = s).
#pragma once

#include "cmfilter/math/vec3.h"

#include <vector>

namespace cmfilter {

// The weights above (mean 1); all 1 when radius <= 0 or fewer than 2
// lights. Lights are taken as unit directions.
std::vector<double> light_density_weights(const std::vector<Vec3>& lights, double radius);

// The mean nearest-neighbour angle in radians; 0 for fewer than 2 lights.
double mean_light_spacing(const std::vector<Vec3>& lights);

// n(s) above: the exponent whose lobe's full width at half maximum is
// `spacing` radians (> 0; +inf for spacing <= 0).
double exponent_for_lobe_width(double spacing);

}  // namespace cmfilter
