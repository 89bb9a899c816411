// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/linear_fit.h"

#include "cmfilter/stack/light_matrix.h"
#include "cmfilter/util/parallel_for.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace cmfilter {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Projections (lu, lv) whose smaller singular value is below this fraction
// of the larger lie on one line through the pole.
constexpr double kCollinearTolerance = 1e-4;
// Lights whose lz differ by less than this lie at one elevation.
constexpr double kElevationTolerance = 1e-4;

// Texel-value columns of the data matrix multiplied per block (a block is
// one task of the parallel loop; blocks do not depend on the thread count,
// so neither do the results).
constexpr std::size_t kBlockColumns = 8192;

using MatrixXdRowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using MatrixXfRowMajor = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

std::string format_number(const char* format, double v)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

// The terms that a constant cos(theta) makes dependent, for the message.
const char* elevation_dependence(LinearModel model)
{
    switch (model) {
    case LinearModel::PtmRgb:
    case LinearModel::PtmLrgb: return "lu^2 + lv^2 is then constant, so the terms a0, a1 and a5 are dependent";
    case LinearModel::Hsh2: return "cos(theta) is then constant, so the terms h0 and h2 are dependent";
    case LinearModel::Hsh3: return "cos(theta) is then constant, so the terms h0, h2 and h6 are dependent";
    }
    return "";
}

Status check_singular_threshold(double threshold)
{
    if (!std::isfinite(threshold) || threshold < 0 || threshold >= 1)
        return bad_input("LinearFitOptions::singular_threshold " + format_number("%g", threshold) +
                             " is invalid: expected a finite fraction in [0, 1) of the largest singular value",
                         "LinearFitOptions::singular_threshold");
    return ok();
}

// The luminance weights of a stack's channels (PtmLrgb: 1 or 3 channels).
std::vector<double> luminance_weights(int channels)
{
    if (channels == 3) return {kRec709Luminance[0], kRec709Luminance[1], kRec709Luminance[2]};
    return {1.0};
}

}  // namespace

Expected<LightSetConditioning> check_light_set(const std::vector<Vec3>& lights, LinearModel model,
                                               double singular_threshold)
{
    if (auto st = check_singular_threshold(singular_threshold); !st) return st.error();
    const int terms = basis_terms(model);
    const int n = static_cast<int>(lights.size());
    const std::string name = to_string(model);
    if (n < terms)
        return bad_input("LinearFitOptions::model " + name + " has " + std::to_string(terms) +
                             " terms per channel, more than the " + std::to_string(n) +
                             " lights can determine (fewer lights than terms)",
                         "LinearFitOptions::model");

    // Collinear: the projections (lu, lv) lie on one line (through the pole
    // or not): the smaller singular value of their centred 2 x N matrix is
    // tiny beside the larger (the square roots of the eigenvalues of the
    // 2 x 2 scatter matrix about their mean).
    double mean_u = 0, mean_v = 0;
    for (const Vec3& l : lights) {
        mean_u += l.x / n;
        mean_v += l.y / n;
    }
    Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
    double lz_min = std::numeric_limits<double>::infinity(), lz_max = -lz_min, lz_sum = 0;
    for (const Vec3& l : lights) {
        const double du = l.x - mean_u, dv = l.y - mean_v;
        scatter(0, 0) += du * du;
        scatter(0, 1) += du * dv;
        scatter(1, 1) += dv * dv;
        lz_min = std::min(lz_min, l.z);
        lz_max = std::max(lz_max, l.z);
        lz_sum += l.z;
    }
    scatter(1, 0) = scatter(0, 1);
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(scatter);
    const double s_large = std::sqrt(std::max(0.0, eig.eigenvalues()(1)));
    const double s_small = std::sqrt(std::max(0.0, eig.eigenvalues()(0)));
    if (s_large > 1e-9 && s_small <= kCollinearTolerance * s_large) {
        const Eigen::Vector2d dir = eig.eigenvectors().col(1);
        double azimuth = std::atan2(dir(1), dir(0)) * 180 / kPi;
        if (azimuth < 0) azimuth += 180;
        // The line's distance from the pole.
        const double offset = std::abs(-dir(1) * mean_u + dir(0) * mean_v);
        return bad_input("the " + std::to_string(n) + " lights cannot determine a " + name +
                         " fit: they are collinear (every projection (lu, lv) lies on one line, at azimuth " +
                         format_number("%.1f", azimuth) + " degrees, " + format_number("%.3g", offset) +
                         " from the pole; smaller / larger singular value " + format_number("%.3g", s_small / s_large) +
                         ")");
    }
    if (lz_max - lz_min <= kElevationTolerance) {
        const double elevation = std::asin(std::clamp(lz_sum / n, -1.0, 1.0)) * 180 / kPi;
        return bad_input("the " + std::to_string(n) + " lights cannot determine a " + name +
                         " fit: they are all at one elevation, " + format_number("%.1f", elevation) + " degrees (" +
                         elevation_dependence(model) + ")");
    }

    const Eigen::MatrixXd a = light_matrix(lights, model);
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(a);
    const Eigen::VectorXd& s = svd.singularValues();
    LightSetConditioning c;
    c.lights = n;
    c.terms = terms;
    c.largest_singular = s(0);
    c.smallest_singular = s(terms - 1);
    int rank = 0;
    for (int j = 0; j < terms; ++j)
        if (s(j) > singular_threshold * s(0) && s(j) > 0) ++rank;
    c.clamped = terms - rank;
    // Largest over smallest kept: a rank deficiency other than the named
    // ones is clamped (the minimum-norm least-squares fit), not refused.
    c.condition_number = rank > 0 ? s(0) / s(rank - 1) : std::numeric_limits<double>::infinity();
    if (rank == 0)
        return bad_input("the " + std::to_string(n) + " lights cannot determine a " + name +
                         " fit: every singular value of the light matrix is zero");
    return c;
}

