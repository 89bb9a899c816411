// SPDX-License-Identifier: Apache-2.0
#include "cmfilter/stack/light_density.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cmfilter {

namespace {

double angle_between(const Vec3& a, const Vec3& b)
{
    const double la = length(a), lb = length(b);
    if (!(la > 0 && lb > 0)) return 0;
    return std::acos(std::clamp(dot(a, b) / (la * lb), -1.0, 1.0));
}

}  // namespace

std::vector<double> light_density_weights(const std::vector<Vec3>& lights, double radius)
{
    const std::size_t K = lights.size();
    std::vector<double> weights(K, 1.0);
    if (!(radius > 0) || K < 2) return weights;
    double sum = 0;
    for (std::size_t k = 0; k < K; ++k) {
        int count = 0;
        for (std::size_t j = 0; j < K; ++j)
            if (angle_between(lights[k], lights[j]) <= radius) ++count;
        weights[k] = 1.0 / std::max(count, 1);
        sum += weights[k];
    }
    for (double& w : weights) w *= K / sum;
    return weights;
}

double mean_light_spacing(const std::vector<Vec3>& lights)
{
    const std::size_t K = lights.size();
    if (K < 2) return 0;
    double sum = 0;
    for (std::size_t k = 0; k < K; ++k) {
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j < K; ++j)
            if (j != k) nearest = std::min(nearest, angle_between(lights[k], lights[j]));
        sum += nearest;
    }
    return sum / K;
}

double exponent_for_lobe_width(double spacing)
{
    if (!(spacing > 0)) return std::numeric_limits<double>::infinity();
    const double c = std::cos(std::min(spacing, 3.14159265358979323846) / 2);
    if (!(c > 0)) return 1;
    return std::log(2.0) / -std::log(c);
}

}  // namespace cmfilter
