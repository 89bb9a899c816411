// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/microsurface/smith_lambda.h"

#include "cmfilter/math/scaled_erfc.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cmfilter {

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

double smith_lambda_gaussian_cot(double mu, double sigma_s)
{
    if (!(mu >= 0) || std::isinf(mu)) return 0.0;  // theta = 0 (or no direction): nothing masked
    if (mu == 0) return std::numeric_limits<double>::infinity();
    if (!(sigma_s > 0)) return 0.0;  // a flat surface masks nothing below 90 degrees
    // Eq. 3 with a = mu / (sqrt(2) sigma_s):
    //   Lambda = (e^{-a^2} / (a sqrt(pi)) - erfc(a)) / 2
    //          = e^{-a^2} (1 / (a sqrt(pi)) - erfcx(a)) / 2,
    // the bracket computed as written while it holds digits, and from the
    // asymptotic series 1/(a sqrt(pi)) (1/(2a^2) - 3/(4a^4) + 15/(8a^6)) beyond.
    const double a = mu / (std::sqrt(2.0) * sigma_s);
    if (a > 27) return 0.0;  // e^{-a^2} < 1e-316
    double bracket;
    if (a < 8) {
        bracket = 1.0 / (a * std::sqrt(kPi)) - scaled_erfc(a);
    } else {
        const double r = 1.0 / (2 * a * a);
        bracket = r * (1 - 3 * r + 15 * r * r - 105 * r * r * r) / (a * std::sqrt(kPi));
    }
    return std::max(0.0, 0.5 * std::exp(-a * a) * bracket);
}

double smith_lambda_gaussian(double theta, double sigma_s)
{
    if (!(theta > 0)) return 0.0;
    if (theta >= kPi / 2) return std::numeric_limits<double>::infinity();
    return smith_lambda_gaussian_cot(1.0 / std::tan(theta), sigma_s);
}

double mean_visibility(double lambda_o, double lambda_i)
{
    const bool inf_o = std::isinf(lambda_o), inf_i = std::isinf(lambda_i);
    if (inf_o && inf_i) return 0.5;
    if (inf_i) return 0.0;
    if (inf_o) return 1.0;
    return (1 + lambda_o) / (1 + lambda_o + lambda_i);  // eq. 13
}

namespace {

// lambda(phi) of the direction-correlated form, phi folded into [0, pi].
double azimuth_correlation(double azimuth_difference)
{
    const double two_pi = 6.28318530717958647692;
    double phi = std::fabs(std::remainder(azimuth_difference, two_pi));
    if (!std::isfinite(phi)) phi = 0;
    return 4.41 * phi / (4.41 * phi + 1);
}

}  // namespace

double lambda_sum(double lambda_o, double lambda_i, double azimuth_difference, MaskingShadowing masking)
{
    if (masking == MaskingShadowing::Uncorrelated) return lambda_o + lambda_i;
    const double larger = std::max(lambda_o, lambda_i);
    if (std::isinf(larger)) return larger;  // not inf + 0 inf
    return larger + azimuth_correlation(azimuth_difference) * std::min(lambda_o, lambda_i);
}

double mean_visibility(double lambda_o, double lambda_i, double azimuth_difference, MaskingShadowing masking)
{
    if (masking == MaskingShadowing::Uncorrelated) return mean_visibility(lambda_o, lambda_i);
    const double c = azimuth_correlation(azimuth_difference);
    const bool inf_o = std::isinf(lambda_o), inf_i = std::isinf(lambda_i);
    if (inf_o && inf_i) return 1 / (1 + c);  // along equal Lambdas
    if (inf_i) return 0.0;
    if (inf_o) return 1.0;
    const double L = std::max(lambda_o, lambda_i) + c * std::min(lambda_o, lambda_i);
    return std::min(1.0, (1 + lambda_o) / (1 + L));
}

}  // namespace cmfilter
