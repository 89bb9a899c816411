// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/lafortune_scalar_fit.h"

#include "cmfilter/stack/lafortune_model.h"

#include <Eigen/Dense>
#include <ceres/tiny_solver.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace cmfilter {

namespace {

const double kLogMaxExponent = std::log(kLafortuneMaxExponent);
// The pole's clamp for a start axis: z at least this (about 84 degrees
// from the pole).
constexpr double kStartMinZ = 0.1;
constexpr double kCandidateExponents[] = {2, 8, 32, 128};
constexpr int kCandidateLights = 3;

double sigmoid(double t) { return 1 / (1 + std::exp(-t)); }

// rho_d and the lobes' scales: at most 1 + kLafortuneMaxLuminanceLobes
// unknowns, held without allocating.
constexpr int kMaxUnknowns = 1 + kLafortuneMaxLuminanceLobes;
using SmallMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxUnknowns, kMaxUnknowns>;
using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxUnknowns, 1>;

// G = A^T A and h = A^T y by dot products (small: no blocked product).
void normal_equations(const Eigen::MatrixXd& A, const Eigen::Ref<const Eigen::VectorXd>& y, SmallMatrix* G,
                      SmallVector* h)
{
    const int p = static_cast<int>(A.cols());
    G->resize(p, p);
    h->resize(p);
    for (int a = 0; a < p; ++a) {
        (*h)[a] = A.col(a).dot(y);
        for (int b = a; b < p; ++b) (*G)(a, b) = (*G)(b, a) = A.col(a).dot(A.col(b));
    }
}

// Non-negative least squares on the normal equations (Lawson and Hanson
// 1974, NNLS): min |A x - y|^2 over x >= 0, with G = A^T A and h = A^T y.
// `free_set` says which unknowns ended positive.
void solve_nnls(const SmallMatrix& G, const SmallVector& h, SmallVector* x, std::array<char, kMaxUnknowns>* free_set)
{
    const int p = static_cast<int>(h.size());
    x->setZero(p);
    free_set->fill(0);
    const double scale = std::max(G.diagonal().maxCoeff(), 1e-300);
    const double tolerance = 1e-12 * std::max(h.cwiseAbs().maxCoeff(), 1e-300);
    SmallVector z(p);
    for (int outer = 0; outer < 3 * p + 3; ++outer) {
        const SmallVector w = h - G * *x;
        int best = -1;
        for (int j = 0; j < p; ++j)
            if (!(*free_set)[j] && w[j] > tolerance && (best < 0 || w[j] > w[best])) best = j;
        if (best < 0) break;
        (*free_set)[best] = 1;
        for (int inner = 0; inner < p + 1; ++inner) {
            std::array<int, kMaxUnknowns> idx;
            int f = 0;
            for (int j = 0; j < p; ++j)
                if ((*free_set)[j]) idx[f++] = j;
            SmallMatrix Gf(f, f);
            SmallVector hf(f);
            for (int a = 0; a < f; ++a) {
                hf[a] = h[idx[a]];
                for (int b = 0; b < f; ++b) Gf(a, b) = G(idx[a], idx[b]);
                Gf(a, a) += 1e-13 * scale;  // a tiny ridge: two lobes alike stay solvable
            }
            const SmallVector zf = Gf.ldlt().solve(hf);
            z.setZero();
            bool positive = true;
            for (int a = 0; a < f; ++a) {
                z[idx[a]] = zf[a];
                if (!(zf[a] > 0)) positive = false;
            }
            if (positive) {
                *x = z;
                break;
            }
            // Step towards z until the first free unknown reaches 0; it
            // leaves the free set (with any other at 0).
            double alpha = 1;
            int blocking = -1;
            for (int a = 0; a < f; ++a) {
                const int j = idx[a];
                if (z[j] > 0) continue;
                const double step = (*x)[j] / std::max((*x)[j] - z[j], 1e-300);
                if (blocking < 0 || step < alpha) {
                    alpha = step;
                    blocking = j;
                }
            }
            *x += alpha * (z - *x);
            if (blocking >= 0) (*x)[blocking] = 0;
            for (int a = 0; a < f; ++a) {
                const int j = idx[a];
                if (!((*x)[j] > 0)) {
                    (*x)[j] = 0;
                    (*free_set)[j] = 0;
                }
            }
        }
    }
    for (int j = 0; j < p; ++j)
        if (!((*x)[j] > 0)) {
            (*x)[j] = 0;
            (*free_set)[j] = 0;
        }
}

// The model's columns for the given shapes: A (K x (1 + m)) with column 0
// uz and column 1 + i uz g_i, and (optionally) each g_i's derivatives by
// qx, qy and t, times uz.
struct LobeColumns {
    Eigen::MatrixXd A, dqx, dqy, dt;

