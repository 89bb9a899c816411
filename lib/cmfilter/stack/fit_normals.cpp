// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/fit_normals.h"

#include "cmfilter/util/parallel_for.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace cmfilter {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRec709[3] = {0.2126, 0.7152, 0.0722};

// The coarse grid of the search: rings of equal polar angle (0 at the pole
// to 90 degrees at the horizon) and points per ring growing with the ring's
// circumference.
constexpr int kSearchRings = 24;
constexpr int kSearchPointsOnHorizon = 96;
// The local refinement stops when its step in (lu, lv) falls below this.
constexpr double kSearchStep = 1e-7;
// A stationary point counts only when 4 a0 a1 - a2^2 exceeds this fraction
// of a0^2 + a1^2 + a2^2 (else the determinant is taken as zero).
constexpr double kDeterminantTolerance = 1e-9;

using Coefficients = std::array<double, kMaxLinearTerms>;

// The direction over the unit disc point (lu, lv), inside or on the circle.
Vec3 disc_direction(double lu, double lv)
{
    const double r2 = lu * lu + lv * lv;
    if (r2 >= 1) {
        const double r = std::sqrt(r2);
        return {lu / r, lv / r, 0};
    }
    return {lu, lv, std::sqrt(1 - r2)};
}

double evaluate(LinearModel model, const Coefficients& a, double lu, double lv)
{
    const auto b = evaluate_basis(model, disc_direction(lu, lv));
    double v = 0;
    for (int k = 0; k < basis_terms(model); ++k) v += a[static_cast<std::size_t>(k)] * b[static_cast<std::size_t>(k)];
    return v;
}

struct SearchResult {
    Vec3 direction;
    bool flat = false;     // no direction is better than another
    bool horizon = false;  // the maximum lies on the horizon
};

// The maximum of the model over the hemisphere: the best point of a coarse
// grid, then a compass search in (lu, lv) kept inside the unit disc, its
// step halved whenever no neighbour improves.
SearchResult search_hemisphere(LinearModel model, const Coefficients& a)
{
    double best_u = 0, best_v = 0;
    double best = evaluate(model, a, 0, 0);
    double worst = best;
    for (int ring = 1; ring <= kSearchRings; ++ring) {
        const double theta = 0.5 * kPi * ring / kSearchRings;
        const double r = std::sin(theta);
        const int points = std::max(6, static_cast<int>(std::lround(kSearchPointsOnHorizon * r)));
        for (int i = 0; i < points; ++i) {
            const double phi = 2 * kPi * i / points;
            const double u = r * std::cos(phi), v = r * std::sin(phi);
            const double f = evaluate(model, a, u, v);
            worst = std::min(worst, f);
            if (f > best) {
                best = f;
                best_u = u;
                best_v = v;
            }
        }
    }
    SearchResult result;
    if (!(best - worst > 1e-12 * std::max(1.0, std::abs(best)))) {
        result.direction = {0, 0, 1};
        result.flat = true;
        return result;
    }
    double step = std::sin(0.5 * kPi / kSearchRings);
    const double moves[8][2] = {
        {1, 0}, {-1, 0}, {0, 1}, {0, -1}, {0.7071, 0.7071}, {-0.7071, 0.7071}, {0.7071, -0.7071}, {-0.7071, -0.7071}};
    while (step > kSearchStep) {
        bool improved = false;
        for (const auto& m : moves) {
            double u = best_u + step * m[0], v = best_v + step * m[1];
            const double r2 = u * u + v * v;
            if (r2 > 1) {
                const double r = std::sqrt(r2);
                u /= r;
                v /= r;
            }
            const double f = evaluate(model, a, u, v);
            if (f > best) {
                best = f;
                best_u = u;
                best_v = v;
                improved = true;
            }
        }
        if (!improved) step *= 0.5;
    }
    result.direction = disc_direction(best_u, best_v);
    result.horizon = best_u * best_u + best_v * best_v > 1 - 1e-6;
    return result;
}

// The luminance's coefficients of texel `t`: PtmLrgb's own polynomial;
// otherwise the Rec. 709 combination of the first three channels' terms
// (the model is linear in its coefficients), one channel itself, two
// channels their mean.
Coefficients luminance_coefficients(const LinearFit& fit, std::size_t t)
{
    Coefficients a{};
    const float* coef = fit.texel(t);
    const int terms = fit.terms();
    if (fit.model == LinearModel::PtmLrgb || fit.channels == 1) {
        for (int k = 0; k < terms; ++k) a[static_cast<std::size_t>(k)] = coef[k];
        return a;
    }
    if (fit.channels == 2) {
        for (int k = 0; k < terms; ++k) a[static_cast<std::size_t>(k)] = 0.5 * (coef[k] + coef[terms + k]);
        return a;
    }
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < terms; ++k) a[static_cast<std::size_t>(k)] += kRec709[c] * coef[c * terms + k];
    return a;
}

}  // namespace

FitNormals fit_normals(const LinearFit& fit, int threads)
{
    FitNormals out;
    out.width = fit.width;
    out.height = fit.height;
    const std::size_t texels = fit.texels();
    if (fit.coefficients.size() != texels * static_cast<std::size_t>(fit.stride())) return out;
    out.normals.assign(texels * 3, 0.0f);
    const bool ptm = fit.model == LinearModel::PtmRgb || fit.model == LinearModel::PtmLrgb;
    std::vector<unsigned char> degenerate(texels, 0);
    parallel_for(fit.height, threads, [&](int y) {
        for (std::size_t t = static_cast<std::size_t>(y) * fit.width; t < static_cast<std::size_t>(y + 1) * fit.width;
             ++t) {
            const Coefficients a = luminance_coefficients(fit, t);
            Vec3 n{0, 0, 1};
            bool found = false;
            if (ptm) {
                // Malzbender et al. 2001, eqs. 16-17: the zero of the
                // polynomial's gradient; a maximum when its Hessian
                // [[2 a0, a2], [a2, 2 a1]] is negative definite.
                const double det = 4 * a[0] * a[1] - a[2] * a[2];
                const double scale = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
                if (scale > 0 && det > kDeterminantTolerance * scale && a[0] < 0) {
                    const double lu = (a[2] * a[4] - 2 * a[1] * a[3]) / det;
                    const double lv = (a[2] * a[3] - 2 * a[0] * a[4]) / det;
                    const double r2 = lu * lu + lv * lv;
                    if (std::isfinite(r2) && r2 < 1) {
                        n = {lu, lv, std::sqrt(1 - r2)};
                        found = true;
                    }
                }
            }
            if (!found) {
                const SearchResult s = search_hemisphere(fit.model, a);
                n = s.direction;
                // A PTM without an interior maximum, or any model whose
                // maximum is on the horizon or nowhere in particular.
                found = !ptm && !s.flat && !s.horizon;
            }
            if (!found) degenerate[t] = 1;
            float* dst = out.normals.data() + 3 * t;
            dst[0] = static_cast<float>(n.x);
            dst[1] = static_cast<float>(n.y);
            dst[2] = static_cast<float>(n.z);
        }
    });
    for (unsigned char d : degenerate) out.degenerate += d;
    return out;
}

}  // namespace cmfilter
