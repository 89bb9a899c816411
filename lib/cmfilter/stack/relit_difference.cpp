// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/relit_difference.h"

#include "cmfilter/util/parallel_for.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

namespace cmfilter {

std::vector<Vec3> hemisphere_directions(int count)
{
    const double pi = 3.14159265358979323846;
    const double golden_angle = pi * (3.0 - std::sqrt(5.0));
    std::vector<Vec3> lights;
    lights.reserve(static_cast<std::size_t>(std::max(count, 0)) + 1);
    lights.push_back({0, 0, 1});
    for (int i = 0; i < count; ++i) {
        const double z = 1.0 - (i + 0.5) / count;
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        const double phi = golden_angle * i;
        lights.push_back({r * std::cos(phi), r * std::sin(phi), z});
    }
    return lights;
}

namespace {

// |a(l) - b(l)| at one texel and channel, given the basis at l. For the
// models linear in their coefficients, the difference of the coefficients
// weighted by the basis; PtmLrgb the difference of the products.
double relit_difference(const LinearFit& fit, const float* a, const float* b, int channel,
                        const std::array<double, kMaxLinearTerms>& basis)
{
    const int terms = fit.terms();
    if (fit.model == LinearModel::PtmLrgb) {
        double pa = 0, pb = 0;
        for (int k = 0; k < terms; ++k) {
            pa += a[k] * basis[k];
            pb += b[k] * basis[k];
        }
        return std::abs(pa * a[terms + channel] - pb * b[terms + channel]);
    }
    const std::size_t offset = static_cast<std::size_t>(channel) * terms;
    double d = 0;
    for (int k = 0; k < terms; ++k) d += (double(a[offset + k]) - double(b[offset + k])) * basis[k];
    return std::abs(d);
}

}  // namespace

double max_relit_difference(const LinearFit& a, const LinearFit& b, const std::vector<Vec3>& lights, int threads)
{
    assert(a.model == b.model && a.width == b.width && a.height == b.height && a.channels == b.channels);
    std::vector<std::array<double, kMaxLinearTerms>> bases;
    bases.reserve(lights.size());
    for (const Vec3& l : lights) bases.push_back(evaluate_basis(a.model, l));
    std::vector<double> row_max(static_cast<std::size_t>(std::max(a.height, 0)), 0.0);
    parallel_for(a.height, threads, [&](int y) {
        double m = 0;
        for (int x = 0; x < a.width; ++x) {
            const std::size_t t = static_cast<std::size_t>(y) * a.width + x;
            const float* ta = a.texel(t);
            const float* tb = b.texel(t);
            for (const auto& basis : bases)
                for (int c = 0; c < a.channels; ++c) m = std::max(m, relit_difference(a, ta, tb, c, basis));
        }
        row_max[static_cast<std::size_t>(y)] = m;
    });
    double m = 0;
    for (double r : row_max) m = std::max(m, r);
    return m;
}

}  // namespace cmfilter