    void build(const LobeLights& lights, const LobeShape* shapes, int m, bool derivatives)
    {
        const int K = lights.count();
        A.resize(K, 1 + m);
        if (derivatives) {
            dqx.resize(K, m);
            dqy.resize(K, m);
            dt.resize(K, m);
        }
        for (int k = 0; k < K; ++k) A(k, 0) = lights.uz[k];
        for (int i = 0; i < m; ++i) {
            const LobeShape& s = shapes[i];
            const double length = std::sqrt(s.qx * s.qx + s.qy * s.qy + 1);
            const double wx = s.qx / length, wy = s.qy / length, wz = 1 / length;
            const double sig = sigmoid(s.t);
            const double n = std::exp(kLogMaxExponent * sig);
            const double dn_dt = n * kLogMaxExponent * sig * (1 - sig);
            for (int k = 0; k < K; ++k) {
                const double ux = lights.ux[k], uy = lights.uy[k], uz = lights.uz[k];
                const double d = wx * ux + wy * uy + wz * uz;
                if (!(d > 0)) {
                    A(k, 1 + i) = 0;
                    if (derivatives) dqx(k, i) = dqy(k, i) = dt(k, i) = 0;
                    continue;
                }
                const double log_d = std::log(d);
                const double g = std::exp(n * log_d);  // d^n, n >= 1, d <= 1: no overflow
                A(k, 1 + i) = uz * g;
                if (derivatives) {
                    // d(d)/dqx = (ux - d wx) / length (the axis normalised).
                    const double dg_dd = n * g / d;
                    dqx(k, i) = uz * dg_dd * (ux - d * wx) / length;
                    dqy(k, i) = uz * dg_dd * (uy - d * wy) / length;
                    dt(k, i) = uz * g * log_d * dn_dt;
                }
            }
        }
    }
};

// The variable-projection residual for TinySolver: parameters are the
// shapes (qx, qy, t per lobe), residuals A c - y with c the NNLS solution.
class VarProLobes {
public:
    using Scalar = double;
    enum { NUM_RESIDUALS = Eigen::Dynamic, NUM_PARAMETERS = Eigen::Dynamic };

    VarProLobes(const LobeLights& lights, const double* values, int lobes)
        : lights_(lights), y_(Eigen::Map<const Eigen::VectorXd>(values, lights.count())), lobes_(lobes)
    {
    }
    int NumResiduals() const { return lights_.count(); }
    int NumParameters() const { return 3 * lobes_; }

