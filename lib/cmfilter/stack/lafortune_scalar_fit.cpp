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

    void build(const LobeLights& lights, const LobeShape* shapes, int m, bool derivatives, double max_exponent)
    {
        const int K = lights.count();
        const double log_max = std::log(max_exponent);
        A.resize(K, 1 + m);
        if (derivatives) {
            dqx.resize(K, m);
            dqy.resize(K, m);
            dt.resize(K, m);
        }
        for (int k = 0; k < K; ++k) A(k, 0) = lights.gain[k];
        for (int i = 0; i < m; ++i) {
            const LobeShape& s = shapes[i];
            const double length = std::sqrt(s.qx * s.qx + s.qy * s.qy + 1);
            const double wx = s.qx / length, wy = s.qy / length, wz = 1 / length;
            const double sig = sigmoid(s.t);
            const double n = std::exp(log_max * sig);
            const double dn_dt = n * log_max * sig * (1 - sig);
            for (int k = 0; k < K; ++k) {
                const double ux = lights.ux[k], uy = lights.uy[k], uz = lights.uz[k], gain = lights.gain[k];
                const double d = wx * ux + wy * uy + wz * uz;
                if (!(d > 0)) {
                    A(k, 1 + i) = 0;
                    if (derivatives) dqx(k, i) = dqy(k, i) = dt(k, i) = 0;
                    continue;
                }
                const double log_d = std::log(d);
                const double g = std::exp(n * log_d);  // d^n, n >= 1, d <= 1: no overflow
                A(k, 1 + i) = gain * g;
                if (derivatives) {
                    // d(d)/dqx = (ux - d wx) / length (the axis normalised).
                    const double dg_dd = n * g / d;
                    dqx(k, i) = gain * dg_dd * (ux - d * wx) / length;
                    dqy(k, i) = gain * dg_dd * (uy - d * wy) / length;
                    dt(k, i) = gain * g * log_d * dn_dt;
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

    VarProLobes(const LobeLights& lights, const double* values, int lobes, double max_exponent)
        : lights_(lights), y_(Eigen::Map<const Eigen::VectorXd>(values, lights.count())), lobes_(lobes),
          max_exponent_(max_exponent)
    {
    }
    int NumResiduals() const { return lights_.count(); }
    int NumParameters() const { return 3 * lobes_; }

    bool operator()(const double* parameters, double* residuals, double* jacobian) const
    {
        const int K = lights_.count(), m = lobes_;
        shapes_.resize(m);
        for (int i = 0; i < m; ++i) shapes_[i] = {parameters[3 * i], parameters[3 * i + 1], parameters[3 * i + 2]};
        columns_.build(lights_, shapes_.data(), m, jacobian != nullptr, max_exponent_);
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
    double max_exponent_;
    mutable std::vector<LobeShape> shapes_;
    mutable LobeColumns columns_;
    mutable SmallMatrix G_;
    mutable SmallVector h_, c_;
    mutable std::array<char, kMaxUnknowns> free_;
};

// VarProLobes with one more residual per lobe, the exponent penalty
// (ScalarLobeSettings::exponent_penalty): sqrt(weight) ln(n_i) / ln(500),
// which does not depend on the scales (so is not projected).
class PenalisedLobes {
public:
    using Scalar = double;
    enum { NUM_RESIDUALS = Eigen::Dynamic, NUM_PARAMETERS = Eigen::Dynamic };

    PenalisedLobes(const LobeLights& lights, const double* values, int lobes, double max_exponent, double weight)
        : data_(lights, values, lobes, max_exponent), lights_(lights.count()), lobes_(lobes),
          log_max_(std::log(max_exponent)), root_(std::sqrt(weight))
    {
    }
    int NumResiduals() const { return lights_ + lobes_; }
    int NumParameters() const { return 3 * lobes_; }

    bool operator()(const double* parameters, double* residuals, double* jacobian) const
    {
        const int K = lights_, m = lobes_;
        if (jacobian) data_jacobian_.resize(K, 3 * m);
        if (!data_(parameters, residuals, jacobian ? data_jacobian_.data() : nullptr)) return false;
        const double scale = root_ * log_max_ / std::log(kLafortuneMaxExponent);
        for (int i = 0; i < m; ++i) residuals[K + i] = scale * sigmoid(parameters[3 * i + 2]);
        if (!jacobian) return true;
        Eigen::Map<Eigen::MatrixXd> J(jacobian, K + m, 3 * m);
        J.setZero();
        J.topRows(K) = data_jacobian_;
        for (int i = 0; i < m; ++i) {
            const double sig = sigmoid(parameters[3 * i + 2]);
            J(K + i, 3 * i + 2) = scale * sig * (1 - sig);
        }
        return true;
    }

private:
    VarProLobes data_;
    int lights_, lobes_;
    double log_max_, root_;
    mutable Eigen::MatrixXd data_jacobian_;
};

// The exponent penalty's residual for one lobe (ScalarLobeSettings::
// exponent_penalty): sqrt(weight) ln(n) / ln(kLafortuneMaxExponent).
double penalty_residual(double weight, double exponent)
{
    return std::sqrt(weight) * std::log(exponent) / std::log(kLafortuneMaxExponent);
}

double exponent_penalty(double weight, const std::vector<LobeShape>& shapes, double max_exponent)
{
    if (!(weight > 0)) return 0;
    double sum = 0;
    for (const LobeShape& shape : shapes) {
        const double r = penalty_residual(weight, lobe_shape_exponent(shape, max_exponent));
        sum += r * r;
    }
    return sum;
}

// The values times the lights' root weights: the rows the solver fits.
std::vector<double> weighted_values(const LobeLights& lights, const double* values)
{
    std::vector<double> out(lights.count());
    for (int k = 0; k < lights.count(); ++k) out[k] = values[k] * lights.root_weight[k];
    return out;
}

// The penalty's weight for a scalar's (weighted) values: the settings'
// fraction of their energy.
double penalty_weight(const LobeLights& lights, const double* weighted, const ScalarLobeSettings& settings)
{
    if (!(settings.exponent_penalty > 0)) return 0;
    double energy = 0;
    for (int k = 0; k < lights.count(); ++k) energy += weighted[k] * weighted[k];
    return settings.exponent_penalty * energy;
}

double solve_weighted_scales(const LobeLights& lights, const double* weighted, const std::vector<LobeShape>& shapes,
                             double max_exponent, double* rho, std::vector<double>* scales)
{
    LobeColumns columns;
    const int m = static_cast<int>(shapes.size());
    columns.build(lights, shapes.data(), m, false, max_exponent);
    const Eigen::Map<const Eigen::VectorXd> y(weighted, lights.count());
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

ScalarLobeFit solved(const LobeLights& lights, const double* weighted, std::vector<LobeShape> shapes,
                     double max_exponent, double penalty)
{
    ScalarLobeFit fit;
    fit.shapes = std::move(shapes);
    fit.sse = solve_weighted_scales(lights, weighted, fit.shapes, max_exponent, &fit.rho, &fit.scales);
    fit.penalty = exponent_penalty(penalty, fit.shapes, max_exponent);
    return fit;
}

// The best start for one more lobe (the coarse search above).
ScalarLobeFit add_lobe(const LobeLights& lights, const double* values, const ScalarLobeFit& current,
                       double max_exponent, double penalty)
{
    const int K = lights.count();
    std::vector<std::pair<double, int>> residual;
    for (int k = 0; k < K; ++k) {
        double model = current.rho;
        for (std::size_t i = 0; i < current.shapes.size(); ++i) {
            const Vec3 w = lobe_shape_axis(current.shapes[i]);
            model += current.scales[i] * lafortune_lobe(w, lobe_shape_exponent(current.shapes[i], max_exponent),
                                                        {lights.ux[k], lights.uy[k], lights.uz[k]});
        }
        residual.emplace_back(values[k] - lights.gain[k] * model, k);
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
    columns.build(lights, shapes.data(), m, false, max_exponent);
    const Eigen::Map<const Eigen::VectorXd> y(values, K);
    SmallMatrix G;
    SmallVector h, c;
    std::array<char, kMaxUnknowns> free_set;
    double best_sse = std::numeric_limits<double>::infinity();
    LobeShape best_shape;
    for (const Vec3& axis : axes)
        for (double n : kCandidateExponents) {
            const LobeShape shape = lobe_shape(axis, n, max_exponent);
            const Vec3 w = lobe_shape_axis(shape);
            const double exponent = lobe_shape_exponent(shape, max_exponent);
            for (int k = 0; k < K; ++k)
                columns.A(k, m) = lights.gain[k] *
                                  lafortune_lobe(w, exponent, {lights.ux[k], lights.uy[k], lights.uz[k]});
            normal_equations(columns.A, y, &G, &h);
            solve_nnls(G, h, &c, &free_set);
            double sse = (columns.A * c - y).squaredNorm();
            if (penalty > 0) {
                const double r = penalty_residual(penalty, exponent);
                sse += r * r;
            }
            if (sse < best_sse) {
                best_sse = sse;
                best_shape = shape;
            }
        }
    shapes.back() = best_shape;
    ScalarLobeFit best = solved(lights, values, std::move(shapes), max_exponent, penalty);
    best.fallbacks = current.fallbacks;
    return best;
}

// The Levenberg-Marquardt refinement of weighted values with a penalty
// weight (refine_lobes).
ScalarLobeFit refine_weighted(const LobeLights& lights, const double* weighted, const std::vector<LobeShape>& start,
                              const ScalarLobeSettings& settings, double penalty)
{
    const double max_exponent = settings.max_exponent;
    ScalarLobeFit initial = solved(lights, weighted, start, max_exponent, penalty);
    if (start.empty() || settings.max_iterations <= 0) return initial;
    const int m = static_cast<int>(start.size());
    Eigen::VectorXd x(3 * m);
    for (int i = 0; i < m; ++i) {
        x[3 * i] = start[i].qx;
        x[3 * i + 1] = start[i].qy;
        x[3 * i + 2] = start[i].t;
    }
    auto configure = [&](auto& solver) {
        solver.options.max_num_iterations = settings.max_iterations;
        solver.options.function_tolerance = settings.function_tolerance;
        solver.options.parameter_tolerance = 1e-7;
        solver.options.gradient_tolerance = 1e-12;
    };
    if (penalty > 0) {
        PenalisedLobes function(lights, weighted, m, max_exponent, penalty);
        ceres::TinySolver<PenalisedLobes> solver;
        configure(solver);
        solver.Solve(function, &x);
    } else {
        VarProLobes function(lights, weighted, m, max_exponent);
        ceres::TinySolver<VarProLobes> solver;
        configure(solver);
        solver.Solve(function, &x);
    }
    std::vector<LobeShape> shapes(m);
    bool finite = x.allFinite();
    for (int i = 0; i < m; ++i) shapes[i] = {x[3 * i], x[3 * i + 1], x[3 * i + 2]};
    ScalarLobeFit refined = finite ? solved(lights, weighted, std::move(shapes), max_exponent, penalty)
                                   : ScalarLobeFit{};
    if (!finite || !(refined.sse + refined.penalty <= initial.sse + initial.penalty)) {
        initial.fallbacks = 1;
        return initial;
    }
    return refined;
}

}  // namespace

LobeShape lobe_shape(const Vec3& axis, double exponent, double max_exponent)
{
    const double z = std::max(axis.z, kStartMinZ * length(axis));
    const double n = std::clamp(exponent, kLafortuneMinExponent, max_exponent);
    const double sig = std::clamp(std::log(n) / std::log(max_exponent), 1e-4, 1 - 1e-4);
    return {axis.x / z, axis.y / z, std::log(sig / (1 - sig))};
}

Vec3 lobe_shape_axis(const LobeShape& shape) { return normalize(Vec3{shape.qx, shape.qy, 1}); }

double lobe_shape_exponent(const LobeShape& shape, double max_exponent)
{
    return std::exp(std::log(max_exponent) * sigmoid(shape.t));
}

LobeLights::LobeLights(const std::vector<Vec3>& lights, const std::vector<double>& weights)
{
    for (std::size_t k = 0; k < lights.size(); ++k) {
        const Vec3& l = lights[k];
        const double w = k < weights.size() ? weights[k] : 1.0;
        const double root = w == 1.0 ? 1.0 : std::sqrt(std::max(0.0, w));
        ux.push_back(l.x);
        uy.push_back(l.y);
        uz.push_back(std::max(0.0, l.z));
        root_weight.push_back(root);
        gain.push_back(uz.back() * root);
    }
}

double solve_lobe_scales(const LobeLights& lights, const double* values, const std::vector<LobeShape>& shapes,
                         double* rho, std::vector<double>* scales, double max_exponent)
{
    const std::vector<double> weighted = weighted_values(lights, values);
    return solve_weighted_scales(lights, weighted.data(), shapes, max_exponent, rho, scales);
}

ScalarLobeFit refine_lobes(const LobeLights& lights, const double* values, const std::vector<LobeShape>& start,
                           const ScalarLobeSettings& settings)
{
    const std::vector<double> weighted = weighted_values(lights, values);
    return refine_weighted(lights, weighted.data(), start, settings, penalty_weight(lights, weighted.data(), settings));
}

ScalarLobeFit fit_scalar_lobes(const LobeLights& lights, const double* values, const ScalarLobeSettings& settings)
{
    const int K = lights.count();
    const std::vector<double> weighted = weighted_values(lights, values);
    const double* y = weighted.data();
    const double penalty = penalty_weight(lights, y, settings);
    ScalarLobeFit fit = solved(lights, y, {}, settings.max_exponent, penalty);
    int fallbacks = 0;
    for (int m = 1; m <= settings.lobes; ++m) {
        const double rms = std::sqrt(fit.sse / K);
        if (settings.auto_lobes && rms <= settings.tolerance) break;
        ScalarLobeFit trial = refine_weighted(
            lights, y, add_lobe(lights, y, fit, settings.max_exponent, penalty).shapes, settings, penalty);
        fallbacks += trial.fallbacks;
        if (settings.auto_lobes && !(std::sqrt(trial.sse / K) < (1 - settings.min_gain) * rms)) break;
        fit = std::move(trial);
    }
    fit.fallbacks = fallbacks;
    return fit;
}

}  // namespace cmfilter
