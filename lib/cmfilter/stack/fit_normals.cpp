// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/fit_normals.h"

#include "cmfilter/util/parallel_for.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace cmfilter {

namespace {

constexpr double kPi = 3.14159265358979323846;

// A stationary point counts only when 4 a0 a1 - a2^2 exceeds this fraction
// of a0^2 + a1^2 + a2^2 (else the determinant is taken as zero).
constexpr double kDeterminantTolerance = 1e-9;
// A polynomial whose non-constant terms are all below this fraction of its
// constant term has no direction of its own.
constexpr double kFlatTolerance = 1e-6;

// The boundary search of a PTM: samples of the horizon circle, then golden
// sections around the best one.
constexpr int kCircleSamples = 256;
constexpr int kGoldenSteps = 48;

// The hemisphere search (HSH) works in the shifted polar angle of Gautron
// et al. 2004, beta with cos(beta) = 2 cos(theta) - 1, over the disc
// g = beta (cos phi, sin phi), |g| <= pi (the pole at 0, the horizon on the
// circle |g| = pi): HSH terms are smooth trigonometric polynomials there,
// while in (lu, lv) they are steep near the horizon. A coarse grid of rings
// of equal beta, points per ring growing with its circumference; then a
// compass search in g, its step halved whenever no neighbour improves,
// down to kCompassStep, and Newton steps until they move less than
// kSearchStep; a maximum on the horizon is refined along it.
constexpr int kSearchRings = 16;
constexpr int kSearchPointsOnHorizon = 64;
constexpr double kCompassStep = 1e-2;
constexpr int kCompassMoves = 200;
constexpr int kNewtonIterations = 30;
constexpr double kDifferenceStep = 1e-4;
constexpr double kSearchStep = 1e-9;

using Coefficients = std::array<double, kMaxLinearTerms>;

// The direction at shifted-angle disc point g = (gx, gy), |g| <= pi.
Vec3 shifted_direction(double gx, double gy)
{
    const double beta = std::min(kPi, std::sqrt(gx * gx + gy * gy));
    const double c = 0.5 * (1 + std::cos(beta));
    const double s = std::sqrt(std::max(0.0, 1 - c * c));
    const double phi = std::atan2(gy, gx);
    return {s * std::cos(phi), s * std::sin(phi), c};
}

double model_value(LinearModel model, const Coefficients& a, const Vec3& l)
{
    const auto b = evaluate_basis(model, l);
    double v = 0;
    for (int k = 0; k < basis_terms(model); ++k) v += a[static_cast<std::size_t>(k)] * b[static_cast<std::size_t>(k)];
    return v;
}

double ptm_value(const Coefficients& a, double lu, double lv)
{
    return a[0] * lu * lu + a[1] * lv * lv + a[2] * lu * lv + a[3] * lu + a[4] * lv + a[5];
}

// The coarse grid of the hemisphere search, its basis evaluated once.
struct SearchGrid {
    std::vector<double> gx, gy;
    std::vector<Coefficients> basis;
};

SearchGrid make_search_grid(LinearModel model)
{
    SearchGrid g;
    const auto add = [&](double x, double y) {
        g.gx.push_back(x);
        g.gy.push_back(y);
        g.basis.push_back(evaluate_basis(model, shifted_direction(x, y)));
    };
    add(0, 0);
    for (int ring = 1; ring <= kSearchRings; ++ring) {
        const double beta = kPi * ring / kSearchRings;
        const int points = std::max(6, static_cast<int>(std::lround(kSearchPointsOnHorizon * ring / kSearchRings)));
        for (int i = 0; i < points; ++i) {
            const double phi = 2 * kPi * (i + 0.5 * (ring % 2)) / points;
            add(beta * std::cos(phi), beta * std::sin(phi));
        }
    }
    return g;
}

struct SearchResult {
    Vec3 direction{0, 0, 1};
    bool flat = false;     // no direction is better than another
    bool horizon = false;  // the maximum lies on the horizon
};

SearchResult search_hemisphere(LinearModel model, const Coefficients& a, const SearchGrid& grid)
{
    const int terms = basis_terms(model);
    std::size_t best_i = 0;
    double best = -std::numeric_limits<double>::infinity(), worst = -best;
    for (std::size_t i = 0; i < grid.gx.size(); ++i) {
        double f = 0;
        for (int k = 0; k < terms; ++k)
            f += a[static_cast<std::size_t>(k)] * grid.basis[i][static_cast<std::size_t>(k)];
        worst = std::min(worst, f);
        if (f > best) {
            best = f;
            best_i = i;
        }
    }
    SearchResult result;
    if (!(best - worst > 1e-12 * std::max(std::abs(best), std::abs(worst))) || !std::isfinite(best)) {
        result.flat = true;
        return result;
    }
    double x0 = grid.gx[best_i], y0 = grid.gy[best_i];
    // The value at g, projected onto the disc |g| <= pi.
    const auto value = [&](double x, double y) {
        const double r = std::sqrt(x * x + y * y);
        if (r > kPi) {
            x *= kPi / r;
            y *= kPi / r;
        }
        return model_value(model, a, shifted_direction(x, y));
    };
    const auto project = [](double* x, double* y) {
        const double r = std::sqrt(*x * *x + *y * *y);
        if (r > kPi) {
            *x *= kPi / r;
            *y *= kPi / r;
        }
    };
    // A compass search to kCompassStep (a bounded number of moves), ...
    double step = kPi / kSearchRings;
    constexpr double h = 0.70710678118654752;
    const double moves[8][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {h, h}, {-h, h}, {h, -h}, {-h, -h}};
    for (int move = 0; step > kCompassStep && move < kCompassMoves; ++move) {
        bool improved = false;
        for (const auto& m : moves) {
            double x = x0 + step * m[0], y = y0 + step * m[1];
            project(&x, &y);
            const double f = value(x, y);
            if (f > best) {
                best = f;
                x0 = x;
                y0 = y;
                improved = true;
            }
        }
        if (!improved) step *= 0.5;
    }
    // ... then Newton steps with central differences (the function is a
    // smooth trigonometric polynomial in g), each accepted only when it
    // improves, halved until it does; a gradient step where the Hessian is
    // not negative definite.
    for (int iteration = 0; iteration < kNewtonIterations; ++iteration) {
        const double d = kDifferenceStep;
        const double fxp = value(x0 + d, y0), fxm = value(x0 - d, y0);
        const double fyp = value(x0, y0 + d), fym = value(x0, y0 - d);
        const double fpp = value(x0 + d, y0 + d), fpm = value(x0 + d, y0 - d);
        const double fmp = value(x0 - d, y0 + d), fmm = value(x0 - d, y0 - d);
        const double gx = (fxp - fxm) / (2 * d), gy = (fyp - fym) / (2 * d);
        const double hxx = (fxp - 2 * best + fxm) / (d * d), hyy = (fyp - 2 * best + fym) / (d * d);
        const double hxy = (fpp - fpm - fmp + fmm) / (4 * d * d);
        const double det = hxx * hyy - hxy * hxy;
        double dx, dy;
        if (hxx < 0 && det > 0) {
            dx = -(hyy * gx - hxy * gy) / det;
            dy = -(hxx * gy - hxy * gx) / det;
        } else {
            const double norm = std::sqrt(gx * gx + gy * gy);
            if (!(norm > 0)) break;
            dx = step * gx / norm;
            dy = step * gy / norm;
        }
        bool accepted = false;
        for (int halving = 0; halving < 30 && !accepted; ++halving, dx *= 0.5, dy *= 0.5) {
            double x = x0 + dx, y = y0 + dy;
            project(&x, &y);
            const double f = value(x, y);
            if (f > best) {
                accepted = true;
                best = f;
                const double moved = std::hypot(x - x0, y - y0);
                x0 = x;
                y0 = y;
                if (moved < kSearchStep) iteration = kNewtonIterations;
            }
        }
        if (!accepted) break;
    }
    // A maximum on the horizon: golden sections along it.
    if (std::sqrt(x0 * x0 + y0 * y0) > kPi - 1e-6) {
        const double phi0 = std::atan2(y0, x0), width = 2 * kPi / kSearchPointsOnHorizon;
        const auto on_horizon = [&](double phi) { return value(kPi * std::cos(phi), kPi * std::sin(phi)); };
        double lo = phi0 - width, hi = phi0 + width;
        const double g = 0.61803398874989485;
        for (int i = 0; i < kGoldenSteps; ++i) {
            const double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
            if (on_horizon(x1) > on_horizon(x2)) hi = x2;
            else lo = x1;
        }
        const double phi = 0.5 * (lo + hi);
        if (on_horizon(phi) > best) {
            x0 = kPi * std::cos(phi);
            y0 = kPi * std::sin(phi);
        }
    }
    result.direction = shifted_direction(x0, y0);
    result.horizon = std::sqrt(x0 * x0 + y0 * y0) > kPi - 1e-6;
    return result;
}

// A quadratic without an interior maximum in the unit disc (its Hessian not
// negative definite, or its stationary point outside) is largest on the
// disc's boundary: the best of kCircleSamples angles, refined by golden
// sections between its neighbours.
Vec3 ptm_boundary_maximum(const Coefficients& a)
{
    const auto f = [&](double t) { return ptm_value(a, std::cos(t), std::sin(t)); };
    const double dt = 2 * kPi / kCircleSamples;
    int best_i = 0;
    double best = f(0);
    for (int i = 1; i < kCircleSamples; ++i) {
        const double v = f(i * dt);
        if (v > best) {
            best = v;
            best_i = i;
        }
    }
    double lo = (best_i - 1) * dt, hi = (best_i + 1) * dt;
    const double g = 0.61803398874989485;
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    double f1 = f(x1), f2 = f(x2);
    for (int i = 0; i < kGoldenSteps; ++i) {
        if (f1 > f2) {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - g * (hi - lo);
            f1 = f(x1);
        } else {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + g * (hi - lo);
            f2 = f(x2);
        }
    }
    double t = 0.5 * (lo + hi);
    if (f(t) < best) t = best_i * dt;
    return {std::cos(t), std::sin(t), 0};
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
        for (int k = 0; k < terms; ++k) a[static_cast<std::size_t>(k)] += kRec709Luminance[c] * coef[c * terms + k];
    return a;
}

// A PTM texel's normal; false when it is degenerate.
bool ptm_normal(const Coefficients& a, Vec3* n)
{
    double linear_and_quadratic = 0;
    for (int k = 0; k < 5; ++k) linear_and_quadratic = std::max(linear_and_quadratic, std::abs(a[k]));
    if (!(linear_and_quadratic > kFlatTolerance * std::abs(a[5]))) {
        *n = {0, 0, 1};
        return false;
    }
    // Malzbender et al. 2001, eqs. 16-17: the zero of the polynomial's
    // gradient; a maximum when its Hessian [[2 a0, a2], [a2, 2 a1]] is
    // negative definite (4 a0 a1 - a2^2 > 0 and a0 < 0).
    const double det = 4 * a[0] * a[1] - a[2] * a[2];
    const double scale = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
    if (scale > 0 && det > kDeterminantTolerance * scale && a[0] < 0) {
        const double lu = (a[2] * a[4] - 2 * a[1] * a[3]) / det;
        const double lv = (a[2] * a[3] - 2 * a[0] * a[4]) / det;
        const double r2 = lu * lu + lv * lv;
        if (std::isfinite(r2) && r2 < 1) {
            *n = {lu, lv, std::sqrt(1 - r2)};
            return true;
        }
    }
    *n = ptm_boundary_maximum(a);
    return false;
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
    const SearchGrid grid = ptm ? SearchGrid{} : make_search_grid(fit.model);
    std::vector<unsigned char> degenerate(texels, 0);
    parallel_for(fit.height, threads, [&](int y) {
        for (std::size_t t = static_cast<std::size_t>(y) * fit.width; t < static_cast<std::size_t>(y + 1) * fit.width;
             ++t) {
            const Coefficients a = luminance_coefficients(fit, t);
            Vec3 n{0, 0, 1};
            bool interior = false;
            if (ptm) {
                interior = ptm_normal(a, &n);
            } else {
                const SearchResult s = search_hemisphere(fit.model, a, grid);
                n = s.direction;
                interior = !s.flat && !s.horizon;
            }
            if (!interior) degenerate[t] = 1;
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
