// SPDX-License-Identifier: Apache-2.0
// cmfilter_height.glsl: height-correlated colour on a Gaussian microsurface
// (Heitz et al. 2013, sec. 5.1; docs/microsurface.md): Smith's Lambda
// (eq. 3), the shadowing of a point at a height (eq. 2), the mean visibility
// (eq. 13, and its direction-correlated form), the moments of the height
// filtering distribution D_h by the paper's fit (eqs. 17-18) or by the
// library's exact table (eqs. 15-16), and the filtered colour of eq. 14
// with a Gaussian D_h, V T(h + mu_d, sigma_d). A function library: no
// #version, no main. Needs cmfilter_color_table.glsl before it.
//
// The height moment table. The library tabulates D_h's exact mean and
// central sigma (sigma_h = 1) at `nodes` points uniform in s = ln(1 + L)
// over [0, ln(1 + max_lambda_sum)] (HeightMomentTable; defaults 512 and 1e6).
// Upload them as a nodes x 1 GL_RG32F texture (R = mean, G = sigma);
// cmf_height_moments_table interpolates with texelFetch, as the library.

#ifndef CMFILTER_HEIGHT_GLSL
#define CMFILTER_HEIGHT_GLSL

const float CMF_PI = 3.14159265358979;
#define CMF_INFINITY uintBitsToFloat(0x7f800000u)  // +infinity (GLSL has no literal for it)

// The scaled complementary error function erfcx(a) = erfc(a) e^{a^2},
// a >= 0, by the Chebyshev-fitted form t exp(P(t)), t = 1 / (1 + a / 2), of
// Press et al., Numerical Recipes (erfcc; fractional error below 1.2e-7):
// it keeps Gaussian tails finite where erfc underflows.
float cmf_erfcx(float a)
{
    float t = 1.0 / (1.0 + 0.5 * a);
    float p = -1.26551223 +
              t * (1.00002368 +
                   t * (0.37409196 +
                        t * (0.09678418 +
                             t * (-0.18628806 +
                                  t * (0.27886807 +
                                       t * (-1.13520398 + t * (1.48851587 + t * (-0.82215223 + t * 0.17087277))))))));
    return t * exp(p);
}

// erfc(z) for any z.
float cmf_erfc(float z)
{
    float e = exp(-z * z) * cmf_erfcx(abs(z));
    return z >= 0.0 ? e : 2.0 - e;
}

// ln Phi(x), the standard normal CDF, without underflow on the left.
float cmf_log_normal_cdf(float x)
{
    float z = -x / sqrt(2.0);
    if (z <= 0.0) return log(1.0 - 0.5 * exp(-z * z) * cmf_erfcx(-z));
    return log(0.5 * cmf_erfcx(z)) - z * z;
}

// Eq. 3 from mu = cot theta >= 0:
//   Lambda = sigma_s / (sqrt(2 pi) mu) exp(-mu^2 / (2 sigma_s^2)) - erfc(mu / (sqrt(2) sigma_s)) / 2
//          = e^{-a^2} (1 / (a sqrt(pi)) - erfcx(a)) / 2,   a = mu / (sqrt(2) sigma_s),
// the bracket from the asymptotic series 1/(a sqrt(pi)) (r - 3 r^2 + 15 r^3 - 105 r^4),
// r = 1 / (2 a^2), for a >= 8. 0 head-on (mu infinite), infinite at mu = 0.
float cmf_smith_lambda_cot(float mu, float sigma_s)
{
    if (!(mu >= 0.0) || isinf(mu)) return 0.0;
    if (mu == 0.0) return CMF_INFINITY;
    if (!(sigma_s > 0.0)) return 0.0;
    float a = mu / (sqrt(2.0) * sigma_s);
    if (a > 27.0) return 0.0;
    float bracket;
    if (a < 8.0) {
        bracket = 1.0 / (a * sqrt(CMF_PI)) - cmf_erfcx(a);
    } else {
        float r = 1.0 / (2.0 * a * a);
        bracket = r * (1.0 - 3.0 * r + 15.0 * r * r - 105.0 * r * r * r) / (a * sqrt(CMF_PI));
    }
    return max(0.0, 0.5 * exp(-a * a) * bracket);
}

// Eq. 3 for the direction at theta radians from the mean normal, sigma_s the
// slopes' standard deviation along its azimuth. theta >= pi/2: infinite.
float cmf_smith_lambda(float theta, float sigma_s)
{
    if (!(theta > 0.0)) return 0.0;
    if (theta >= 0.5 * CMF_PI) return CMF_INFINITY;
    return cmf_smith_lambda_cot(1.0 / tan(theta), sigma_s);
}

// Eq. 2: the probability that a point at height h of a surface of height
// deviation sigma_h is visible along a direction of Lambda `lambda`,
// Phi(h / sigma_h)^Lambda (render's V_r for the resolved heights).
float cmf_smith_height_visibility(float h, float sigma_h, float lambda)
{
    if (!(lambda > 0.0) || !(sigma_h > 0.0)) return 1.0;
    float log_phi = cmf_log_normal_cdf(h / sigma_h);
    if (isinf(lambda)) return log_phi < 0.0 ? 0.0 : 1.0;
    return exp(lambda * log_phi);
}