    bool operator()(const double* parameters, double* residuals, double* jacobian) const
    {
        const int K = lights_.count(), m = lobes_;
        shapes_.resize(m);
        for (int i = 0; i < m; ++i) shapes_[i] = {parameters[3 * i], parameters[3 * i + 1], parameters[3 * i + 2]};
        columns_.build(lights_, shapes_.data(), m, jacobian != nullptr);
        const Eigen::MatrixXd& A = columns_.A;
        normal_equations(A, y_, &G_, &h_);
        solve_nnls(G_, h_, &c_, &free_);
        Eigen::Map<Eigen::VectorXd> r(residuals, K);
        r = A * c_;
        r -= y_;
        if (!r.allFinite()) return false;
        if (!jacobian) return true;
        Eigen::Map<Eigen::MatrixXd> J(jacobian, K, 3 * m);
        for (int i = 0; i < m; ++i) {
            J.col(3 * i) = columns_.dqx.col(i) * c_[1 + i];
            J.col(3 * i + 1) = columns_.dqy.col(i) * c_[1 + i];
            J.col(3 * i + 2) = columns_.dt.col(i) * c_[1 + i];
        }
        // Kaufman: project the columns off the span of A's free columns,
        // J -= A_f G_ff^-1 A_f^T J.
        std::array<int, kMaxUnknowns> idx;
        int f = 0;
        for (int j = 0; j < 1 + m; ++j)
            if (free_[j]) idx[f++] = j;
        if (f > 0) {
            SmallMatrix Gf(f, f);
            for (int a = 0; a < f; ++a)
                for (int b = 0; b < f; ++b) Gf(a, b) = G_(idx[a], idx[b]);
            Gf.diagonal().array() += 1e-13 * std::max(G_.diagonal().maxCoeff(), 1e-300);
            const Eigen::LDLT<SmallMatrix> ldlt(Gf);
            SmallVector AtJ(f);
            for (int col = 0; col < 3 * m; ++col) {
                for (int a = 0; a < f; ++a) AtJ[a] = A.col(idx[a]).dot(J.col(col));
                const SmallVector coeff = ldlt.solve(AtJ);
                for (int a = 0; a < f; ++a) J.col(col) -= coeff[a] * A.col(idx[a]);
            }
        }
        return J.allFinite();
    }

private:
    const LobeLights& lights_;
    Eigen::Map<const Eigen::VectorXd> y_;
    int lobes_;
    mutable std::vector<LobeShape> shapes_;
    mutable LobeColumns columns_;
    mutable SmallMatrix G_;
    mutable SmallVector h_, c_;
    mutable std::array<char, kMaxUnknowns> free_;
};

ScalarLobeFit solved(const LobeLights& lights, const double* values, std::vector<LobeShape> shapes)
{
    ScalarLobeFit fit;
    fit.shapes = std::move(shapes);
    fit.sse = solve_lobe_scales(lights, values, fit.shapes, &fit.rho, &fit.scales);
    return fit;
}

// The best start for one more lobe (the coarse search above).
ScalarLobeFit add_lobe(const LobeLights& lights, const double* values, const ScalarLobeFit& current)
{
    const int K = lights.count();
    std::vector<std::pair<double, int>> residual;
    for (int k = 0; k < K; ++k) {
        double model = current.rho;
        for (std::size_t i = 0; i < current.shapes.size(); ++i) {
            const Vec3 w = lobe_shape_axis(current.shapes[i]);
            model += current.scales[i] * lafortune_lobe(w, lobe_shape_exponent(current.shapes[i]),
                                                        {lights.ux[k], lights.uy[k], lights.uz[k]});
        }
        residual.emplace_back(values[k] - lights.uz[k] * model, k);
    }
    // Largest first; ties by the light's index (deterministic).
    std::sort(residual.begin(), residual.end(), [](const auto& a, const auto& b) {
        return a.first > b.first || (a.first == b.first && a.second < b.second);
    });
    std::vector<Vec3> axes{{0, 0, 1}};
    for (int j = 0; j < std::min(kCandidateLights, K); ++j)
        if (residual[j].first > 0) {
            const int k = residual[j].second;
            axes.push_back({lights.ux[k], lights.uy[k], lights.uz[k]});
        }
    // The earlier lobes' columns once; each candidate fills the last.
    const int m = static_cast<int>(current.shapes.size()) + 1;
    std::vector<LobeShape> shapes = current.shapes;
    shapes.push_back({});
    LobeColumns columns;
    columns.build(lights, shapes.data(), m, false);
    const Eigen::Map<const Eigen::VectorXd> y(values, K);
    SmallMatrix G;
    SmallVector h, c;
    std::array<char, kMaxUnknowns> free_set;
    double best_sse = std::numeric_limits<double>::infinity();
    LobeShape best_shape;
    for (const Vec3& axis : axes)
        for (double n : kCandidateExponents) {
            const LobeShape shape = lobe_shape(axis, n);
            const Vec3 w = lobe_shape_axis(shape);
            const double exponent = lobe_shape_exponent(shape);
            for (int k = 0; k < K; ++k)
                columns.A(k, m) = lights.uz[k] *
                                  lafortune_lobe(w, exponent, {lights.ux[k], lights.uy[k], lights.uz[k]});
            normal_equations(columns.A, y, &G, &h);
            solve_nnls(G, h, &c, &free_set);
            const double sse = (columns.A * c - y).squaredNorm();
            if (sse < best_sse) {
                best_sse = sse;
                best_shape = shape;
            }
        }
    shapes.back() = best_shape;
    ScalarLobeFit best = solved(lights, values, std::move(shapes));
    best.fallbacks = current.fallbacks;
    return best;
}

}  // namespace