Expected<LinearFit> fit_linear(const ImageStack& stack, const LinearFitOptions& options)
{
    const std::string where = stack.light_file.empty() ? std::string("image stack: ")
                                                       : "image stack '" + stack.light_file + "': ";
    if (auto st = check_singular_threshold(options.singular_threshold); !st) return st.error();
    if (stack.width <= 0 || stack.height <= 0 || stack.channels <= 0)
        return bad_input(where + "has " + std::to_string(stack.width) + " x " + std::to_string(stack.height) +
                         " texels of " + std::to_string(stack.channels) + " channels, expected at least one of each");
    const std::size_t values = stack.texels() * static_cast<std::size_t>(stack.channels);
    if (stack.pixels.size() != values * stack.lights.size())
        return bad_input(where + "holds " + std::to_string(stack.pixels.size()) + " values, expected " +
                         std::to_string(values * stack.lights.size()) + " for " + std::to_string(stack.count()) +
                         " images");
    if (options.model == LinearModel::PtmLrgb && stack.channels != 1 && stack.channels != 3)
        return bad_input("LinearFitOptions::model ptm-lrgb fits a luminance and a base colour of 1 or 3 channels; " +
                             where.substr(0, where.size() - 2) + " has " + std::to_string(stack.channels),
                         "LinearFitOptions::model");
    auto conditioning = check_light_set(stack.lights, options.model, options.singular_threshold);
    if (!conditioning) return prefixed(where, conditioning.error());

    // The pseudo-inverse P = V S^+ U^T of the light matrix A.
    const LightPseudoInverse inverse = light_pseudo_inverse(stack.lights, options.model, options.singular_threshold);
    const Eigen::MatrixXd& a = inverse.a;
    const Eigen::MatrixXd& p = inverse.p;

    LinearFit fit;
    fit.model = options.model;
    fit.width = stack.width;
    fit.height = stack.height;
    fit.channels = stack.channels;
    fit.encoding = stack.encoding;
    fit.colorspace = stack.colorspace;
    fit.conditioning = *conditioning;
    const int terms = fit.terms();
    const int n = stack.count();
    fit.coefficients.assign(stack.texels() * static_cast<std::size_t>(fit.stride()), 0.0f);

    // The data matrix: light k's image is row k, its texel t channel c
    // column t * channels + c.
    const Eigen::Map<const MatrixXfRowMajor> data(stack.pixels.data(), n, static_cast<Eigen::Index>(values));

    if (options.model != LinearModel::PtmLrgb) {
        // Coefficients = P * data, terms x (texels * channels); stored column
        // major, column t * channels + c holds channel c's terms of texel t,
        // which is LinearFit's texel-major layout.
        Eigen::Map<Eigen::MatrixXf> out(fit.coefficients.data(), terms, static_cast<Eigen::Index>(values));
        const int blocks = static_cast<int>((values + kBlockColumns - 1) / kBlockColumns);
        parallel_for(blocks, options.threads, [&](int b) {
            const Eigen::Index first = static_cast<Eigen::Index>(b) * kBlockColumns;
            const Eigen::Index cols = std::min<Eigen::Index>(kBlockColumns, static_cast<Eigen::Index>(values) - first);
            const Eigen::MatrixXd block = data.middleCols(first, cols).cast<double>();
            out.middleCols(first, cols) = (p * block).cast<float>();
        });
        return fit;
    }

    // PtmLrgb: the luminance Y under every light, its polynomial a = P Y, the
    // fitted luminance F = A a, and the base colour
    // c = sum_k I_k F_k / sum_k F_k^2. When sum_k F_k^2 is negligible beside
    // the luminance's own energy sum_k Y_k^2 (a black or flat texel) the
    // base colour is the mean colour over the mean luminance, or 0 when that
    // is negligible too.
    const int channels = stack.channels;
    const std::vector<double> weights = luminance_weights(channels);
    const int stride = fit.stride();
    const std::size_t texels = stack.texels();
    const std::size_t block_texels = std::max<std::size_t>(1, kBlockColumns / static_cast<std::size_t>(channels));
    const int blocks = static_cast<int>((texels + block_texels - 1) / block_texels);
    parallel_for(blocks, options.threads, [&](int b) {
        const std::size_t first = static_cast<std::size_t>(b) * block_texels;
        const std::size_t count = std::min(block_texels, texels - first);
        const Eigen::Index cols = static_cast<Eigen::Index>(count);
        const Eigen::MatrixXd block =
            data.middleCols(static_cast<Eigen::Index>(first * channels), cols * channels).cast<double>();
        Eigen::MatrixXd luminance(n, cols);
        for (Eigen::Index t = 0; t < cols; ++t) {
            luminance.col(t) = weights[0] * block.col(t * channels);
            for (int c = 1; c < channels; ++c) luminance.col(t) += weights[c] * block.col(t * channels + c);
        }
        const Eigen::MatrixXd poly = p * luminance;
        const Eigen::MatrixXd fitted = a * poly;
        for (Eigen::Index t = 0; t < cols; ++t) {
            float* texel = fit.coefficients.data() + (first + static_cast<std::size_t>(t)) * stride;
            for (int k = 0; k < terms; ++k) texel[k] = static_cast<float>(poly(k, t));
            const double energy = fitted.col(t).squaredNorm();
            const double own = luminance.col(t).squaredNorm();
            const bool usable = energy > 1e-30 && energy > 1e-12 * own;
            const double mean_luminance = luminance.col(t).mean();
            for (int c = 0; c < channels; ++c) {
                double base = 0;
                if (usable) base = block.col(t * channels + c).dot(fitted.col(t)) / energy;
                else if (std::abs(mean_luminance) > 1e-30) base = block.col(t * channels + c).mean() / mean_luminance;
                texel[terms + c] = static_cast<float>(base);
            }
        }
    });
    return fit;
}

