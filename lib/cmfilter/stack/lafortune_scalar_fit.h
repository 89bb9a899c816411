// SPDX-License-Identifier: Apache-2.0
// Lafortune lobes fitted to one scalar per light (one texel's luminance or
// one colour channel): value_k = uz,k (rho_d + sum_i s_i max(0, w_i . u_k)^n_i)
// (lafortune_model.h, with a_i = s_i^(1/n_i) w_i), by Levenberg-Marquardt
// (Ceres' TinySolver) over the lobe shapes alone. The shape of lobe i is
// three unbounded numbers: its unit axis w_i = normalize(qx, qy, 1) (above
// the horizon: Cz >= 0 at the usual view) and its exponent
// n_i = exp(ln(500) sigmoid(t)), inside (kLafortuneMinExponent,
// kLafortuneMaxExponent). For fixed shapes the model is linear in rho_d and
// the lobe scales s_i, which are solved inside every residual evaluation by
// non-negative least squares (Lawson and Hanson 1974): variable projection
// (Golub and Pereyra 1973) with Kaufman's (1975) Jacobian, the derivative of
// the model at the solved scales projected off the span of the free
// columns.
//
// Lobes are added one at a time: each new lobe starts from the best of a
// coarse search (axes towards the pole and the three lights with the largest
// positive residual of the fit so far, exponents 2, 8, 32, 128; every
// candidate's scales solved linearly with the earlier lobes' shapes fixed),
// then all lobes are refined together. A refinement that ends no better
// than its start (or not finite) is discarded for its start: a fallback.
#pragma once

#include "cmfilter/math/vec3.h"
#include "cmfilter/stack/lafortune_model.h"

#include <vector>

namespace cmfilter {

// A lobe's shape in the solver's parameters.
struct LobeShape {
    double qx = 0, qy = 0;  // axis normalize(qx, qy, 1)
    double t = 0;           // exponent exp(ln(500) sigmoid(t))
};

// The shape with the given axis (z > 0 taken; below that, near the horizon)
// and exponent (clamped inside [kLafortuneMinExponent, max_exponent]). With
// a smaller most exponent N (ScalarLobeSettings::max_exponent) the exponent
// is exp(ln(N) sigmoid(t)): the same t maps into the narrower range.
LobeShape lobe_shape(const Vec3& axis, double exponent, double max_exponent = kLafortuneMaxExponent);
Vec3 lobe_shape_axis(const LobeShape& shape);  // unit
double lobe_shape_exponent(const LobeShape& shape, double max_exponent = kLafortuneMaxExponent);

// The lights of a fit, as the solver reads them, with a weight per light
// (missing weights: 1): the fit minimises sum_k w_k (model_k - value_k)^2,
// its rows scaled by root_weight = sqrt(w_k); gain = uz root_weight, the
// factor of the model's columns. With every weight 1 the fit is the
// unweighted one, bit for bit.
struct LobeLights {
    std::vector<double> ux, uy, uz, root_weight, gain;
    explicit LobeLights(const std::vector<Vec3>& lights, const std::vector<double>& weights = {});
    int count() const { return static_cast<int>(uz.size()); }
};

struct ScalarLobeSettings {
    int lobes = 2;            // the lobes fitted (auto: the most)
    bool auto_lobes = false;  // add lobes while each helps (below)
    // Auto: no further lobe once the RMS over the lights is at most this.
    double tolerance = 0;
    // Auto: a lobe is kept only if it cuts the RMS by more than this
    // fraction of the RMS without it.
    double min_gain = 0.1;
    int max_iterations = 20;  // Levenberg-Marquardt iterations per refinement
    // Levenberg-Marquardt stops when a step changes the cost by less than
    // this fraction of it.
    double function_tolerance = 1e-4;
    // The most exponent a lobe may take, in (kLafortuneMinExponent,
    // kLafortuneMaxExponent] (the exponent cap by the light spacing,
    // lafortune_fit.h).
    double max_exponent = kLafortuneMaxExponent;
    // A prior towards broad lobes: the cost minimised is the (weighted) SSE
    // plus, per lobe, P (ln n_i / ln kLafortuneMaxExponent)^2 with P this
    // fraction of the scalar's energy sum_k w_k value_k^2 (a lobe at the
    // largest exponent costs that fraction of the signal); 0: none. Auto
    // lobes and `sse` still judge the data alone.
    double exponent_penalty = 0;
};

struct ScalarLobeFit {
    double rho = 0;
    std::vector<LobeShape> shapes;
    std::vector<double> scales;  // s_i >= 0
    double sse = 0;              // sum of (weighted) squared residuals over the lights
    double penalty = 0;          // the exponent penalty's cost (0 without one)
    int fallbacks = 0;           // refinements discarded for their start
};

// rho_d and the scales (non-negative) for fixed shapes; the (weighted) SSE.
double solve_lobe_scales(const LobeLights& lights, const double* values, const std::vector<LobeShape>& shapes,
                         double* rho, std::vector<double>* scales, double max_exponent = kLafortuneMaxExponent);

// Levenberg-Marquardt from `start` (all lobes refined together), with the
// fallback above (judged by the SSE plus the penalty).
ScalarLobeFit refine_lobes(const LobeLights& lights, const double* values, const std::vector<LobeShape>& start,
                           const ScalarLobeSettings& settings);

// The whole fit: lobes added one at a time as above.
ScalarLobeFit fit_scalar_lobes(const LobeLights& lights, const double* values, const ScalarLobeSettings& settings);

}  // namespace cmfilter