// Masking and shadowing: eq. 13 takes them independent (CMF_UNCORRELATED);
// the direction-correlated form (van Ginneken et al. 1998, as Heitz 2014,
// sec. 6) takes L = max(Lo, Li) + lambda(phi) min(Lo, Li),
// lambda(phi) = 4.41 phi / (4.41 phi + 1) (`render --masking`).
const int CMF_UNCORRELATED = 0;
const int CMF_DIRECTION_CORRELATED = 1;

float cmf_azimuth_correlation(float azimuth_difference)
{
    float two_pi = 2.0 * CMF_PI;
    float phi = abs(azimuth_difference - two_pi * round(azimuth_difference / two_pi));  // folded into [0, pi]
    if (isnan(phi) || isinf(phi)) phi = 0.0;
    return 4.41 * phi / (4.41 * phi + 1.0);
}

// The Lambda sum that weights the heights seen lit, P_h^L (eq. 16).
float cmf_lambda_sum(float lambda_o, float lambda_i, float azimuth_difference, int masking)
{
    if (masking == CMF_UNCORRELATED) return lambda_o + lambda_i;
    float larger = max(lambda_o, lambda_i);
    if (isinf(larger)) return larger;
    return larger + cmf_azimuth_correlation(azimuth_difference) * min(lambda_o, lambda_i);
}

// Eq. 13: the share of the viewed microsurface that is lit,
// (1 + Lambda_o) / (1 + L), with its limits where a Lambda is infinite.
float cmf_mean_visibility(float lambda_o, float lambda_i, float azimuth_difference, int masking)
{
    bool inf_o = isinf(lambda_o), inf_i = isinf(lambda_i);
    if (masking == CMF_UNCORRELATED) {
        if (inf_o && inf_i) return 0.5;
        if (inf_i) return 0.0;
        if (inf_o) return 1.0;
        return (1.0 + lambda_o) / (1.0 + lambda_o + lambda_i);
    }
    float c = cmf_azimuth_correlation(azimuth_difference);
    if (inf_o && inf_i) return 1.0 / (1.0 + c);
    if (inf_i) return 0.0;
    if (inf_o) return 1.0;
    float L = max(lambda_o, lambda_i) + c * min(lambda_o, lambda_i);
    return min(1.0, (1.0 + lambda_o) / (1.0 + L));
}

// Eqs. 17-18 (eq. 18 read as the central sigma): the paper's fit of D_h's
// mean and sigma, mu_d = 0.39 sigma_h ln(4.75 L + 1),
// sigma_d = sigma_h / (1 + 0.26 ln(1.13 L + 1)). Returns (mu_d, sigma_d).
// L is clamped to 1e100 as in the library (an infinite Lambda stands for a
// grazing direction): beyond 1e6, ln(b L + 1) is ln b + ln L, which float
// holds where b L itself would overflow.
float cmf_log_scaled_plus_one(float b, float L)
{
    if (L < 1e6) return log(b * L + 1.0);
    return log(b) + min(isinf(L) ? 230.258509 : log(L), 230.258509);  // ln(1e100)
}

vec2 cmf_height_fit(float lambda_sum, float sigma_h)
{
    float L = max(0.0, isnan(lambda_sum) ? 0.0 : lambda_sum);
    float s = max(0.0, sigma_h);
    return vec2(0.39 * s * cmf_log_scaled_plus_one(4.75, L), s / (1.0 + 0.26 * cmf_log_scaled_plus_one(1.13, L)));
}

// Eqs. 15-16's exact mean and central sigma of D_h from the library's table
// (HeightMomentTable::lookup): linear in s = ln(1 + L) between nodes, L
// beyond max_lambda_sum reads the last node. s_max = ln(1 + max_lambda_sum).
// ln(1 + L) is log(1 + L) where 1 + L holds L's digits, L (1 - L/2) below
// (GLSL has no log1p). Returns (mean, sigma).
vec2 cmf_height_moments_table(sampler2D table, float s_max, float lambda_sum, float sigma_h)
{
    int nodes = textureSize(table, 0).x;
    float L = isnan(lambda_sum) ? 0.0 : max(0.0, lambda_sum);
    float s = isinf(L) ? s_max : min(L < 1e-4 ? L * (1.0 - 0.5 * L) : log(1.0 + L), s_max);
    float x = s / s_max * float(nodes - 1);
    int i = min(int(x), nodes - 2);
    float f = x - float(i);
    vec2 a = texelFetch(table, ivec2(i, 0), 0).rg, b = texelFetch(table, ivec2(i + 1, 0), 0).rg;
    return max(0.0, sigma_h) * ((1.0 - f) * a + f * b);
}

// Eq. 14 with a Gaussian D_h: V T(h_r + mu_d, sigma_d), where
// moments = (mu_d, sigma_d) from cmf_height_fit (`render --method gaussian`)
// or cmf_height_moments_table (`gaussian-exact`), h_r the footprint's
// resolved mean height and `visibility` eq. 13's V (times V_r where the
// resolved heights are not displaced). The table is the height colour map's
// Gaussian table (its driver domain in height units).
vec3 cmf_height_color(sampler2D table, CmfColorTable t, float resolved_height, vec2 moments, float visibility)
{
    return visibility * cmf_color_table_exact(table, t, resolved_height + moments.x, moments.y);
}

#endif  // CMFILTER_HEIGHT_GLSL
