// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/microsurface/slope_filtering.h"

#include "cmfilter/math/scaled_erfc.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cmfilter {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kSqrt2 = 1.41421356237309504880;

// Beyond this distance x = -k of the clamp below the mean (in standard
// deviations) the ratios q_n come from their continued fraction; closer, from
// the Mills ratio through erfcx. The two agree to about 1e-13 relative there
// (a unit test; docs/slope.md, step 7).
constexpr double kContinuedFractionFrom = 3;

double sanitised(double v) { return std::isnan(v) ? 0.0 : v; }

// The standard normal z weighted by (k - z)_+ (docs/slope.md, steps 2-4).
// With y = k - z >= 0 and x = -k its moments are those of
// I_n(x) = int_0^inf y^n e^{-x y - y^2/2} dy, whose ratios q_n = I_n / I_{n-1}
// obey q_n = n / (x + q_{n+1}) (from I_{n+1} = n I_{n-1} - x I_n, integration
// by parts) and I_0 = R(x), the Mills ratio (1 - Phi(x)) / phi(x).
struct ClampedLinearNormal {
    // E[z] for k >= 0; for k < 0 the mean from the clamp, E[z] - k = -E[y],
    // which stays finite as k -> -inf.
    double shift = 0;
    double variance = 1;  // Var[z] = Var[y]
};

ClampedLinearNormal clamped_linear_normal(double k)
{
    if (k >= 0) {
        // h = phi(k) / Phi(k), q_1 = k + h:
        //   E[z] = -1 / q_1,  Var[z] = 1 + h / q_1 - 1 / q_1^2,
        // every term O(1) or smaller for k >= 0 (Var[z] >= 0.43).
        if (std::isinf(k)) return {0.0, 1.0};
        const double h = std::sqrt(2 / kPi) * std::exp(-0.5 * k * k) / std::erfc(-k / kSqrt2);
        const double q1 = k + h;
        return {-1 / q1, 1 + h / q1 - 1 / (q1 * q1)};
    }
    const double x = -k;
    if (std::isinf(x)) return {0.0, 0.0};  // all weight at z = k
    if (x < kContinuedFractionFrom) {
        // h = 1 / R(x), q_1 = h - x, E[z] = -1 / q_1 as for k >= 0, so
        // E[y] = k - E[z] = 1 / q_1 - x.
        const double R = std::sqrt(kPi / 2) * scaled_erfc(x / kSqrt2);
        const double h = 1 / R, q1 = h - x;
        return {x - 1 / q1, 1 + h / q1 - 1 / (q1 * q1)};
    }
    // q_4, q_3, q_2 from the continued fraction (80 levels), then
    //   E[y] = q_2,  Var[y] = q_2 (q_3 - q_2) = q_2 (x + 3 q_3 - 2 q_4) / ((x + q_3)(x + q_4)),
    // the last form without cancellation (E[y] ~ 2/x, Var[y] ~ 2/x^2).
    double tail = 0, q2 = 0, q3 = 0, q4 = 0;
    for (int n = 80; n >= 2; --n) {
        tail = n / (x + tail);
        if (n == 4) q4 = tail;
        if (n == 3) q3 = tail;
    }
    q2 = tail;
    return {-q2, q2 * ((x + 3 * q3 - 2 * q4) / (x + q3)) / (x + q4)};
}

// The law of u = <s, d> under D_s, and the normalisation.
struct ViewSlopeLaw {
    double mean = 0, variance = 0, normalisation = 0;
};

ViewSlopeLaw view_slope_law(const SlopeViewFrame& f)
{
    // Eq. 20's weight (a - b u)_+ = scale (k - z)_+, z = (u - mean_u) / sigma_u
    // (docs/slope.md, steps 1 and 3).
    const double a = f.cos_theta, b = f.sin_theta;
    const double margin = a - b * f.mean_u;  // the weight at u = mean_u
    const double scale = b * f.sigma_u;      // the weight's slope in z
    if (!(scale > 0)) {
        // The weight is constant over the slopes there are: D_s = p, or no
        // facet faces the viewer and the limit of a vanishing spread along d
        // puts u at the horizon, cot t (b > 0 here since a - b mean_u <= 0).
        if (margin > 0) return {f.mean_u, f.sigma_u * f.sigma_u, margin};
        return {a / b, 0.0, 0.0};
    }
    const double k = margin / scale;
    const ClampedLinearNormal z = clamped_linear_normal(k);
    const double variance = f.sigma_u * f.sigma_u * z.variance;
    if (k >= 0) {
        // Eq. 20's normalisation Z = scale (k Phi(k) + phi(k)) = margin Phi(k) +
        // scale phi(k); cos t (1 + Lambda) of eq. 3 for m = 0 (step 5).
        const double Z = margin * 0.5 * std::erfc(-k / kSqrt2) + scale * std::exp(-0.5 * k * k) / std::sqrt(2 * kPi);
        return {f.mean_u + f.sigma_u * z.shift, variance, Z};
    }
    // u = cot t - sigma y: E[u] = cot t - sigma E[y]; cot t = a / b (b > 0).
    // Z = scale phi(k) I_1(x), I_1 = q_1 R = q_1 / (x + q_1) (q_1 = 1 / (x + q_2)).
    const double x = -k;
    double I1;
    if (x < kContinuedFractionFrom) {
        I1 = 1 - x * std::sqrt(kPi / 2) * scaled_erfc(x / kSqrt2);
    } else {
        const double q1 = 1 / (x - z.shift);  // q_2 = -shift
        I1 = q1 / (x + q1);
    }
    const double Z = std::isinf(x) ? 0.0 : scale * std::exp(-0.5 * x * x) / std::sqrt(2 * kPi) * I1;
    return {a / b + f.sigma_u * z.shift, variance, Z};
}

}  // namespace

