// SPDX-License-Identifier: Apache-2.0
// The height filtering distribution of a Gaussian microsurface (Heitz et al.
// 2013, sec. 5.1): the heights a viewer sees lit, eqs. 15-16,
//
//   D_h(h) = P_h(h)^L p_h(h) / int P_h^L p_h,    L = Lambda_o + Lambda_i,
//
// for heights h ~ N(0, sigma_h^2) with CDF P_h. With u = P_h(h), D_h is
// (L + 1) u^L on [0, 1]: the heights are distributed as the largest of L + 1
// independent draws of h (for integer L), so their mean grows like
// sigma_h sqrt(2 ln L) and their spread shrinks as L grows.
//
// exact_height_moments gives the exact mean and central standard deviation
// (Gauss-Legendre about the peak of the integrand, in log space: finite for
// every L in [0, inf)); paper_height_fit the paper's Gaussian fit of both
// (eqs. 17-18: mu_d = alpha_mu sigma_h ln(beta_mu L + 1), sigma_d =
// sigma_h / (1 + alpha_sigma ln(beta_sigma L + 1)), with alpha_mu = 0.39,
// beta_mu = 4.75, alpha_sigma = 0.26, beta_sigma = 1.13, ln the natural log;
// eq. 18 writes the raw second moment, but its fit follows the central one).
#pragma once

namespace cmfilter {

struct HeightMoments {
    double mean = 0;   // of h under D_h
    double sigma = 0;  // central standard deviation
};

// sigma_h >= 0 and L >= 0; L is clamped to 1e100 (an infinite Lambda, a
// grazing direction, sees only the highest points: the mean grows without
// bound, and a finite one stands for it), NaN reads as 0.
HeightMoments exact_height_moments(double lambda_sum, double sigma_h);

HeightMoments paper_height_fit(double lambda_sum, double sigma_h);

}  // namespace cmfilter
