// SPDX-License-Identifier: Apache-2.0
// Smith's masking and shadowing on a textured displacement from the
// texture's own statistics rather than a Gaussian's (Heitz et al. 2013,
// eqs. 2-3; Heitz 2014, "Understanding the masking-shadowing function in
// microfacet-based BRDFs", secs. 5-6).
//
// Smith's model takes the surface a ray crosses as uncorrelated with the
// point it leaves from, so a ray leaving a point of height h towards a
// direction omega escapes with probability
//     G1(omega, h) = F(h)^Lambda(omega)                         (eq. 2)
// for F the surface's height CDF and Lambda the mean number of crossings per
// unit of height, which for any slope distribution is
//     Lambda(omega) = E[(q - mu)_+] / mu,  q = <s, d>, mu = cot theta,  (eq. 3)
// d the direction's azimuth in the plane: the slopes steeper than the ray
// along it (eq. 3 is this expectation for Gaussian slopes). Both come here
// from the texels: F is their heights' empirical CDF and Lambda the mean over
// their slopes, so non-Gaussian relief (the flat tops and steep rims of
// scales) gets its own Lambda. What eq. 20 then leaves out, and a sampled
// footprint can keep, is that heights and slopes are correlated on such a
// relief: the rims lie low and are hidden first at grazing angles. Weighting
// each sampled point by G1(omega_o, h) does that (displacement_slope_color.h).
//
// The texels stand for the whole repeating surface: the occluders of any
// footprint, near or far, are drawn from them.
#pragma once

#include "cmfilter/microsurface/slope_filtering.h"

#include <vector>

namespace cmfilter {

struct DisplacementMaskingOptions {
    int azimuths = 32;       // Lambda tabulated at this many azimuths, linear between; >= 1
    int max_texels = 16384;  // a regular subset of the texels beyond this many; >= 1
};

class DisplacementMasking {
public:
    DisplacementMasking() = default;  // a flat surface: F = 1/2, Lambda = 0
    // Heights and slopes at the texels of one N x N repeat, row-major.
    static DisplacementMasking from_texels(const std::vector<double>& heights, const std::vector<double>& slopes_x,
                                           const std::vector<double>& slopes_y, int n,
                                           const DisplacementMaskingOptions& options = {});

    // F(h): the share of the surface at or below h, in (0, 1); ties take
    // their mid rank, linear between distinct heights.
    double height_cdf(double h) const;
    // Lambda(omega) (eq. 3 for these slopes): 0 at theta = 0, +infinity at
    // 90 degrees wherever a slope rises along the azimuth.
    double lambda(const ViewAngles& direction) const;

private:
    std::vector<double> heights_;                 // sorted
    std::vector<std::vector<double>> projected_;  // per azimuth: q sorted
    std::vector<std::vector<double>> tail_;       // per azimuth: tail_[k] = sum of q from k on
    double lambda_at(int azimuth, double mu) const;
};

}  // namespace cmfilter