SlopeViewFrame slope_view_frame(const SlopeGaussian& slopes, const ViewAngles& view)
{
    SlopeViewFrame f;
    const double theta = sanitised(view.theta);
    if (theta >= kPi / 2) {
        f.cos_theta = 0, f.sin_theta = 1;
    } else if (theta > 0) {
        f.cos_theta = std::cos(theta), f.sin_theta = std::sin(theta);
    }
    const double phi = std::isfinite(view.phi) ? view.phi : 0.0;
    const double c = std::cos(phi), sn = std::sin(phi);
    f.dx = c, f.dy = sn;
    const double mx = sanitised(slopes.mean_x), my = sanitised(slopes.mean_y);
    const double xx = std::max(0.0, sanitised(slopes.xx)), yy = std::max(0.0, sanitised(slopes.yy));
    const double bound = std::sqrt(xx * yy);
    const double xy = std::clamp(sanitised(slopes.xy), -bound, bound);
    f.mean_u = mx * c + my * sn;
    f.mean_v = -mx * sn + my * c;
    // Sigma in the frame (d, e): d^T Sigma d, d^T Sigma e, e^T Sigma e.
    const double uu = std::max(0.0, xx * c * c + 2 * xy * c * sn + yy * sn * sn);
    const double uv = (yy - xx) * c * sn + xy * (c * c - sn * sn);
    const double vv = std::max(0.0, xx * sn * sn - 2 * xy * c * sn + yy * c * c);
    f.sigma_u = std::sqrt(uu);
    if (uu > 0) {
        f.regression = uv / uu;
        // det Sigma / d^T Sigma d = e^T Sigma e - (d^T Sigma e)^2 / d^T Sigma d,
        // the determinant being the same in every frame (and free of the
        // cancellation of the right-hand side where Sigma is nearly singular
        // across d); the right-hand side where the determinant overflows.
        double residual = (xx * yy - xy * xy) / uu;
        if (!std::isfinite(residual)) residual = vv - uv * (uv / uu);
        f.residual_variance = residual >= 0 ? std::min(residual, vv) : 0.0;
    } else {
        f.residual_variance = vv;  // d^T Sigma e = 0 too (Sigma >= 0)
    }
    return f;
}

Status validate(const SlopeGaussian& slopes, const std::string& what)
{
    const double v[5] = {slopes.mean_x, slopes.mean_y, slopes.xx, slopes.xy, slopes.yy};
    for (double x : v) {
        if (!std::isfinite(x)) return bad_input(what + ": a slope mean or covariance entry is not finite");
    }
    if (slopes.xx < 0 || slopes.yy < 0) {
        std::ostringstream msg;
        msg << what << ": slope variances " << slopes.xx << " and " << slopes.yy << " must be >= 0";
        return bad_input(msg.str());
    }
    if (slopes.xy * slopes.xy > slopes.xx * slopes.yy * (1 + 1e-12)) {
        std::ostringstream msg;
        msg << what << ": slope covariance xy = " << slopes.xy
            << " exceeds sqrt(xx yy) = " << std::sqrt(slopes.xx * slopes.yy) << " (not positive semi-definite)";
        return bad_input(msg.str());
    }
    return ok();
}

double slope_filtering_normalisation(const SlopeGaussian& slopes, const ViewAngles& view)
{
    return view_slope_law(slope_view_frame(slopes, view)).normalisation;
}

SlopeMoments exact_slope_moments(const SlopeGaussian& slopes, const ViewAngles& view)
{
    const SlopeViewFrame f = slope_view_frame(slopes, view);
    const ViewSlopeLaw u = view_slope_law(f);
    // v = mean_v + regression (u - mean_u) + r, r independent of u:
    //   E[v] = mean_v + regression (E[u] - mean_u),
    //   Cov[u, v] = regression Var[u],  Var[v] = residual + regression^2 Var[u].
    const double mean_v = f.mean_v + f.regression * (u.mean - f.mean_u);
    const double uv = f.regression * u.variance;
    const double vv = f.residual_variance + f.regression * uv;
    // Back to (x, y): s = u d + v e, d = (cos p, sin p), e = (-sin p, cos p).
    const double c = f.dx, sn = f.dy;
    SlopeMoments m;
    m.mean_x = f.slope_x(u.mean, mean_v);
    m.mean_y = f.slope_y(u.mean, mean_v);
    m.xx = std::max(0.0, u.variance * c * c - 2 * uv * c * sn + vv * sn * sn);
    m.xy = (u.variance - vv) * c * sn + uv * (c * c - sn * sn);
    m.yy = std::max(0.0, u.variance * sn * sn + 2 * uv * c * sn + vv * c * c);
    return m;
}

}  // namespace cmfilter