std::vector<float> relight(const LinearFit& fit, const Vec3& light, int threads)
{
    const std::size_t texels = fit.texels();
    const int channels = fit.channels;
    const int terms = fit.terms();
    const int stride = fit.stride();
    if (fit.coefficients.size() != texels * static_cast<std::size_t>(stride)) return {};
    std::vector<float> out(texels * static_cast<std::size_t>(channels));
    const auto basis = evaluate_basis(fit.model, light);
    const bool lrgb = fit.model == LinearModel::PtmLrgb;
    parallel_for(fit.height, threads, [&](int y) {
        for (std::size_t t = static_cast<std::size_t>(y) * fit.width; t < static_cast<std::size_t>(y + 1) * fit.width;
             ++t) {
            const float* coef = fit.texel(t);
            float* pixel = out.data() + t * channels;
            if (lrgb) {
                // The luminance polynomial times the base colour.
                double luminance = 0;
                for (int k = 0; k < terms; ++k) luminance += coef[k] * basis[static_cast<std::size_t>(k)];
                for (int c = 0; c < channels; ++c) pixel[c] = static_cast<float>(coef[terms + c] * luminance);
                continue;
            }
            for (int c = 0; c < channels; ++c) {
                double v = 0;
                for (int k = 0; k < terms; ++k) v += coef[c * terms + k] * basis[static_cast<std::size_t>(k)];
                pixel[c] = static_cast<float>(v);
            }
        }
    });
    return out;
}

}  // namespace cmfilter