LobeShape lobe_shape(const Vec3& axis, double exponent)
{
    const double z = std::max(axis.z, kStartMinZ * length(axis));
    const double n = std::clamp(exponent, kLafortuneMinExponent, kLafortuneMaxExponent);
    const double sig = std::clamp(std::log(n) / kLogMaxExponent, 1e-4, 1 - 1e-4);
    return {axis.x / z, axis.y / z, std::log(sig / (1 - sig))};
}

Vec3 lobe_shape_axis(const LobeShape& shape) { return normalize(Vec3{shape.qx, shape.qy, 1}); }

double lobe_shape_exponent(const LobeShape& shape) { return std::exp(kLogMaxExponent * sigmoid(shape.t)); }

LobeLights::LobeLights(const std::vector<Vec3>& lights)
{
    for (const Vec3& l : lights) {
        ux.push_back(l.x);
        uy.push_back(l.y);
        uz.push_back(std::max(0.0, l.z));
    }
}

double solve_lobe_scales(const LobeLights& lights, const double* values, const std::vector<LobeShape>& shapes,
                         double* rho, std::vector<double>* scales)
{
    LobeColumns columns;
    const int m = static_cast<int>(shapes.size());
    columns.build(lights, shapes.data(), m, false);
    const Eigen::Map<const Eigen::VectorXd> y(values, lights.count());
    SmallMatrix G;
    SmallVector h, c;
    std::array<char, kMaxUnknowns> free_set;
    normal_equations(columns.A, y, &G, &h);
    solve_nnls(G, h, &c, &free_set);
    *rho = c[0];
    scales->assign(c.data() + 1, c.data() + 1 + m);
    const double sse = (columns.A * c - y).squaredNorm();
    return std::isfinite(sse) ? sse : std::numeric_limits<double>::infinity();
}

ScalarLobeFit refine_lobes(const LobeLights& lights, const double* values, const std::vector<LobeShape>& start,
                           const ScalarLobeSettings& settings)
{
    ScalarLobeFit initial = solved(lights, values, start);
    if (start.empty() || settings.max_iterations <= 0) return initial;
    const int m = static_cast<int>(start.size());
    VarProLobes function(lights, values, m);
    Eigen::VectorXd x(3 * m);
    for (int i = 0; i < m; ++i) {
        x[3 * i] = start[i].qx;
        x[3 * i + 1] = start[i].qy;
        x[3 * i + 2] = start[i].t;
    }
    ceres::TinySolver<VarProLobes> solver;
    solver.options.max_num_iterations = settings.max_iterations;
    solver.options.function_tolerance = settings.function_tolerance;
    solver.options.parameter_tolerance = 1e-7;
    solver.options.gradient_tolerance = 1e-12;
    solver.Solve(function, &x);
    std::vector<LobeShape> shapes(m);
    bool finite = x.allFinite();
    for (int i = 0; i < m; ++i) shapes[i] = {x[3 * i], x[3 * i + 1], x[3 * i + 2]};
    ScalarLobeFit refined = finite ? solved(lights, values, std::move(shapes)) : ScalarLobeFit{};
    if (!finite || !(refined.sse <= initial.sse)) {
        initial.fallbacks = 1;
        return initial;
    }
    return refined;
}

ScalarLobeFit fit_scalar_lobes(const LobeLights& lights, const double* values, const ScalarLobeSettings& settings)
{
    const int K = lights.count();
    ScalarLobeFit fit = solved(lights, values, {});
    int fallbacks = 0;
    for (int m = 1; m <= settings.lobes; ++m) {
        const double rms = std::sqrt(fit.sse / K);
        if (settings.auto_lobes && rms <= settings.tolerance) break;
        ScalarLobeFit trial = refine_lobes(lights, values, add_lobe(lights, values, fit).shapes, settings);
        fallbacks += trial.fallbacks;
        if (settings.auto_lobes && !(std::sqrt(trial.sse / K) < (1 - settings.min_gain) * rms)) break;
        fit = std::move(trial);
    }
    fit.fallbacks = fallbacks;
    return fit;
}

}  // namespace cmfilter
